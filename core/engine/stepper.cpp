#include "jl/engine/stepper.h"

#include "jl/engine/world.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

namespace jl {

namespace {

Eigen::Vector3d rates(const Powers& p) { return {p.held, p.user, p.damping}; }

// The sum of M terms, M known to the compiler so that it can unroll the
// terms and vectorize the elements.
template <size_t M>
void sumTerms(double* out, const Eigen::VectorXd* base, const double* c, const double* const* terms, Eigen::Index n) {
    if (base) {
        const double* b = base->data();
        for (Eigen::Index e = 0; e < n; ++e) {
            double sum = b[e];
            for (size_t i = 0; i < M; ++i) sum = sum + c[i] * terms[i][e];
            out[e] = sum;
        }
    } else {
        for (Eigen::Index e = 0; e < n; ++e) {
            double sum = 0.0;
            for (size_t i = 0; i < M; ++i) sum = sum + c[i] * terms[i][e];
            out[e] = sum;
        }
    }
}

// out = base + c_0 k_0 + c_1 k_1 + ... for the stages whose coefficient is
// not zero, added in that order: bit for bit what one axpy after another
// gives, in one pass over memory instead of one pass (reading and writing
// `out`) per stage. A step of Dormand-Prince makes 28 such sums for q and
// as many for v; on a long chain its vectors outgrow the cache, and those
// passes were a sixth of the method's cost per block-step at 100,000 blocks.
// `base` null: the sum starts from zero.
void combineStages(Eigen::VectorXd& out, const Eigen::VectorXd* base, double scale, const double* coefficients,
                   const std::vector<Eigen::VectorXd>& k, size_t count) {
    constexpr size_t kMostStages = 9;  // Verner's 6(5) pair, the longest tableau
    assert(count <= kMostStages);
    double c[kMostStages];
    const double* terms[kMostStages];
    size_t m = 0;
    for (size_t j = 0; j < count; ++j) {
        if (coefficients[j] == 0) continue;
        c[m] = scale * coefficients[j];
        terms[m++] = k[j].data();
    }
    const Eigen::Index n = k[0].size();
    out.resize(n);
    switch (m) {
    case 0: sumTerms<0>(out.data(), base, c, terms, n); break;
    case 1: sumTerms<1>(out.data(), base, c, terms, n); break;
    case 2: sumTerms<2>(out.data(), base, c, terms, n); break;
    case 3: sumTerms<3>(out.data(), base, c, terms, n); break;
    case 4: sumTerms<4>(out.data(), base, c, terms, n); break;
    case 5: sumTerms<5>(out.data(), base, c, terms, n); break;
    case 6: sumTerms<6>(out.data(), base, c, terms, n); break;
    case 7: sumTerms<7>(out.data(), base, c, terms, n); break;
    case 8: sumTerms<8>(out.data(), base, c, terms, n); break;
    default: sumTerms<9>(out.data(), base, c, terms, n); break;
    }
}

}  // namespace

Stepper::Stepper(Integrator kind, double tolerance) : kind_(kind), tolerance_(tolerance) {
    switch (kind) {
    case Integrator::ExplicitEuler:
    case Integrator::SymplecticEuler:
        tableau_ = {{0}, {1}, {}, {{}}};
        break;
    case Integrator::RK4:
        tableau_ = {{0, 0.5, 0.5, 1},
                    {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6},
                    {},
                    {{}, {0.5}, {0, 0.5}, {0, 0, 1}}};
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
    kq_.resize(s);
    kv_.resize(s);
    kl_.resize(s);
}

int Stepper::order() const {
    switch (kind_) {
    case Integrator::ExplicitEuler:
    case Integrator::SymplecticEuler: return 1;
    case Integrator::RK4: return 4;
    case Integrator::DormandPrince45: return 5;
    case Integrator::Verner65: return 6;
    case Integrator::RosenbrockW: return 3;
    }
    return 1;
}

// One explicit Runge-Kutta step of size h from the state in w (which must be
// saved in q0_, v0_). Leaves the new state in w; returns the error norm
// (adaptive) or 0.
double Stepper::attempt(World& w, Dynamics& d, double t, double h, Ledger& ledger, bool firstKnown,
                        double projectionTolerance) {
    if (kind_ == Integrator::RosenbrockW) return rosenbrockAttempt(w, d, t, h, ledger);
    const size_t stages = tableau_.c.size();
    // Dormand-Prince's last stage is taken at the fifth-order solution itself
    // (its row of a is b, and b's last weight is 0): projected onto the pins
    // first, it is the end of the step as the caller would project and
    // evaluate it, one evaluation a step fewer. Its error estimate then
    // differs by h/40 times the change of the rates that the projection
    // makes, a projection of a drift below the step's own error.
    const bool projectLast = projectionTolerance > 0 && lastStageIsEnd();
    for (size_t i = firstKnown ? 1 : 0; i < stages; ++i) {
        if (i > 0) {
            combineStages(w.q, &q0_, h, tableau_.a[i].data(), kq_, i);
            combineStages(w.v, &v0_, h, tableau_.a[i].data(), kv_, i);
        }
        const bool last = projectLast && i + 1 == stages;
        if (last) {
            endProjection_ = projectPositions(w, d.solver(), projectionTolerance);
            if (!endProjection_.converged) return std::numeric_limits<double>::quiet_NaN();
            projectVelocities(w, d.solver());
        }
        const Powers p = d.evaluate(w, t + tableau_.c[i] * h, t + h / 2);
        if (last) endPowers_ = p;
        kl_[i] = rates(p);
        // A stage's rates are its velocities and accelerations. Before the
        // last stage they are moved, not copied (the next stage writes all
        // of w.q and w.v, the evaluation all of w.a that it reads): on a long
        // chain each copy is another pass over memory.
        if (i + 1 < stages && kq_[i].size() == w.v.size() && kv_[i].size() == w.a.size()) {
            kq_[i].swap(w.v);
            kv_[i].swap(w.a);
        } else {
            kq_[i] = w.v;
            kv_[i] = w.a;
        }
    }
    Eigen::Vector3d dl = Eigen::Vector3d::Zero();
    if (!projectLast) {
        combineStages(w.q, &q0_, h, tableau_.b.data(), kq_, stages);
        combineStages(w.v, &v0_, h, tableau_.b.data(), kv_, stages);
    }
    for (size_t i = 0; i < stages; ++i) {
        const double bi = tableau_.b[i];
        if (bi == 0) continue;
        dl += (h * bi) * kl_[i];
    }
    ledger.held += dl[0];
    ledger.user += dl[1];
    ledger.damping += dl[2];
    if (tableau_.e.empty()) return 0;
    combineStages(errQ_, nullptr, h, tableau_.e.data(), kq_, stages);
    combineStages(errV_, nullptr, h, tableau_.e.data(), kv_, stages);
    return errorNorm(w);
}

// RMS of the local error over dynamic coordinates, scaled by atol + rtol |y|.
// A body counts once for each of its parts: the mean is over the parts the
// scene has, however many of them move as one (a locked pair, a still
// tail's segment of hundreds of blocks), so that joining parts that move
// rigidly changes what the error control asks of the step in nothing.
double Stepper::errorNorm(const World& w) const {
    double sum = 0, n = 0;
    const Eigen::Index bodies = std::min<Eigen::Index>(w.bodyCount(), w.q.size() / 3);
    for (Eigen::Index b = 0; b < bodies; ++b) {
        const double parts = double(w.body(int(b)).parts.size());
        for (Eigen::Index i = 3 * b; i < 3 * b + 3; ++i) {
            if (w.invMassDiag[i] == 0) continue;
            const double sq = tolerance_ * (1 + std::max(std::abs(q0_[i]), std::abs(w.q[i])));
            const double sv = tolerance_ * (1 + std::max(std::abs(v0_[i]), std::abs(w.v[i])));
            sum += parts * ((errQ_[i] / sq) * (errQ_[i] / sq) + (errV_[i] / sv) * (errV_[i] / sv));
            n += 2 * parts;
        }
    }
    return n > 0 ? std::sqrt(sum / n) : 0.0;
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
    if (atStart && kind_ != Integrator::RosenbrockW && kind_ != Integrator::SymplecticEuler) {
        kq_[0] = w.v;
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
        for (;;) {
            // A rejected trial left its end state in w; the first stage of
            // the next trial must be evaluated at the start of the step.
            w.q = q0_;
            w.v = v0_;
            ledger = start;
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

}  // namespace jl
