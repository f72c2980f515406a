// The linearly implicit integrator: the Rosenbrock-W method ROS34PW2 of
// Rang and Angermann (2005), 4 stages, order 3 with an embedded order 2,
// L-stable, stiffly accurate, and of order 3 for any approximation W of the
// Jacobian (a W-method). Why this method and which W: docs/model.md
// section 6.4.
//
// W is the Jacobian of a hanging ladder's fastest motion: the rocking of
// each block against the tension in its pins. With the pin forces lambda
// frozen, the moment r x lambda of a pin on a body turning by dtheta changes
// by -(r . lambda) dtheta: a stiffness k on the body's angle alone, so that
// (I - h^2 gamma^2 A) x = z is the pins' own equation with each block's
// inertia raised by h^2 gamma^2 |k|. The O(N) chain solver solves it as it
// solves the dynamics: one factorisation per step, one solve per stage.
#include "jl/engine/stepper.h"

#include "jl/engine/world.h"

#include <Eigen/LU>

#include <algorithm>

namespace jl {

Stepper::Rosenbrock Stepper::rosenbrockTableau() {
    // The method as published: y1 = y0 + sum b_i k_i,
    // (I - h gamma W) k_i = h F(y0 + sum alpha_ij k_j) + h W sum gamma_ij k_j.
    constexpr double g = 4.3586652150845900e-01;
    Eigen::Matrix4d gamma, alpha;
    gamma << g, 0, 0, 0,                                                  //
        -8.7173304301691801e-01, g, 0, 0,                                 //
        -9.0338057013044082e-01, 5.4180672388095326e-02, g, 0,            //
        2.4212380706095346e-01, -1.2232505839045147e+00, 5.4526025533510214e-01, g;
    alpha << 0, 0, 0, 0,                                        //
        8.7173304301691801e-01, 0, 0, 0,                         //
        8.4457060015369423e-01, -1.1299064236484185e-01, 0, 0,  //
        0, 0, 1, 0;
    const Eigen::RowVector4d b(2.4212380706095346e-01, -1.2232505839045147e+00, 1.5452602553351020e+00, g);
    const Eigen::RowVector4d bHat(3.7810903145819369e-01, -9.6042292212423178e-02, 0.5, 2.1793326075422950e-01);
    // Transformed to u_i = sum_j gamma_ij k_j, which needs no product with W
    // (Hairer and Wanner, Solving ODEs II, section IV.7).
    const Eigen::Matrix4d inverse = gamma.inverse();
    const Eigen::Matrix4d a = alpha * inverse;
    const Eigen::RowVector4d m = b * inverse, mHat = bHat * inverse;
    Rosenbrock r;
    r.gamma = g;
    for (int i = 0; i < 4; ++i) {
        r.alpha[i] = alpha.row(i).sum();
        r.m[i] = m[i];
        r.e[i] = m[i] - mHat[i];
        for (int j = 0; j < i; ++j) {
            r.a[i][j] = a(i, j);
            r.c[i][j] = -inverse(i, j);
        }
    }
    return r;
}

// The step's matrix from the pin forces of the evaluation at its start:
// every dynamic body's angle gets the restoring part of its pins' stiffness
// (a compressed pin's negative stiffness is left out: it would lower the
// inertia, possibly to zero, and a W-method keeps its order without it).
void Stepper::stiffMass(const World& w, Dynamics& d, double s) {
    const int bodies = w.bodyCount();
    stiffInverse_.assign(size_t(bodies), Eigen::Vector2d::Zero());
    mask_ = (w.invMassDiag.array() != 0).cast<double>();
    keep_.setZero(w.q.size());
    stiffness_.assign(size_t(bodies), 0.0);
    const std::vector<Pin>& pins = w.pins();
    const Eigen::VectorXd& lambda = d.pinForces();
    for (size_t i = 0; i < pins.size(); ++i) {
        const Vec2 l = lambda.segment<2>(2 * Eigen::Index(i));
        stiffness_[size_t(pins[i].bodyA)] -= d.solver().armA(int(i)).dot(l);
        stiffness_[size_t(pins[i].bodyB)] += d.solver().armB(int(i)).dot(l);
    }
    // From the world's flat inverse masses (zero for held and dead bodies,
    // which then keep zeros): a Body is a long stride to read two numbers from.
    for (int b = 0; b < bodies; ++b) {
        const double invMass = w.invMassDiag[3 * b], invInertia = w.invMassDiag[3 * b + 2];
        const double raise = 1 + s * invInertia * std::max(0.0, -stiffness_[size_t(b)]);
        stiffInverse_[size_t(b)] = {invMass, invInertia / raise};
        keep_.segment<3>(3 * b) = mask_.segment<3>(3 * b).cwiseProduct(Eigen::Vector3d(1, 1, 1 / raise));
    }
    stiff_.solver.assemble(w, stiffInverse_);
}

// z := (I - h^2 gamma^2 A)^{-1} z: (M + h^2 gamma^2 |K|) x = M z + J^T mu
// with J x = J z. With y = M'^{-1} M z (the kept part of z), mu solves
// (J M'^{-1} J^T) mu = J (z - y), and x = y + M'^{-1} J^T mu.
void Stepper::solveStiff(const World& w, Eigen::VectorXd& z) {
    z.array() *= mask_.array();  // held and dead bodies do not move by it
    kept_ = keep_.cwiseProduct(z);
    rest_ = z - kept_;
    stiff_.solver.multiplyJ(rest_, rhs_);
    stiff_.solver.solve(rhs_, mu_);
    jmu_.setZero(z.size());
    stiff_.solver.addJTranspose(mu_, jmu_);
    for (int b = 0; b < w.bodyCount(); ++b) {
        const Eigen::Vector2d& im = stiffInverse_[size_t(b)];
        jmu_.segment<2>(3 * b) *= im[0];
        jmu_[3 * b + 2] *= im[1];
    }
    z = kept_ + jmu_;
}

double Stepper::rosenbrockAttempt(World& w, Dynamics& d, double t, double h, Ledger& ledger) {
    const Rosenbrock& r = ros_;
    const double hg = h * r.gamma;
    Eigen::Vector3d rl;
    for (int i = 0; i < Rosenbrock::stages; ++i) {
        if (i > 0) {
            w.q = q0_;
            w.v = v0_;
            for (int j = 0; j < i; ++j) {
                if (r.a[i][j] == 0) continue;
                w.q.noalias() += r.a[i][j] * uq_[size_t(j)];
                w.v.noalias() += r.a[i][j] * uv_[size_t(j)];
            }
        }
        const Powers p = d.evaluate(w, t + r.alpha[i] * h, t + h / 2);
        if (i == 0) stiffMass(w, d, hg * hg);
        rq_ = w.v.cwiseProduct(mask_);  // held bodies follow their path instead
        rv_ = w.a.cwiseProduct(mask_);
        rl = {p.held, p.user, p.damping};
        for (int j = 0; j < i; ++j) {
            const double cij = r.c[i][j] / h;
            rq_.noalias() += cij * uq_[size_t(j)];
            rv_.noalias() += cij * uv_[size_t(j)];
            rl += cij * ul_[size_t(j)];
        }
        // (q, v): u_q / (h gamma) - u_v = R_q, u_v / (h gamma) - A u_q = R_v,
        // so u_v = (I - h^2 gamma^2 A)^{-1} (h gamma R_v + R_q) - R_q.
        z_ = hg * rv_ + rq_;
        solveStiff(w, z_);
        uv_[size_t(i)] = z_ - rq_;
        uq_[size_t(i)] = hg * (rq_ + uv_[size_t(i)]);
        ul_[size_t(i)] = hg * rl;  // the books have no stiff part: W is 0 there
    }
    w.q = q0_;
    w.v = v0_;
    errQ_.setZero(w.q.size());
    errV_.setZero(w.v.size());
    for (int i = 0; i < Rosenbrock::stages; ++i) {
        w.q.noalias() += r.m[i] * uq_[size_t(i)];
        w.v.noalias() += r.m[i] * uv_[size_t(i)];
        ledger.held += r.m[i] * ul_[size_t(i)][0];
        ledger.user += r.m[i] * ul_[size_t(i)][1];
        ledger.damping += r.m[i] * ul_[size_t(i)][2];
        errQ_.noalias() += r.e[i] * uq_[size_t(i)];
        errV_.noalias() += r.e[i] * uv_[size_t(i)];
    }
    return errorNorm(w);
}

}  // namespace jl
