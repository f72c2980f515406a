// Applied forces: gravity, air damping, springs, rotary dampers, loads, the mouse.
#include "core/dynamics.h"
#include "core/world.h"

#include <algorithm>

namespace jl {

namespace {

// Adds force f at world point x on part's body; a force on a kinematic body
// does no work on the system but its reaction does: that is the held power.
void applyAt(const World& w, PartId part, const Vec2& x, const Vec2& f, Eigen::VectorXd& force,
             Powers& powers) {
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

void accumulateForces(const World& w, Eigen::VectorXd& force, Powers& powers) {
    force.setZero(w.q.size());
    for (int b = 0; b < w.bodyCount(); ++b) {
        const Body& body = w.body(b);
        if (!body.alive || body.kinematic) continue;
        // The body's origin is its centre of mass: gravity has no torque.
        force.segment<2>(3 * b) += body.mass * w.gravity;
    }
    for (PartId p = 1; p < w.partCount(); ++p) {
        const Part& part = w.part(p);
        if (part.linearDamping <= 0 && part.angularDamping <= 0) continue;
        if (w.body(part.body).kinematic) continue;
        const Twist vel = w.partVelocity(p);
        const Vec2 x = w.partPose(p).position;
        applyAt(w, p, x, -part.linearDamping * vel.linear, force, powers);
        applyTorque(w, p, -part.angularDamping * vel.angular, force, powers);
        powers.damping += part.linearDamping * vel.linear.squaredNorm() +
                          part.angularDamping * vel.angular * vel.angular;
    }
    for (const Spring& s : w.springs()) {
        if (!w.isLive(s.a) || !w.isLive(s.b)) continue;
        const Vec2 xa = w.particlePosition(s.a), xb = w.particlePosition(s.b);
        const Vec2 d = xb - xa;
        const double len = d.norm();
        if (len <= 0) continue;
        const Vec2 u = d / len;
        const double rate = (w.particleVelocity(s.b) - w.particleVelocity(s.a)).dot(u);
        const Vec2 f = (s.stiffness * (len - s.restLength) + s.damping * rate) * u;  // on a
        const Attachment& pa = w.particle(s.a).at.front();
        const Attachment& pb = w.particle(s.b).at.front();
        applyAt(w, pa.part, xa, f, force, powers);
        applyAt(w, pb.part, xb, -f, force, powers);
        powers.damping += s.damping * rate * rate;
    }
    for (const RotaryDamper& d : w.rotaryDampers()) {
        const int ba = w.part(d.a).body, bb = w.part(d.b).body;
        if (ba == bb) continue;  // locked together: internal
        const double rel = w.v[3 * bb + 2] - w.v[3 * ba + 2];
        applyTorque(w, d.b, -d.damping * rel, force, powers);
        applyTorque(w, d.a, d.damping * rel, force, powers);
        powers.damping += d.damping * rel * rel;
    }
    for (const AppliedLoad& l : w.loads()) {
        if (w.body(w.part(l.part).body).kinematic) continue;  // the hand holds it: no effect
        const Vec2 x = w.pointPosition(l.part, l.local);
        applyAt(w, l.part, x, l.force, force, powers);
        applyTorque(w, l.part, l.torque, force, powers);
        powers.user += l.force.dot(w.pointVelocity(l.part, l.local)) + l.torque * w.partVelocity(l.part).angular;
    }
    for (const UserDrag& g : w.drags()) {
        if (w.body(w.part(g.part).body).kinematic) continue;
        const Vec2 x = w.pointPosition(g.part, g.local);
        const Vec2 vx = w.pointVelocity(g.part, g.local);
        Vec2 f = g.stiffness * (g.target - x) - g.damping * vx;
        const double n = f.norm();
        if (n > g.maxForce && n > 0) f *= g.maxForce / n;
        applyAt(w, g.part, x, f, force, powers);
        powers.user += f.dot(vx);
    }
}

}  // namespace jl
