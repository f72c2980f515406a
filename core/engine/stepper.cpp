#include "jl/engine/stepper.h"

#include "jl/base/heap_bytes.h"
#include "jl/engine/world.h"
#include "stage_sums.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace jl {

namespace {

Eigen::Vector3d rates(const Powers& p) { return {p.held, p.user, p.damping}; }

}  // namespace

Stepper::Stepper(Integrator kind, double tolerance) : kind_(kind), tolerance_(tolerance) {
    switch (kind) {
        case Integrator::ExplicitEuler:
        case Integrator::SymplecticEuler:
            tableau_ = {{0}, {1}, {}, {{}}};
            break;
        case Integrator::RK4:
            tableau_ = {{0, 0.5, 0.5, 1}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6}, {}, {{}, {0.5}, {0, 0.5}, {0, 0, 1}}};
            break;
        case Integrator::RosenbrockW:
            ros_ = rosenbrockTableau();
            uq_.resize(Rosenbrock::stages);
            uv_.resize(Rosenbrock::stages);
            ul_.resize(Rosenbrock::stages);
            break;
        case Integrator::Verner65:
            // Verner's "most efficient" 6(5) pair (2010), first same as last:
            // the ninth stage is the end of the step, so a step costs eight
            // evaluations. Its stability interval on the imaginary axis is
            // 2.584 (Dormand-Prince's 0.9972), which is what a long ladder's
            // fastest vibration asks of a step (docs/model.md section 6.1).
            // The exact rationals, rounded once to double; e = b - b_embedded.
            tableau_ = {{0, 0.06, 0.09593333333333333, 0.1439, 0.4973, 0.9725, 0.9995, 1, 1},
                        {0.03438957868357036, 0, 0, 0.2582624555633503, 0.4209371189673537, 4.40539646966931,
                         -176.48311902429865, 172.36413340141507, 0},
                        {-0.008623404282200852, 0, 0, 0.019434029953152708, -0.028450072588037983, 2.109711061065291,
                         -103.45854289996399, 101.39980461914911, -0.03333333333333333},
                        {{},
                         {0.06},
                         {0.019239962962962962, 0.07669337037037037},
                         {0.035975, 0, 0.107925},
                         {1.3186834152331484, 0, -5.042058063628562, 4.220674648395414},
                         {-41.872591664327516, 0, 159.4325621631375, -122.11921356501003, 5.531743066200054},
                         {-54.430156935316504, 0, 207.06725136501848, -158.61081378459, 6.991816585950242,
                          -0.018597231062203234},
                         {-54.66374178728198, 0, 207.95280625538936, -159.2889574744995, 7.018743740796944,
                          -0.018338785905045722, -0.0005119484997882099},
                         {0.03438957868357036, 0, 0, 0.2582624555633503, 0.4209371189673537, 4.40539646966931,
                          -176.48311902429865, 172.36413340141507}}};
            break;
        case Integrator::DormandPrince45:
            tableau_ = {{0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1},
                        {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0},
                        {71.0 / 57600, 0, -71.0 / 16695, 71.0 / 1920, -17253.0 / 339200, 22.0 / 525, -1.0 / 40},
                        {{},
                         {1.0 / 5},
                         {3.0 / 40, 9.0 / 40},
                         {44.0 / 45, -56.0 / 15, 32.0 / 9},
                         {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                         {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                         {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}}};
            break;
    }
    const size_t s = tableau_.c.size();
    kv_.resize(s);
    kl_.resize(s);
    nystrom_ = nystromOf(tableau_);
}

// The coefficients of the Nystrom form (Stepper::attempt): sums of products
// of the tableau's, in long double so that they are the exact ones to
// rounding.
Stepper::Nystrom Stepper::nystromOf(const Tableau& t) {
    const size_t s = t.c.size();
    using Wide = long double;
    Nystrom r;
    r.rowSum.assign(s, 0.0);
    r.aa.assign(s, std::vector<double>(s, 0.0));
    for (size_t i = 0; i < s; ++i) {
        Wide sum = 0;
        for (size_t j = 0; j < i; ++j) sum += Wide(t.a[i][j]);
        r.rowSum[i] = double(sum);
        for (size_t k = 0; k < s; ++k) {
            Wide aa = 0;
            for (size_t j = k + 1; j < i; ++j) aa += Wide(t.a[i][j]) * Wide(t.a[j][k]);
            r.aa[i][k] = double(aa);
        }
    }
    // The same for a row of weights w over the stages: (w a)_k and sum w,
    // over the first `count` stages.
    const auto weigh = [&](const std::vector<double>& weights, size_t count, std::vector<double>& wa, double& total) {
        wa.assign(s, 0.0);
        Wide sum = 0;
        for (size_t j = 0; j < count; ++j) sum += Wide(weights[j]);
        total = double(sum);
        for (size_t k = 0; k < s; ++k) {
            Wide x = 0;
            for (size_t j = k + 1; j < count; ++j) x += Wide(weights[j]) * Wide(t.a[j][k]);
            wa[k] = double(x);
        }
    };
    weigh(t.b, s, r.ba, r.bSum);
    if (!t.e.empty()) {
        weigh(t.e, s, r.ea, r.eSum);
        weigh(t.e, s - 1, r.eaHead, r.eHeadSum);
    }
    return r;
}

int Stepper::order() const {
    switch (kind_) {
        case Integrator::ExplicitEuler:
        case Integrator::SymplecticEuler:
            return 1;
        case Integrator::RK4:
            return 4;
        case Integrator::DormandPrince45:
            return 5;
        case Integrator::Verner65:
            return 6;
        case Integrator::RosenbrockW:
            return 3;
    }
    return 1;
}

// One explicit Runge-Kutta step of size h from the state in w (which must be
// saved in q0_, v0_). Leaves the new state in w; returns the error norm
// (adaptive) or 0.
//
// The method is applied to q' = v, v' = a(q, v) in the form of Nystrom: a
// stage's velocities V_i = v0 + h sum_j a_ij A_j, and its positions
// Q_i = q0 + h sum_j a_ij V_j = q0 + h c_i v0 + h^2 sum_k (a a)_ik A_k, the
// same in exact arithmetic (docs/model.md section 6.1). Only the stages'
// accelerations A_j are kept: on a long chain every stage vector read is a
// pass over memory, and reading the velocities' as well took half again as
// many.
double Stepper::attempt(World& w, Dynamics& d, double t, double h, Ledger& ledger, bool firstKnown,
                        double projectionTolerance) {
    if (kind_ == Integrator::RosenbrockW) return rosenbrockAttempt(w, d, t, h, ledger);
    const Tableau& r = tableau_;
    const Nystrom& y = nystrom_;
    const size_t stages = r.c.size();
    const Eigen::Index n = w.q.size();
    // Dormand-Prince's last stage is taken at the fifth-order solution itself
    // (its row of a is b, and b's last weight is 0): projected onto the pins
    // first, it is the end of the step as the caller would project and
    // evaluate it, one evaluation a step fewer. Its error estimate then
    // differs by h/40 times the change of the rates that the projection
    // makes, a projection of a drift below the step's own error.
    const bool projectLast = projectionTolerance > 0 && lastStageIsEnd();
    // The stages' accelerations: the last stage's stay in w.a (nothing
    // after it writes w.a), the others are moved out of it.
    const Eigen::VectorXd* A[StageTerms::most];
    for (size_t i = 0; i < stages; ++i) A[i] = &kv_[i];
    for (size_t i = firstKnown ? 1 : 0; i < stages; ++i) {
        if (i > 0) {
            StageTerms tq;
            tq.add(h * y.rowSum[i], v0_);
            for (size_t k = 0; k + 1 < i; ++k) tq.add(h * h * y.aa[i][k], *A[k]);
            combineStages(w.q, q0_, tq, w.v, v0_, StageTerms(h, r.a[i].data(), A, i), n);
        }
        const bool last = i + 1 == stages;
        if (last && projectLast) {
            endProjection_ = projectPositions(w, d, projectionTolerance);
            if (!endProjection_.converged) return std::numeric_limits<double>::quiet_NaN();
            projectVelocities(w, d, nullptr, ContactRule::Hold);
        }
        const Powers p = d.evaluate(w, t + r.c[i] * h, t + h / 2);
        if (last && projectLast) endPowers_ = p;
        kl_[i] = rates(p);
        // Moved, not copied: the next stage's evaluation writes all of w.a
        // that it reads.
        if (last)
            A[i] = &w.a;
        else if (kv_[i].size() == w.a.size())
            kv_[i].swap(w.a);
        else
            kv_[i] = w.a;
    }
    Eigen::Vector3d dl = Eigen::Vector3d::Zero();
    if (!projectLast) {
        StageTerms tq;
        tq.add(h * y.bSum, v0_);
        for (size_t k = 0; k + 1 < stages; ++k) tq.add(h * h * y.ba[k], *A[k]);
        combineStages(w.q, q0_, tq, w.v, v0_, StageTerms(h, r.b.data(), A, stages), n);
    }
    for (size_t i = 0; i < stages; ++i) {
        const double bi = r.b[i];
        if (bi == 0) continue;
        dl += (h * bi) * kl_[i];
    }
    ledger.held += dl[0];
    ledger.user += dl[1];
    ledger.damping += dl[2];
    if (r.e.empty()) return 0;
    // The positions' error h sum_j e_j V_j in the same form; a projected
    // last stage's velocities are w.v, not the sum.
    StageTerms eq;
    if (projectLast) {
        eq.add(h * y.eHeadSum, v0_);
        eq.add(h * r.e[stages - 1], w.v);
        for (size_t k = 0; k + 1 < stages; ++k) eq.add(h * h * y.eaHead[k], *A[k]);
    } else {
        eq.add(h * y.eSum, v0_);
        for (size_t k = 0; k + 1 < stages; ++k) eq.add(h * h * y.ea[k], *A[k]);
    }
    return errorNorm(w, eq, StageTerms(h, r.e.data(), A, stages));
}

double Stepper::errorNorm(const World& w, const StageTerms& errorQ, const StageTerms& errorV) const {
    ErrorNormInputs in;
    in.tolerance = tolerance_;
    in.n = 3 * std::min<Eigen::Index>(w.bodyCount(), w.q.size() / 3);
    in.parts = w.coordinateParts().data();
    in.q0 = q0_.data();
    in.q1 = w.q.data();
    in.v0 = v0_.data();
    in.v1 = w.v.data();
    return jl::errorNorm(in, errorQ, errorV);
}

void Stepper::symplecticEuler(World& w, Dynamics& d, double t, double h, Ledger& ledger, const Powers* atStart) {
    const Eigen::Vector3d r = rates(atStart ? *atStart : d.evaluate(w, t, t + h / 2));
    w.v.noalias() += h * w.a;
    w.q.noalias() += h * w.v;
    ledger.held += h * r[0];
    ledger.user += h * r[1];
    ledger.damping += h * r[2];
}

StepOutcome Stepper::advance(World& w, Dynamics& d, double t, double h, Ledger& ledger, bool exact,
                             const Powers* atStart, double projectionTolerance) {
    StepOutcome out;
    q0_ = w.q;
    v0_ = w.v;
    const Ledger start = ledger;
    // The first stage of every explicit Runge-Kutta trial is the start state
    // itself: given, or evaluated by the first trial and kept for the rest.
    bool firstKnown = false;
    // Its accelerations are moved out of w.a (the first evaluation of the
    // step writes all of w.a that it reads) unless the step makes no
    // evaluation at all (explicit Euler), which leaves w.a as it found it.
    if (atStart && kind_ != Integrator::RosenbrockW && kind_ != Integrator::SymplecticEuler) {
        if (tableau_.c.size() > 1 && kv_[0].size() == w.a.size())
            kv_[0].swap(w.a);
        else
            kv_[0] = w.a;
        kl_[0] = rates(*atStart);
        firstKnown = true;
    }
    if (kind_ == Integrator::SymplecticEuler) {
        symplecticEuler(w, d, t, h, ledger, atStart);
        out.taken = h;
    } else if (!isAdaptive(kind_) || exact) {
        attempt(w, d, t, h, ledger, firstKnown, projectionTolerance);
        out.taken = h;
    } else {
        double trial = next_ > 0 ? std::min(next_, h) : h;
        for (bool first = true;; first = false) {
            // A rejected trial left its end state in w; the next one starts
            // again from the start of the step.
            if (!first) {
                w.q = q0_;
                w.v = v0_;
                ledger = start;
            }
            const double err = attempt(w, d, t, trial, ledger, firstKnown, projectionTolerance);
            firstKnown = kind_ != Integrator::RosenbrockW;
            if (!std::isfinite(err) && trial > 1e-12) {  // diverged inside the step: much smaller
                ++out.rejected;
                trial *= 0.1;
                continue;
            }
            // The error estimate is the embedded method's, O(h^(p+1)) for its order p.
            const double exponent = -1.0 / order();
            const double grow = err > 0 ? 0.9 * std::pow(err, exponent) : 5.0;
            if (err <= 1.0 || trial < 1e-12) {
                out.taken = trial;
                next_ = trial * std::clamp(grow, 0.2, 5.0);
                break;
            }
            ++out.rejected;
            trial *= std::clamp(grow, 0.1, 0.9);
        }
    }
    w.updateKinematics(t + out.taken);
    if (projectionTolerance > 0 && lastStageIsEnd()) {
        out.endEvaluated = endProjection_.converged;
        out.endPowers = endPowers_;
        out.projection = endProjection_;
    }
    if (!w.q.allFinite() || !w.v.allFinite()) {
        w.q = q0_;
        w.v = v0_;
        ledger = start;
        w.updateKinematics(t);
        out.finite = false;
    }
    return out;
}

std::size_t Stepper::heapBytes() const {
    using jl::heapBytes;
    std::size_t n = heapBytes(kv_) + heapBytes(kl_) + heapBytes(q0_) + heapBytes(v0_) + heapBytes(uq_) +
                    heapBytes(uv_) + heapBytes(ul_) + heapBytes(rq_) + heapBytes(mask_) + heapBytes(keep_) +
                    heapBytes(kept_) + heapBytes(rest_) + heapBytes(mu_) + heapBytes(jmu_) + heapBytes(stiffness_) +
                    heapBytes(stiffInverse_);
    for (const auto* stages : {&kv_, &uq_, &uv_})
        for (const Eigen::VectorXd& x : *stages) n += heapBytes(x);
    return n;
}

}  // namespace jl
