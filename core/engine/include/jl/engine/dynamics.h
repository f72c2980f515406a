// Forward dynamics: forces, then accelerations from M a = f + J^T lambda with
// J a = -Jdot v, and the powers that the energy balance integrates.
#pragma once

#include "jl/base/geometry.h"
#include "jl/engine/contact.h"

#include <Eigen/Core>

#include <cstdint>
#include <memory>
#include <vector>

namespace jl {

class PinSolver;
class World;

// Rates of the energy ledger (W): work by held blocks and by the user's
// drags flow in, viscous damping flows out (dissipation >= 0).
struct Powers {
    double held = 0, user = 0, damping = 0;
};

class Dynamics {
public:
    Dynamics();
    ~Dynamics();

    // Sets kinematic bodies to their path at time t, then computes w.a for
    // the dynamic bodies from w.q and w.v. Allocation-free once warmed up.
    Powers evaluate(World& w, double t) { return evaluate(w, t, t); }
    // The same with the held blocks' paths taken along the piece that holds
    // `within` (a step's stages: World::updateKinematics).
    Powers evaluate(World& w, double t, double within);

    // Pin forces of the last evaluation (2 per pin, force on body A), then
    // one multiplier per weld (World::Weld).
    const Eigen::VectorXd& pinForces() const { return lambda_; }
    // The pushes of the world's resting contacts in the last evaluation (N,
    // one per World::contacts(), on the corner's part along the face's
    // normal), and each contact's row at that state.
    const Eigen::VectorXd& contactForces() const { return contactForces_; }
    // Their Delassus matrix in that evaluation, K_ij = G_i u_j (docs/model.md
    // section 17.2): what a unit push at contact j does to contact i's gap.
    const Eigen::MatrixXd& contactMatrix() const { return contactResponse_.matrix; }
    // Applied (non-constraint) forces of the last evaluation, 3 per body.
    const Eigen::VectorXd& appliedForces() const { return force_; }
    // The pin solver the evaluations and the projections share (private to
    // the engine: core/engine/pin_solver.h).
    PinSolver& solver() { return *solver_; }
    // Forget what the pin solver keeps of the structure it last saw (the
    // world was replaced, e.g. by a snapshot).
    void forgetStructure();
    // Every solve sparse (PinSolver::setForceSparse).
    void setForceSparse(bool on);
    // What the last evaluation left (applied and pin forces), to put back
    // after evaluations that must leave no trace (frames read off a step).
    struct Last {
        Eigen::VectorXd force, lambda, contactForces;
    };
    Last last() const { return {force_, lambda_, contactForces_}; }
    void restoreLast(const Last& l) {
        force_ = l.force;
        lambda_ = l.lambda;
        contactForces_ = l.contactForces;
        weightsRevision_ = 0;
        ++forcesGeneration_;
    }
    long long evaluations() const { return evaluations_; }
    // Changes whenever the forces held here may (an evaluation, restoreLast):
    // what is computed from them holds while it and World::revision stay.
    std::uint64_t forcesGeneration() const { return forcesGeneration_; }

private:
    void addContacts(World& w, Powers& powers);
    std::unique_ptr<PinSolver> solver_;
    Eigen::VectorXd force_, lambda_, contactForces_;
    ContactResponse contactResponse_;
    std::vector<size_t> heldPins_;        // pins with exactly one held side
    std::uint64_t heldPinsRevision_ = 0;  // the World::revision they were listed for
    // force_ holds the weights of the world with this revision and gravity
    // (0: it may hold other forces).
    std::uint64_t weightsRevision_ = 0;
    Vec2 weightsGravity_ = Vec2::Zero();
    long long evaluations_ = 0;
    std::uint64_t forcesGeneration_ = 0;
};

// Applied forces on every body (3 per body: fx, fy, torque about the body's
// origin) and the held, user and damping powers of those forces.
void accumulateForces(const World& w, Eigen::VectorXd& force, Powers& powers);

// The applied forces (jl/engine/applied_forces.h) on one part alone (gravity, air damping, springs,
// loads, the mouse; not the rotary dampers, which act between parts), as a
// force and a moment about the point `about`: one side of a locked pair is
// held by its contact against these (Ladder's contact forces).
struct AppliedWrench {
    Vec2 force = Vec2::Zero();
    double moment = 0;
};
AppliedWrench appliedOnPart(const World& w, int part, const Vec2& about);  // part: a PartId

}  // namespace jl
