// An independent check of the engine: the falling chain in reduced
// coordinates (one absolute angle per link), integrated with a tight
// adaptive Dormand-Prince 5(4) of its own. Dense O(N^3) per evaluation:
// meant for N <= a few hundred, where accuracy matters and speed does not.
#pragma once

#include "jl/base/geometry.h"

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <vector>

namespace jl {

struct ReferenceChainSpec {
    int links = 10;
    double length = 0.06, thickness = 0.012, width = 0.045, density = 600, gravity = 9.81;
    double mass() const { return density * length * thickness * width; }
    double inertia() const { return mass() * (length * length + thickness * thickness) / 12; }
};

class ReferenceChain {
public:
    // Links pinned end to end through their end midpoints, link 0's free end
    // at the origin; angles measured from +x (all zero: the straight start).
    explicit ReferenceChain(const ReferenceChainSpec& spec, const Eigen::VectorXd& angles = {},
                            const Eigen::VectorXd& rates = {});

    // Integrates to time t (> time()) with local error tolerance `tolerance`.
    // Returns the number of accepted steps.
    long long advanceTo(double t, double tolerance);

    double time() const { return t_; }
    const Eigen::VectorXd& angles() const { return theta_; }
    const Eigen::VectorXd& rates() const { return omega_; }
    Vec2 centre(int link) const;  // m
    double energy() const;        // J, kinetic + gravity (zero at y = 0)

private:
    void accelerations(const Eigen::VectorXd& theta, const Eigen::VectorXd& omega, Eigen::VectorXd& alpha) const;
    double weight(int i, int j) const;  // sum over links k of a_ki a_kj (see .cpp)

    ReferenceChainSpec spec_;
    Eigen::VectorXd theta_, omega_;
    double t_ = 0, h_ = 1e-5;
    mutable Eigen::MatrixXd mass_;  // work space: 80 KB at N = 100, not reallocated per evaluation
    mutable Eigen::VectorXd rhs_;
    mutable Eigen::LLT<Eigen::MatrixXd> llt_;
};

}  // namespace jl
