// Removes drift: mass-weighted projection of positions (Newton-Raphson with
// line backtracking, the paper's solver) and of velocities onto the pins.
// With the pin solver of a Dynamics, or with the world's scratch one (after
// a change of structure, for a world with no dynamics of its own).
#pragma once

#include "jl/engine/world.h"

#include <Eigen/Core>

#include <optional>
#include <vector>

namespace jl {

class Dynamics;

struct ProjectionResult {
    bool converged = true;
    int iterations = 0;
    double residual = 0;  // m, largest pin gap after the projection
};

// Largest distance between the two sides of any pin, or by which a weld's
// second shared point is off (m).
double pinResidual(const World& w);
// Largest relative velocity across any pin (m/s).
double pinVelocityResidual(const World& w);

// Moves dynamic bodies the least (in the mass metric) so every pin closes.
// The world's resting contacts are closed too, unless `contacts` is false:
// a change of structure closes its pins to rounding, and leaves the
// contacts (closed by every step's projection) as they are.
ProjectionResult projectPositions(World& w, Dynamics& d, double tolerance, int maxIterations = 25,
                                  bool contacts = true);

// The plastic impulse: v+ = v- + W J^T P with J v+ = 0. Held bodies have
// infinite mass. If `impulses` is given it receives P (2 per pin, on body A, then one
// per weld).
// The world's resting contacts (World::contacts) are held too: at an
// impact `PushOnly`, each pushing only as much as keeps its gap from
// closing (a contact that would have to pull is left to part); after a
// step `Hold`, each kept at zero rate like a pin, since a resting contact
// opens only where its force crosses zero (docs/model.md section 17.3).
enum class ContactRule { PushOnly, Hold };
void projectVelocities(World& w, Dynamics& d, Eigen::VectorXd* impulses = nullptr,
                       ContactRule contacts = ContactRule::PushOnly);
// The same (pushing only) with the world's scratch solver.
void projectVelocities(World& w);

// A bounce after a plastic impact, the world at its plastic velocities
// (restructured as the bounce leaves it): Newton's law from the part
// velocities `before` the impact, v +
// (1 + e)(v_plastic - v), then projected onto the constraints that stay
// closed (a hinge too slow to rebound, one the impact locked): that is a
// second, plastic jump. Returns what the whole impact dissipates, (1 - e^2)
// of the plastic jump's energy and all of the second's (docs/model.md
// section 12.3).
double bounce(World& w, Dynamics& d, const std::vector<Twist>& before, double e);

// Both, after a change of structure (combine, separate, hold: the world's
// operations only restructure, and the caller projects), with the world's
// scratch solver reset first, so nothing but its capacity carries over.
ProjectionResult makeConsistent(World& w, double tolerance, bool contacts = true);
// The same to World::restructureTolerance, the resting contacts left as
// they are: the pins closed to rounding (docs/model.md section 3.4). A gap
// left beyond 1e-9 m (ten times the default tolerance of a step's
// projection) is a projection that failed, said in words naming
// `operation`; the structure has changed by then, and a caller that gets
// this error stops (the simulation keeps its last good frame).
std::optional<WorldError> makeConsistentAfter(World& w, const char* operation);
// After a change of structure by a caller that sets the velocities itself
// (an impact projects them with its own impulses): the pins closed by
// moving positions alone; the error as for makeConsistentAfter.
std::optional<WorldError> closePinGaps(World& w, const char* operation);

}  // namespace jl
