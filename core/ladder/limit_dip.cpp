// A limit passed and left again within one step (docs/model.md section
// 9.1): the event functions are compared at the step's ends, so a hinge
// that swings just past its limit and back inside a long adaptive step
// would raise no event. The angle's quintic Hermite through both ends
// (angle, rate and acceleration, as the step's interpolant has them) finds
// the dip; the step is then taken again to end inside it.
#include "jl/ladder/ladder.h"
#include "jl/ladder/quintic_dip.h"

#include <algorithm>
#include <array>
#include <utility>

namespace jl {

double Ladder::limitDip(World& w, StepStart& start, double h) const {
    const int live = liveEnd();
    // Rate and acceleration at the start: the world holds the end, so the
    // start is put in for the reading and taken out again (swaps, no copies).
    std::vector<std::array<double, 2>> begin(size_t(std::max(0, live - 1)));
    std::swap(w.q, start.q), std::swap(w.v, start.v), std::swap(w.a, start.a);
    for (int j = 1; j < live; ++j)
        if (hinge(j).mode == HingeMode::Free) begin[size_t(j - 1)] = {foldRate(w, j), foldAcceleration(w, j)};
    std::swap(w.q, start.q), std::swap(w.v, start.v), std::swap(w.a, start.a);
    double first = 0;
    for (int j = 1; j < live; ++j) {
        if (hinge(j).mode != HingeMode::Free) continue;
        const auto [rate0, accel0] = begin[size_t(j - 1)];
        const double rate1 = foldRate(w, j);
        // A lowest point of phi - z (or of pi - phi - z) inside the step
        // needs the angle to turn back from that limit within it.
        const bool towardOpen = rate0 < 0 && rate1 > 0, towardFolded = rate0 > 0 && rate1 < 0;
        if (!towardOpen && !towardFolded) continue;
        // The start's angle is the tracked one (updateAngles ran at its end).
        const double phi0 = hinge(j).foldAngle, phi1 = foldAngle(w, j), accel1 = foldAcceleration(w, j);
        const auto [open0, folded0] = limitFunctions(j, phi0);
        const auto [open1, folded1] = limitFunctions(j, phi1);
        if (!(open0 > 0 && open1 > 0 && folded0 > 0 && folded1 > 0)) continue;  // a crossing at an end: located
        const double sign = towardOpen ? 1 : -1;
        const auto [s, value] = quinticLowest(towardOpen ? open0 : folded0, sign * rate0 * h, sign * accel0 * h * h,
                                              towardOpen ? open1 : folded1, sign * rate1 * h, sign * accel1 * h * h);
        if (value < 0 && (first == 0 || s * h < first)) first = s * h;
    }
    return first;
}

}  // namespace jl
