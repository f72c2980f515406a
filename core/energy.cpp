#include "core/energy.h"

#include "core/world.h"

namespace jl {

// Summed over parts, so a block locked to a held block keeps its energy in
// the books (the hand's work on it is counted in the held power).
Energy energy(const World& w) {
    Energy e;
    for (PartId p = 1; p < w.partCount(); ++p) {
        const Part& part = w.part(p);
        if (part.drive || part.body == 0) continue;
        const Twist vel = w.partVelocity(p);
        e.kinetic += 0.5 * part.mass * vel.linear.squaredNorm() + 0.5 * part.inertia * vel.angular * vel.angular;
        e.potential -= part.mass * w.gravity.dot(w.partPose(p).position);
    }
    for (const Spring& s : w.springs()) {
        if (!w.isLive(s.a) || !w.isLive(s.b)) continue;
        const double stretch = (w.particlePosition(s.b) - w.particlePosition(s.a)).norm() - s.restLength;
        e.potential += 0.5 * s.stiffness * stretch * stretch;
    }
    return e;
}

}  // namespace jl
