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
#include "pin_solver.h"
#include "stage_sums.h"

#include <Eigen/LU>

#include <algorithm>

namespace jl {

Stepper::Rosenbrock Stepper::rosenbrockTableau() {
    // The method as published: y1 = y0 + sum b_i k_i,
    // (I - h gamma W) k_i = h F(y0 + sum alpha_ij k_j) + h W sum gamma_ij k_j.
    constexpr double g = 4.3586652150845900e-01;
    Eigen::Matrix4d gamma, alpha;
    gamma << g, 0, 0, 0,                                        //
        -8.7173304301691801e-01, g, 0, 0,                       //
        -9.0338057013044082e-01, 5.4180672388095326e-02, g, 0,  //
        2.4212380706095346e-01, -1.2232505839045147e+00, 5.4526025533510214e-01, g;
    alpha << 0, 0, 0, 0,                                        //
        8.7173304301691801e-01, 0, 0, 0,                        //
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
    const size_t bodies = size_t(w.bodyCount());
    const Eigen::Index n = w.q.size();
    // Which coordinates move (the inverse masses' pattern) changes only with
    // the world's revision; the rest is written whole, once a step.
    if (maskRevision_ != w.revision() || mask_.size() != n) {
        mask_ = (w.invMassDiag.array() != 0).cast<double>();
        maskRevision_ = w.revision();
    }
    stiffInverse_.resize(bodies);
    keep_.resize(n);
    stiffness_.assign(bodies, 0.0);
    const PinSolver& solver = d.solver();
    const Eigen::VectorXd& lambda = d.pinForces();
    for (int i = 0; i < solver.pinCount(); ++i) {
        const Vec2 l = lambda.segment<2>(2 * Eigen::Index(i));
        stiffness_[size_t(solver.bodyA(i))] -= solver.armA(i).dot(l);
        stiffness_[size_t(solver.bodyB(i))] += solver.armB(i).dot(l);
    }
    // From the world's flat inverse masses (zero for held and dead bodies,
    // which then keep zeros): a Body is a long stride to read two numbers from.
    for (size_t b = 0; b < bodies; ++b) {
        const Eigen::Index i = 3 * Eigen::Index(b);
        const double invMass = w.invMassDiag[i], invInertia = w.invMassDiag[i + 2];
        const double raise = 1 + s * invInertia * std::max(0.0, -stiffness_[b]);
        stiffInverse_[b] = {invMass, invInertia / raise};
        keep_.segment<3>(i) = mask_.segment<3>(i).cwiseProduct(Eigen::Vector3d(1, 1, 1 / raise));
    }
    for (Eigen::Index i = 3 * Eigen::Index(bodies); i < n; ++i) keep_[i] = 0;
    stiff_->assemble(w, stiffInverse_);
}

// A stage's increments. With R_q = v + sum_j c_ij u_q,j / h and R_v = a +
// sum_j c_ij u_v,j / h (held and dead bodies' rows zero: they follow their
// path), u_q / (h gamma) - u_v = R_q and u_v / (h gamma) - A u_q = R_v, so
// u_v = (I - h^2 gamma^2 A)^{-1} z - R_q with z = h gamma R_v + R_q, and
// u_q = h gamma (R_q + u_v). (I - h^2 gamma^2 A)^{-1} z solves
// (M + h^2 gamma^2 |K|) x = M z + J^T mu with J x = J z: with y = M'^{-1} M z
// (the kept part of z), mu solves (J M'^{-1} J^T) mu = J (z - y), and
// x = y + M'^{-1} J^T mu. What is known before the solve is formed in one
// pass over the coordinates, and what follows it in one more: on a long
// chain each pass streams every vector it touches from memory.
void Stepper::rosenbrockStage(World& w, int i, double h) {
    const Rosenbrock& r = ros_;
    const double hg = h * r.gamma;
    const Eigen::Index n = w.v.size();
    double c[Rosenbrock::stages];
    const double* uq[Rosenbrock::stages];
    const double* uv[Rosenbrock::stages];
    for (int j = 0; j < i; ++j) {
        c[j] = r.c[i][j] / h;
        uq[j] = uq_[size_t(j)].data();
        uv[j] = uv_[size_t(j)].data();
    }
    rq_.resize(n);
    kept_.resize(n);
    rest_.resize(n);
    const double *v = w.v.data(), *a = w.a.data(), *mask = mask_.data(), *keep = keep_.data();
    for (Eigen::Index e = 0; e < n; ++e) {
        double q = v[e] * mask[e], p = a[e] * mask[e];
        for (int j = 0; j < i; ++j) q = q + c[j] * uq[j][e];
        for (int j = 0; j < i; ++j) p = p + c[j] * uv[j][e];
        const double z = (hg * p + q) * mask[e];
        rq_[e] = q;
        kept_[e] = keep[e] * z;
        rest_[e] = z - kept_[e];
    }
    stiff_->solveApplying(w, rest_, mu_, jmu_);
    Eigen::VectorXd& uqi = uq_[size_t(i)];
    Eigen::VectorXd& uvi = uv_[size_t(i)];
    uqi.resize(n);
    uvi.resize(n);
    // In the same pass, what follows from the increments: the next stage's
    // state y0 + sum_j a_(i+1)j u_j, or after the last stage the step's end
    // y0 + sum_j m_j u_j, summed as the explicit methods' stage sums are (the
    // terms with a zero coefficient left out, in the order of j), while u_i is at hand.
    const double* next = i + 1 < Rosenbrock::stages ? r.a[i + 1] : r.m;
    int terms = 0;
    double cn[Rosenbrock::stages];
    const double* nq[Rosenbrock::stages];
    const double* nv[Rosenbrock::stages];
    for (int j = 0; j < i; ++j) {
        if (next[j] == 0) continue;
        cn[terms] = next[j];
        nq[terms] = uq[j];
        nv[terms++] = uv[j];
    }
    const double ci = next[i];
    w.q.resize(n);
    w.v.resize(n);
    double *q1 = w.q.data(), *v1 = w.v.data();
    const double *q0 = q0_.data(), *v0 = v0_.data();
    const auto finish = [&](Eigen::Index e, double x) {
        const double dv = (kept_[e] + x) - rq_[e];
        const double dq = hg * (rq_[e] + dv);
        uvi[e] = dv;
        uqi[e] = dq;
        double sq = q0[e], sv = v0[e];
        for (int j = 0; j < terms; ++j) {
            sq = sq + cn[j] * nq[j][e];
            sv = sv + cn[j] * nv[j][e];
        }
        if (ci != 0) {
            sq = sq + ci * dq;
            sv = sv + ci * dv;
        }
        q1[e] = sq;
        v1[e] = sv;
    };
    const Eigen::Index bodies = std::min<Eigen::Index>(w.bodyCount(), n / 3);
    for (Eigen::Index b = 0; b < bodies; ++b) {
        const Eigen::Vector2d& im = stiffInverse_[size_t(b)];
        finish(3 * b, jmu_[3 * b] * im[0]);
        finish(3 * b + 1, jmu_[3 * b + 1] * im[0]);
        finish(3 * b + 2, jmu_[3 * b + 2] * im[1]);
    }
    for (Eigen::Index e = 3 * bodies; e < n; ++e) finish(e, jmu_[e]);
}

double Stepper::rosenbrockAttempt(World& w, Dynamics& d, double t, double h, Ledger& ledger) {
    const Rosenbrock& r = ros_;
    const double hg = h * r.gamma;
    // Each stage leaves the next one's state in w (the last the step's end).
    for (int i = 0; i < Rosenbrock::stages; ++i) {
        const Powers p = d.evaluate(w, t + r.alpha[i] * h, t + h / 2);
        if (i == 0) stiffMass(w, d, hg * hg);
        rosenbrockStage(w, i, h);
        Eigen::Vector3d rl(p.held, p.user, p.damping);
        for (int j = 0; j < i; ++j) rl += (r.c[i][j] / h) * ul_[size_t(j)];
        ul_[size_t(i)] = hg * rl;  // the books have no stiff part: W is 0 there
    }
    for (int i = 0; i < Rosenbrock::stages; ++i) {
        ledger.held += r.m[i] * ul_[size_t(i)][0];
        ledger.user += r.m[i] * ul_[size_t(i)][1];
        ledger.damping += r.m[i] * ul_[size_t(i)][2];
    }
    const Eigen::VectorXd* uq[Rosenbrock::stages];
    const Eigen::VectorXd* uv[Rosenbrock::stages];
    for (int i = 0; i < Rosenbrock::stages; ++i) {
        uq[i] = &uq_[size_t(i)];
        uv[i] = &uv_[size_t(i)];
    }
    return errorNorm(w, StageTerms(1.0, r.e, uq, Rosenbrock::stages), StageTerms(1.0, r.e, uv, Rosenbrock::stages));
}

}  // namespace jl
