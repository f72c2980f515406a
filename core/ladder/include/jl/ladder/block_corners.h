// Where a ladder's hinges attach: the four numbered corners of each block in
// the block's own frame, from the design alone (no world is built). The
// engine pins hinges to these corners and the views number them; both ask here.
#pragma once

#include "jl/base/geometry.h"
#include "jl/scene/scene.h"

#include <array>
#include <vector>

namespace jl {

// Corner k (0..3) of block i of a ladder of blocks `length` long: bit 0 walks
// the length, bit 1 the thickness. Even blocks point "up", odd ones "down",
// so a hinge joins equal corner numbers.
Vec2 blockCorner(int i, int k, double thickness, double length);

// Every block's four corners, in its own frame (per-block thicknesses included).
std::vector<std::array<Vec2, 4>> blockCorners(const LadderSpec& spec);

}  // namespace jl
