// A limit passed and left again within one step (docs/model.md section
// 9.1): the event functions are compared at the step's ends, so a hinge
// that swings just past its limit and back inside a long adaptive step
// would raise no event. The angle's quintic Hermite through both ends
// (angle, rate and acceleration, as the step's interpolant has them) finds
// the dip; the step is then taken again to end inside it.
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <array>
#include <utility>

namespace jl {

namespace {

// The lowest of 32 samples inside (0, 1) of the quintic Hermite with value
// f, slope m and curvature c (per unit s) at both ends: {s, value}.
std::pair<double, double> lowestInside(double f0, double m0, double c0, double f1, double m1, double c1) {
    std::pair<double, double> lowest{0, f0};
    for (int i = 1; i < 32; ++i) {
        const double s = i / 32.0, s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
        const double h0 = 1 - 10 * s3 + 15 * s4 - 6 * s5, h1 = s - 6 * s3 + 8 * s4 - 3 * s5,
                     h2 = (s2 - 3 * s3 + 3 * s4 - s5) / 2, h5 = 10 * s3 - 15 * s4 + 6 * s5,
                     h4 = -4 * s3 + 7 * s4 - 3 * s5, h3 = (s3 - 2 * s4 + s5) / 2;
        const double p = h0 * f0 + h1 * m0 + h2 * c0 + h3 * c1 + h4 * m1 + h5 * f1;
        if (p < lowest.second) lowest = {s, p};
    }
    return lowest;
}

}  // namespace

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
        const auto [s, value] = lowestInside(towardOpen ? open0 : folded0, sign * rate0 * h, sign * accel0 * h * h,
                                             towardOpen ? open1 : folded1, sign * rate1 * h, sign * accel1 * h * h);
        if (value < 0 && (first == 0 || s * h < first)) first = s * h;
    }
    return first;
}

}  // namespace jl
