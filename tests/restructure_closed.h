// Test support: the world's combine, separate and hold, each followed by
// the projection a caller makes after a change of structure (the world's
// operations only restructure): the pins closed to rounding and the
// velocities made consistent, with the error in words if a gap is left.
#pragma once

#include "jl/engine/projection.h"
#include "jl/engine/world.h"

#include <optional>

namespace jl::test {

inline std::optional<WorldError> combineClosed(World& w, ParticleId p, ParticleId q) {
    if (auto e = w.combine(p, q)) return e;
    return makeConsistentAfter(w, "combine");
}

inline std::optional<WorldError> separateClosed(World& w, ParticleId p) {
    if (auto e = w.separate(p)) return e;
    return makeConsistentAfter(w, "separate");
}

// The hand takes the part where it is.
inline void holdClosed(World& w, PartId part) {
    w.hold(part, Drive(w.partPose(part)));
    makeConsistentAfter(w, "hold");
}

}  // namespace jl::test
