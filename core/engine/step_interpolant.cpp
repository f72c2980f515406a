#include "jl/engine/step_interpolant.h"

namespace jl {

void StepInterpolant::setEnd(const Eigen::VectorXd& q1, const Eigen::VectorXd& v1, const Eigen::VectorXd& a1) {
    q1_ = q1;
    v1_ = v1;
    a1_ = a1;
}

void StepInterpolant::setStart(double h, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                               const Eigen::VectorXd& a0) {
    h_ = h;
    q0_ = q0;
    v0_ = v0;
    a0_ = a0;
}

namespace {

// The quintic Hermite basis on s in [0, 1]: the weights of q0, h v0, h^2 a0,
// h^2 a1, h v1 and q1.
struct Weights {
    double w0, w1, w2, w3, w4, w5;
};

Weights positionWeights(double s) {
    const double s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
    return {1 - 10 * s3 + 15 * s4 - 6 * s5, s - 6 * s3 + 8 * s4 - 3 * s5, 0.5 * (s2 - 3 * s3 + 3 * s4 - s5),
            0.5 * (s3 - 2 * s4 + s5),       -4 * s3 + 7 * s4 - 3 * s5,    10 * s3 - 15 * s4 + 6 * s5};
}

}  // namespace

double StepInterpolant::coordinateAt(double tau, Eigen::Index i) const {
    if (inside_ == Inside::SymplecticEuler) return q0_[i] + tau * (v0_[i] + tau * a0_[i]);
    const double h = h_, hh = h_ * h_;
    const auto [w0, w1, w2, w3, w4, w5] = positionWeights(h_ > 0 ? tau / h_ : 0);
    return w0 * q0_[i] + (w1 * h) * v0_[i] + (w2 * hh) * a0_[i] + (w3 * hh) * a1_[i] + (w4 * h) * v1_[i] + w5 * q1_[i];
}

// The weights of positionWeights and their derivatives in s.
void StepInterpolant::at(double tau, Eigen::VectorXd& q, Eigen::VectorXd& v) const {
    if (inside_ == Inside::SymplecticEuler) {
        v = v0_ + tau * a0_;
        q = q0_ + tau * v;
        return;
    }
    const double s = h_ > 0 ? tau / h_ : 0, s2 = s * s, s3 = s2 * s, s4 = s3 * s;
    const double h = h_, hh = h_ * h_;
    const auto [w0, w1, w2, w3, w4, w5] = positionWeights(s);
    const double d0 = -30 * s2 + 60 * s3 - 30 * s4;
    const double d1 = 1 - 18 * s2 + 32 * s3 - 15 * s4;
    const double d2 = 0.5 * (2 * s - 9 * s2 + 12 * s3 - 5 * s4);
    const double d3 = 0.5 * (3 * s2 - 8 * s3 + 5 * s4);
    const double d4 = -12 * s2 + 28 * s3 - 15 * s4;
    const double d5 = 30 * s2 - 60 * s3 + 30 * s4;
    q = w0 * q0_ + (w1 * h) * v0_ + (w2 * hh) * a0_ + (w3 * hh) * a1_ + (w4 * h) * v1_ + w5 * q1_;
    if (h_ > 0)
        v = (d0 / h) * q0_ + d1 * v0_ + (d2 * h) * a0_ + (d3 * h) * a1_ + d4 * v1_ + (d5 / h) * q1_;
    else
        v = v0_;
}

}  // namespace jl
