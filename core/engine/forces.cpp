// Applied forces: gravity, air damping, springs, rotary dampers, loads, the mouse.
#include "jl/engine/dynamics.h"
#include "jl/engine/world.h"

#include <algorithm>

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

// The force law of a spring-damper, on its end a (minus it on b); false if
// its ends coincide (no direction). An end absorbed by combine still has its
// own attachment at the shared point: the spring keeps acting there.
bool springForce(const World& w, const Spring& s, Vec2& xa, Vec2& xb, Vec2& f, double& rate) {
    if (!w.validParticle(s.a) || !w.validParticle(s.b)) return false;
    xa = w.particlePosition(s.a);
    xb = w.particlePosition(s.b);
    const Vec2 d = xb - xa;
    const double len = d.norm();
    if (len <= 0) return false;
    const Vec2 u = d / len;
    rate = (w.particleVelocity(s.b) - w.particleVelocity(s.a)).dot(u);
    f = (s.stiffness * (len - s.restLength) + s.damping * rate) * u;
    return true;
}

// The mouse spring of docs/model.md section 11.3 at its point x, capped.
Vec2 dragForce(const World& w, const UserDrag& g, Vec2& x, Vec2& vx) {
    x = w.pointPosition(g.part, g.local);
    vx = w.pointVelocity(g.part, g.local);
    Vec2 f = g.stiffness * (g.target - x) - g.damping * vx;
    const double n = f.norm();
    if (n > g.maxForce && n > 0) f *= g.maxForce / n;
    return f;
}

}  // namespace

AppliedWrench appliedOnPart(const World& w, PartId p, const Vec2& about) {
    const Part& part = w.part(p);
    const Vec2 c = w.partPose(p).position;
    AppliedWrench s;
    auto add = [&](const Vec2& x, const Vec2& f) {
        s.force += f;
        s.moment += cross(x - about, f);
    };
    add(c, part.mass * w.gravity);
    const Twist vel = w.partVelocity(p);
    add(c, -part.linearDamping * vel.linear);
    s.moment -= part.angularDamping * vel.angular;
    for (const Spring& sp : w.springs()) {
        Vec2 xa, xb, f;
        double rate = 0;
        const bool onA = w.validParticle(sp.a) && w.particle(sp.a).at.front().part == p;
        const bool onB = w.validParticle(sp.b) && w.particle(sp.b).at.front().part == p;
        if ((!onA && !onB) || !springForce(w, sp, xa, xb, f, rate)) continue;
        if (onA) add(xa, f);
        if (onB) add(xb, -f);
    }
    for (const AppliedLoad& l : w.loads()) {
        if (l.part != p) continue;
        add(w.pointPosition(l.part, l.local), l.force);
        s.moment += l.torque;
    }
    for (const UserDrag& g : w.drags()) {
        if (g.part != p) continue;
        Vec2 x, vx;
        const Vec2 f = dragForce(w, g, x, vx);
        add(x, f);
    }
    return s;
}

void accumulateForces(const World& w, Eigen::VectorXd& force, Powers& powers) {
    force = w.weights();
    for (PartId p : w.dampedParts()) {
        const Part& part = w.part(p);
        if (p == World::ground || w.body(part.body).kinematic) continue;
        const Twist vel = w.partVelocity(p);
        const Vec2 x = w.partPose(p).position;
        applyAt(w, p, x, -part.linearDamping * vel.linear, force, powers);
        applyTorque(w, p, -part.angularDamping * vel.angular, force, powers);
        powers.damping +=
            part.linearDamping * vel.linear.squaredNorm() + part.angularDamping * vel.angular * vel.angular;
    }
    for (const Spring& s : w.springs()) {
        Vec2 xa, xb, f;  // f on a
        double rate = 0;
        if (!springForce(w, s, xa, xb, f, rate)) continue;
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
        Vec2 x, vx;
        const Vec2 f = dragForce(w, g, x, vx);
        applyAt(w, g.part, x, f, force, powers);
        powers.user += f.dot(vx);
    }
}

}  // namespace jl
