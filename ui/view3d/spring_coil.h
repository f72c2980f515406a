// A spring as drawn: a zigzag between its two ends, the same in the 3-D view
// and the side view, so that a stretched spring reads as one at a glance.
#pragma once

#include "jl/base/geometry.h"

#include <vector>

namespace jl::ui {

// The points of the zigzag from a to b (m): a straight lead at each end,
// then eight teeth across the line, the coil a fifth as wide as it is long
// within 4 to 12 mm (a particle is drawn 8 mm across).
std::vector<jl::Vec2> springCoil(const jl::Vec2& a, const jl::Vec2& b);

}  // namespace jl::ui
