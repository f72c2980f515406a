// The complete elliptic integral of the first kind, for exact pendulum periods.
#pragma once

#include <cmath>
#include <numbers>

namespace jl {

// K(k) = integral_0^{pi/2} dt / sqrt(1 - k^2 sin^2 t), by the arithmetic-
// geometric mean: K = pi / (2 AGM(1, sqrt(1 - k^2))), exact to rounding.
inline double ellipticK(double k) {
    double a = 1.0, g = std::sqrt(1.0 - k * k);
    for (int i = 0; i < 40 && std::abs(a - g) > 1e-16 * a; ++i) {
        const double next = 0.5 * (a + g);
        g = std::sqrt(a * g);
        a = next;
    }
    return std::numbers::pi / (2.0 * a);
}

// Period of a physical pendulum: moment of inertia about the pivot I_p, mass
// m, gravity g, centre-to-pivot distance r, released at rest from angle theta0.
inline double pendulumPeriod(double inertiaAboutPivot, double mass, double g, double r, double theta0) {
    return 4.0 * std::sqrt(inertiaAboutPivot / (mass * g * r)) * ellipticK(std::sin(theta0 / 2.0));
}

}  // namespace jl
