// The lowest point inside a step of a quantity known at the step's two
// ends by value, rate and acceleration: what shows a limit passed and left
// again within one step (docs/model.md section 9.1), for the ladder's
// hinges (Ladder::limitDip) and a general scene's stops (PinStops::limitDip).
#pragma once

#include <utility>

namespace jl {

// The lowest of 32 samples inside (0, 1) of the quintic Hermite with value
// f, slope m and curvature c (per unit s) at both ends: {s, value}.
inline std::pair<double, double> quinticLowest(double f0, double m0, double c0, double f1, double m1, double c1) {
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

}  // namespace jl
