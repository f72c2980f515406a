#include "jl/engine/energy.h"

#include "jl/engine/applied_forces.h"
#include "jl/engine/world.h"

namespace jl {

// A dynamic body's energy is its own: its mass at its centre of mass (the
// body's origin) and its inertia about it, one term for a body of a
// thousand blocks (a long ladder's still tail, docs/model.md section 3.7),
// where a sum over its parts would cost a thousand at every step. Parts of
// kinematic bodies are summed one by one, so a block locked to a held block
// keeps its energy in the books (the hand's work on it is counted in the
// held power); the held block itself is outside them.
Energy energy(const World& w) {
    Energy e;
    for (int b = 1; b < w.bodyCount(); ++b) {
        const Body& body = w.body(b);
        if (!body.alive) continue;
        if (!body.kinematic) {
            const Twist vel = w.bodyVelocity(b);
            e.kinetic += 0.5 * body.mass * vel.linear.squaredNorm() + 0.5 * body.inertia * vel.angular * vel.angular;
            e.potential -= body.mass * w.gravity.dot(w.bodyPose(b).position);
            continue;
        }
        for (PartId p : body.parts) {
            const Part& part = w.part(p);
            if (part.drive) continue;
            const Twist vel = w.partVelocity(p);
            e.kinetic += 0.5 * part.mass * vel.linear.squaredNorm() + 0.5 * part.inertia * vel.angular * vel.angular;
            e.potential -= part.mass * w.gravity.dot(w.partPose(p).position);
        }
    }
    forEachAppliedPotential(w, [&](double u) { e.potential += u; });
    return e;
}

// Kinetic energy relative to the held body when exactly one body is held,
// else the plain kinetic energy: the measure the ladder's impacts book by, in
// whose frame a plastic impact never creates energy (docs/model.md section 12.3).
// The held body moves rigidly, so its motion applied to every part satisfies
// every pin: a plastic projection can only lower this.
double heldFrameKinetic(const World& w) {
    int held = -1, count = 0;
    for (int b = 1; b < w.bodyCount(); ++b)
        if (w.body(b).alive && w.body(b).kinematic) {
            held = b;
            ++count;
        }
    if (count != 1) return energy(w).kinetic;
    const Vec2 origin = w.q.segment<2>(3 * held), vel = w.v.segment<2>(3 * held);
    const double omega = w.v[3 * held + 2];
    double ke = 0;
    for (PartId p = 1; p < w.partCount(); ++p) {
        const Part& part = w.part(p);
        if (part.drive || part.body == 0) continue;
        const Twist v = w.partVelocity(p);
        const Vec2 rel = v.linear - vel - omega * perp(w.partPose(p).position - origin);
        ke += 0.5 * part.mass * rel.squaredNorm() + 0.5 * part.inertia * (v.angular - omega) * (v.angular - omega);
    }
    return ke;
}

// The energy of a velocity jump in the mass metric, 1/2 sum m |dv|^2 +
// I dw^2 over the parts the hand does not hold itself. A plastic impact is the
// projection of the velocities onto the constraints in that metric, with the
// held bodies' motion prescribed; what it dissipates is exactly this, with
// any number of held bodies and pins to the world (the kinetic energy
// relative to one held body gives the same number when there is one).
double jumpEnergy(const World& w, const std::vector<Twist>& before) {
    double e = 0;
    for (PartId p = 1; p < w.partCount() && size_t(p) < before.size(); ++p) {
        const Part& part = w.part(p);
        if (part.drive || part.body == 0) continue;  // a part locked to a held one counts: it was stopped
        const Twist v = w.partVelocity(p);
        const Twist& b = before[size_t(p)];
        e += 0.5 * part.mass * (v.linear - b.linear).squaredNorm() +
             0.5 * part.inertia * (v.angular - b.angular) * (v.angular - b.angular);
    }
    return e;
}

std::vector<Twist> bounced(const std::vector<Twist>& before, const std::vector<Twist>& plastic, double e) {
    std::vector<Twist> out(before.size());
    for (size_t p = 0; p < before.size(); ++p)
        out[p] = {before[p].linear + (1 + e) * (plastic[p].linear - before[p].linear),
                  before[p].angular + (1 + e) * (plastic[p].angular - before[p].angular)};
    return out;
}

}  // namespace jl
