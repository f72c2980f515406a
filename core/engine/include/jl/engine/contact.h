// A resting contact: a corner of one part pressed against a face of
// another, frictionless, one scalar equation (the gap along the face's
// normal stays zero) whose multiplier may only push (docs/model.md section
// 17). The pins are solved first (chain or sparse); each contact is then
// added by its Schur complement on top of the pins' factorisation: the
// pins' response to a unit push at the contact, one solve of the pins per
// contact, so a scene with no contact computes nothing more.
#pragma once

#include "jl/base/geometry.h"

#include <Eigen/Core>

#include <vector>

namespace jl {

class PinSolver;
class World;

// Corner `corner` of part `cornerPart` (in that part's frame) against the
// face of part `facePart` whose outward unit normal is `normal` (face
// part's frame), at `offset` from the part's centre along it; the face
// reaches `halfLength` either side of its middle along the face.
struct Contact {
    int cornerPart = -1;
    Vec2 corner = Vec2::Zero();
    int facePart = -1;
    Vec2 normal = Vec2::Zero();
    double offset = 0;
    double halfLength = 0;
};

// A contact's row at the world's positions: the gap's rate is
// n . (vA + wA perp(rA) - vB - wB perp(rB)) with rA, rB the arms from each
// body's origin to the corner.
struct ContactRow {
    int bodyA = 0, bodyB = 0;
    Vec2 normal = Vec2::Zero();
    Vec2 armA = Vec2::Zero(), armB = Vec2::Zero();
};

ContactRow contactRow(const World& w, const Contact& c);
// Signed gap (m): > 0 apart, < 0 the corner is inside the face's half-plane.
double contactGap(const World& w, const Contact& c);
// Where the corner lies along the face, from the face's middle (m).
double contactSlide(const World& w, const Contact& c);
// G u for body vector u (3 per body): the gap's rate at velocities u.
double rowTimes(const ContactRow& r, const Eigen::VectorXd& u);
// f += s G^T: a push s along the normal, on A at the corner and opposite on B.
void addRowTranspose(const ContactRow& r, double s, Eigen::VectorXd& f);
// The part of the gap's second derivative that is not G a (velocity terms).
double rowBias(const World& w, const ContactRow& r);

// The pins' response to a unit push at each contact: for contact i the
// change of every body's acceleration (or velocity, for an impulse) u_i =
// W (G_i^T + J^T x_i), with x_i the pins' forces that keep J u_i = 0, and
// the contacts' matrix K_ij = G_i u_j (the Delassus matrix of the contacts
// with every pin active).
struct ContactResponse {
    std::vector<ContactRow> rows;
    std::vector<Eigen::VectorXd> response, pinForces;
    Eigen::MatrixXd matrix;
    // `stale`: the solver's factorisation is not for w's positions yet
    // (PinSolver::prepare said so); it is after this.
    void build(const World& w, PinSolver& solver, bool stale);
    // The same for other contacts than the world's, at its positions.
    void build(const World& w, const std::vector<Contact>& contacts, PinSolver& solver, bool stale);
    // Solves K_S s_S = rhs_S on the subset S of contacts (mask), zero elsewhere.
    Eigen::VectorXd solve(const Eigen::VectorXd& rhs, const std::vector<char>& in) const;
    // A unilateral solve: the pushes s >= 0 with K s >= rhs, s (K s - rhs) = 0
    // (the rows that would pull are dropped one at a time, the most
    // negative first; the rest are kept).
    Eigen::VectorXd solvePushing(const Eigen::VectorXd& rhs) const;
};

// The contacts' matrix K of the world's resting contacts and `trial` after
// them, at the world's positions: what a push at a contact not yet made
// would move with every pin and the others active. Built in the world's
// scratch (valid until the next use of it), the world left as it was.
const Eigen::MatrixXd& contactMatrixWith(const World& w, const Contact& trial);

}  // namespace jl
