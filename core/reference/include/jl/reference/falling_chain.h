// The falling chain: N boxes pinned end to end, hung from the world at one
// end, let fall from a straight line. The engine's comparison case.
#pragma once

#include "jl/engine/world.h"

namespace jl {

struct FallingChain {
    double length = 0.06, thickness = 0.012, width = 0.045, density = 600;
    double mass() const { return density * length * thickness * width; }
};

// Block i lies along +x from x = i L to (i+1) L, at rest; block 0's free end
// is pinned to the world at the origin. Returns the parts in chain order.
std::vector<PartId> buildFallingChain(World& w, int n, const FallingChain& spec = {});

}  // namespace jl
