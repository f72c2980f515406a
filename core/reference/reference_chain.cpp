#include "jl/reference/reference_chain.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace jl {

ReferenceChain::ReferenceChain(const ReferenceChainSpec& spec, const Eigen::VectorXd& angles,
                               const Eigen::VectorXd& rates)
    : spec_(spec),
      theta_(angles.size() ? angles : Eigen::VectorXd::Zero(spec.links)),
      omega_(rates.size() ? rates : Eigen::VectorXd::Zero(spec.links)) {}

// The centre of link k is sum_{i<k} L u_i + (L/2) u_k, u_i = (cos, sin) of
// angle i: d c_k / d theta_i = a_ki L u_i' with a_ki = 1 (i < k), 1/2
// (i = k), 0 (i > k). The mass matrix and the velocity terms both carry
// W_ij = sum_k a_ki a_kj = (N-1-max(i,j)) + (1/4 if i == j else 1/2).
double ReferenceChain::weight(int i, int j) const {
    return double(spec_.links - 1 - std::max(i, j)) + (i == j ? 0.25 : 0.5);
}

// Lagrange's equations in absolute angles:
// sum_j [I d_ij + m L^2 W_ij cos(t_i - t_j)] a_j
//   = -m g L cos(t_i) (N - i - 1/2) - sum_j m L^2 W_ij sin(t_i - t_j) w_j^2.
void ReferenceChain::accelerations(const Eigen::VectorXd& theta, const Eigen::VectorXd& omega,
                                   Eigen::VectorXd& alpha) const {
    const int n = spec_.links;
    const double m = spec_.mass(), l = spec_.length, mll = m * l * l;
    Eigen::MatrixXd& mass = mass_;
    Eigen::VectorXd& rhs = rhs_;
    mass.resize(n, n);
    rhs.resize(n);
    for (int i = 0; i < n; ++i) {
        rhs[i] = -m * spec_.gravity * l * std::cos(theta[i]) * (double(n - i) - 0.5);
        for (int j = 0; j < n; ++j) {
            const double d = theta[i] - theta[j];
            mass(i, j) = mll * weight(i, j) * std::cos(d) + (i == j ? spec_.inertia() : 0.0);
            rhs[i] -= mll * weight(i, j) * std::sin(d) * omega[j] * omega[j];
        }
    }
    llt_.compute(mass);
    alpha = llt_.solve(rhs);
}

// Dormand-Prince 5(4) with its own coefficients (not the engine's Stepper;
// the equations are autonomous, so the nodes c_i are not needed),
// error per component scaled by tolerance * (1 + |y|).
long long ReferenceChain::advanceTo(double tEnd, double tolerance) {
    static constexpr double a[7][6] = {{0},
                                       {1.0 / 5},
                                       {3.0 / 40, 9.0 / 40},
                                       {44.0 / 45, -56.0 / 15, 32.0 / 9},
                                       {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                                       {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                                       {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}};
    static constexpr std::array<double, 7> b{35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0};
    static constexpr std::array<double, 7> e{71.0 / 57600,      0,          -71.0 / 16695, 71.0 / 1920,
                                             -17253.0 / 339200, 22.0 / 525, -1.0 / 40};
    const int n = spec_.links;
    std::array<Eigen::VectorXd, 7> kt, kw;
    Eigen::VectorXd th(n), om(n), al(n);
    long long accepted = 0;
    while (t_ < tEnd) {
        const double h = std::min(h_, tEnd - t_);
        for (int s = 0; s < 7; ++s) {
            th = theta_;
            om = omega_;
            for (int j = 0; j < s; ++j) {
                th += h * a[s][j] * kt[size_t(j)];
                om += h * a[s][j] * kw[size_t(j)];
            }
            accelerations(th, om, al);
            kt[size_t(s)] = om;
            kw[size_t(s)] = al;
        }
        Eigen::VectorXd nt = theta_, nw = omega_, et = Eigen::VectorXd::Zero(n), ew = Eigen::VectorXd::Zero(n);
        for (int s = 0; s < 7; ++s) {
            nt += h * b[size_t(s)] * kt[size_t(s)];
            nw += h * b[size_t(s)] * kw[size_t(s)];
            et += h * e[size_t(s)] * kt[size_t(s)];
            ew += h * e[size_t(s)] * kw[size_t(s)];
        }
        double sum = 0;
        for (int i = 0; i < n; ++i) {
            const double st = tolerance * (1 + std::max(std::abs(theta_[i]), std::abs(nt[i])));
            const double sw = tolerance * (1 + std::max(std::abs(omega_[i]), std::abs(nw[i])));
            sum += (et[i] / st) * (et[i] / st) + (ew[i] / sw) * (ew[i] / sw);
        }
        const double err = std::sqrt(sum / (2.0 * n));
        const double grow = err > 0 ? 0.9 * std::pow(err, -0.2) : 5.0;
        if (err <= 1) {
            theta_ = nt;
            omega_ = nw;
            t_ += h;
            ++accepted;
            if (h == h_ || grow < 1) h_ = h * std::clamp(grow, 0.2, 5.0);
        } else {
            h_ = h * std::clamp(grow, 0.1, 0.9);
        }
    }
    return accepted;
}

Vec2 ReferenceChain::centre(int link) const {
    Vec2 c = Vec2::Zero();
    for (int i = 0; i < link; ++i) c += spec_.length * Vec2(std::cos(theta_[i]), std::sin(theta_[i]));
    return c + 0.5 * spec_.length * Vec2(std::cos(theta_[link]), std::sin(theta_[link]));
}

double ReferenceChain::energy() const {
    const int n = spec_.links;
    const double m = spec_.mass(), l = spec_.length;
    double kinetic = 0, potential = 0;
    Vec2 joint = Vec2::Zero(), jointVelocity = Vec2::Zero();
    for (int k = 0; k < n; ++k) {
        const Vec2 u(std::cos(theta_[k]), std::sin(theta_[k])), du(-u.y(), u.x());
        const Vec2 vc = jointVelocity + 0.5 * l * omega_[k] * du;
        kinetic += 0.5 * m * vc.squaredNorm() + 0.5 * spec_.inertia() * omega_[k] * omega_[k];
        potential += m * spec_.gravity * (joint + 0.5 * l * u).y();
        joint += l * u;
        jointVelocity += l * omega_[k] * du;
    }
    return kinetic + potential;
}

}  // namespace jl
