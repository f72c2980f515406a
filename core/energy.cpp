#include "core/energy.h"

#include "core/world.h"

namespace jl {

Energy energy(const World& w) {
    Energy e;
    for (int b = 0; b < w.bodyCount(); ++b) {
        const Body& body = w.body(b);
        if (!body.alive || body.kinematic) continue;
        e.kinetic += 0.5 * body.mass * w.v.segment<2>(3 * b).squaredNorm() +
                     0.5 * body.inertia * w.v[3 * b + 2] * w.v[3 * b + 2];
        e.potential -= body.mass * w.gravity.dot(w.q.segment<2>(3 * b));
    }
    for (const Spring& s : w.springs()) {
        if (!w.isLive(s.a) || !w.isLive(s.b)) continue;
        const double stretch = (w.particlePosition(s.b) - w.particlePosition(s.a)).norm() - s.restLength;
        e.potential += 0.5 * s.stiffness * stretch * stretch;
    }
    return e;
}

}  // namespace jl
