// Applied forces (jl/engine/applied_forces.h) summed: on every body for the
// dynamics, with their powers, and on one part for a contact force.
#include "jl/engine/applied_forces.h"
#include "jl/engine/dynamics.h"
#include "jl/engine/world.h"

namespace jl {

namespace {

// Adds force f at world point x on part's body; a force on a kinematic body
// does no work on the system but its reaction does: that is the held power.
void applyAt(const World& w, PartId part, const Vec2& x, const Vec2& f, Eigen::VectorXd& force, Powers& powers) {
    const int b = w.part(part).body;
    const Vec2 r = x - w.q.segment<2>(3 * b);
    if (w.body(b).kinematic) {
        const Vec2 vx = w.v.segment<2>(3 * b) + w.v[3 * b + 2] * perp(r);
        powers.held -= f.dot(vx);
        return;
    }
    force.segment<2>(3 * b) += f;
    force[3 * b + 2] += cross(r, f);
}

void applyTorque(const World& w, PartId part, double torque, Eigen::VectorXd& force, Powers& powers) {
    const int b = w.part(part).body;
    if (w.body(b).kinematic) {
        powers.held -= torque * w.v[3 * b + 2];
        return;
    }
    force[3 * b + 2] += torque;
}

}  // namespace

// Rotary dampers act between parts: a side of a locked pair takes them on
// its own (Ladder::addDampersOnSide).
AppliedWrench appliedOnPart(const World& w, PartId p, const Vec2& about) {
    AppliedWrench s;
    forEachAppliedForce(w, AppliedForce::kAll & ~AppliedForce::RotaryDamper, p, [&](const AppliedForce& a) {
        if (a.couple) {
            s.moment += a.torque;
            return;
        }
        s.force += a.force;
        s.moment += cross(a.at - about, a.force);
    });
    return s;
}

void accumulateForces(const World& w, Eigen::VectorXd& force, Powers& powers) {
    force = w.weights();
    forEachAppliedForce(w, AppliedForce::kAll, -1, [&](const AppliedForce& a) {
        if (!a.betweenParts() && w.body(w.part(a.part).body).kinematic) return;  // the hand takes it
        if (a.couple)
            applyTorque(w, a.part, a.torque, force, powers);
        else
            applyAt(w, a.part, a.at, a.force, force, powers);
        powers.damping += a.dissipated;
        powers.user += a.userPower;
    });
}

}  // namespace jl
