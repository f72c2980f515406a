#include "jl/reference/falling_chain.h"

#include "jl/engine/projection.h"

#include <numbers>

namespace jl {

std::vector<PartId> buildFallingChain(World& w, int n, const FallingChain& spec) {
    std::vector<PartId> parts;
    parts.reserve(size_t(n));
    const double half = spec.length / 2;
    // A box's length runs along its local y; -90 degrees lays it along +x.
    for (int i = 0; i < n; ++i)
        parts.push_back(w.addBox(spec.mass(), Vec2(spec.thickness, spec.length), spec.width,
                                 Pose{Vec2((i + 0.5) * spec.length, 0), -std::numbers::pi / 2}));
    ParticleId previous = w.anchor(Vec2::Zero());
    for (int i = 0; i < n; ++i) {
        w.combine(previous, w.addParticle(parts[size_t(i)], Vec2(0, -half)));
        previous = w.addParticle(parts[size_t(i)], Vec2(0, half));
    }
    w.shrinkToFit();
    makeConsistent(w, w.restructureTolerance);
    return parts;
}

}  // namespace jl
