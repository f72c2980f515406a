#include "jl/engine/stable_step.h"

#include "scratch.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jl {

double fastestVibration(const World& w, const Eigen::VectorXd& pinForces) {
    const std::vector<Pin>& pins = w.pins();
    if (pinForces.size() < 2 * Eigen::Index(pins.size())) return 0;
    // Sum of |F| |r| per body, then the largest ratio to the inertia.
    std::vector<double>& sums = w.scratch().pull;
    sums.assign(size_t(w.bodyCount()), 0.0);
    double* pull = sums.data();  // not re-read through the world at every pin
    for (size_t i = 0; i < pins.size(); ++i) {
        const Pin& p = pins[i];
        const double f = pinForces.segment<2>(2 * Eigen::Index(i)).norm();
        if (p.bodyA >= 0) pull[size_t(p.bodyA)] += f * p.localA.norm();
        if (p.bodyB >= 0) pull[size_t(p.bodyB)] += f * p.localB.norm();
    }
    double omega2 = 0;
    for (int b = 0; b < w.bodyCount(); ++b) {
        const Body& body = w.body(b);
        if (!body.alive || body.kinematic || !(body.inertia > 0)) continue;
        omega2 = std::max(omega2, pull[size_t(b)] / body.inertia);
    }
    return std::sqrt(omega2);
}

double fastestSpringVibration(const World& w) {
    const std::vector<Spring>& springs = w.springs();
    if (springs.empty()) return 0;
    // Each body's row of M^-1/2 K M^-1/2, bounded by the sizes of its
    // blocks (Gershgorin): sum over its springs of k |u_b| (|u_b| + |u_o|),
    // |u|^2 = 1/m + |r|^2 / I the inverse mass a point at arm r moves with,
    // k the larger of the spring's stiffness and its tension over its
    // length (the stiffness across it), plus the tension's pull T |r| / I.
    std::vector<double>& row = w.scratch().pull;  // the pins' sums are done with
    row.assign(size_t(w.bodyCount()), 0.0);
    for (const Spring& s : springs) {
        const Vec2 xa = w.particlePosition(s.a), xb = w.particlePosition(s.b);
        const double length = (xb - xa).norm();
        const double tension = std::abs(s.stiffness * (length - s.restLength));
        const double k = std::max(s.stiffness, length > 0 ? tension / length : 0.0);
        const int body[2] = {w.part(w.particle(s.a).own.part).body, w.part(w.particle(s.b).own.part).body};
        const Vec2 x[2] = {xa, xb};
        double u[2] = {0, 0}, arm[2] = {0, 0};
        for (int e = 0; e < 2; ++e) {
            const Body& b = w.body(body[e]);
            if (!b.alive || b.kinematic) continue;
            arm[e] = (x[e] - w.q.segment<2>(3 * body[e])).norm();
            u[e] = std::sqrt(b.invMass + arm[e] * arm[e] * b.invInertia);
        }
        for (int e = 0; e < 2; ++e)
            row[size_t(body[e])] += k * u[e] * (u[e] + u[1 - e]) + tension * arm[e] * w.body(body[e]).invInertia;
    }
    return std::sqrt(*std::max_element(row.begin(), row.end()));
}

double fastestTurn(const World& w) {
    double omega = 0;
    for (int b = 0; b < w.bodyCount(); ++b)
        if (w.body(b).alive) omega = std::max(omega, std::abs(w.v[3 * b + 2]));
    return omega;
}

double imaginaryStabilityLimit(Integrator integrator) {
    switch (integrator) {
        case Integrator::RK4:
            return 2 * std::sqrt(2.0);
        case Integrator::DormandPrince45:
            return 0.9972;
        case Integrator::Verner65:
            return 2.5842;
        // L-stable on the stiffness its W holds: no limit from the vibration
        // (what is left of the step's choice is accuracy, its error control's).
        case Integrator::RosenbrockW:
            return std::numeric_limits<double>::infinity();
        case Integrator::ExplicitEuler:
        case Integrator::SymplecticEuler:
            return 2.0;
    }
    return 2.0;
}

double automaticStep(Integrator integrator, double omega, double cap) {
    constexpr double kSafety = 0.6;
    if (!(omega > 0)) return cap;
    return std::min(cap, kSafety * imaginaryStabilityLimit(integrator) / omega);
}

}  // namespace jl
