// How far behind the clock a run played in the window may fall and still
// catch up. A stall of the simulation thread (the processor taken by the
// renderer, the window or another program) leaves the run behind; what
// it falls behind by up to kCatchUp it makes good by playing on without
// waiting between frames, what is beyond is given up for good: an engine
// slower than the clock plays on from where it is instead of racing.
#pragma once

#include <algorithm>

namespace jl::ui {

constexpr double kCatchUp = 0.1;  // s of simulated time

// Of a lag behind the clock (s of simulated time), what is given up.
constexpr double lagGivenUp(double lag) { return std::max(0.0, lag - kCatchUp); }

}  // namespace jl::ui
