#include "bench/folding_siconos.h"

#include "jl/base/thread_clock.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>

#ifdef JL_BENCH_PEERS
#include <SiconosKernel.hpp>
#endif

namespace jl::bench {

#ifdef JL_BENCH_PEERS

namespace {

using namespace folding;

// The chain in absolute angles q_i (block i's angle from +x). Block i's
// centre is sum_{j<i} L e(q_j) + (L/2) e(q_i), so its velocity is
// L sum_j a_ij e'(q_j) v_j with a_ij = 1 (j < i), 1/2 (j = i), 0 (j > i).
// The kinetic energy 1/2 v^T M v then has
//   M_jk = m L^2 c_jk cos(q_j - q_k) + I delta_jk,  c_jk = sum_i a_ij a_ik,
// and Lagrange's equations M qdd + FGyr = -dV/dq with
//   FGyr_j = sum_k m L^2 c_jk sin(q_j - q_k) v_k^2,
//   dV/dq_j = m g L (N - j - 1/2) cos q_j   (V = sum_i m g y_i).
// Siconos writes M qdd + FGyr + FInt = FExt + p: gravity is FInt = dV/dq.
double coupling(unsigned n, unsigned j, unsigned k) {
    if (j == k) return double(n - 1 - j) + 0.25;
    return double(n - 1 - std::max(j, k)) + 0.5;
}

const double kMl2 = kMass * kLength * kLength;

// Siconos' plugins: matrices column-major, z unused.
void chainMass(unsigned n, double* q, double* mass, unsigned, double*) {
    for (unsigned k = 0; k < n; ++k)
        for (unsigned j = 0; j < n; ++j)
            mass[j + n * k] = kMl2 * coupling(n, j, k) * std::cos(q[j] - q[k]) + (j == k ? kInertia : 0.0);
}

void chainFGyr(unsigned n, double* q, double* v, double* f, unsigned, double*) {
    for (unsigned j = 0; j < n; ++j) {
        f[j] = 0;
        for (unsigned k = 0; k < n; ++k) f[j] += kMl2 * coupling(n, j, k) * std::sin(q[j] - q[k]) * v[k] * v[k];
    }
}

void chainFGyrJacobianQ(unsigned n, double* q, double* v, double* jac, unsigned, double*) {
    for (unsigned j = 0; j < n; ++j) {
        double diagonal = 0;
        for (unsigned k = 0; k < n; ++k) {
            if (k == j) continue;
            const double d = kMl2 * coupling(n, j, k) * std::cos(q[j] - q[k]) * v[k] * v[k];
            jac[j + n * k] = -d;
            diagonal += d;
        }
        jac[j + n * j] = diagonal;
    }
}

void chainFGyrJacobianV(unsigned n, double* q, double* v, double* jac, unsigned, double*) {
    for (unsigned k = 0; k < n; ++k)
        for (unsigned j = 0; j < n; ++j) jac[j + n * k] = 2 * kMl2 * coupling(n, j, k) * std::sin(q[j] - q[k]) * v[k];
}

double gravityLever(unsigned n, unsigned j) { return kMass * kGravity * kLength * (double(n - j) - 0.5); }

void chainGravity(double, unsigned n, double* q, double*, double* f, unsigned, double*) {
    for (unsigned j = 0; j < n; ++j) f[j] = gravityLever(n, j) * std::cos(q[j]);
}

void chainGravityJacobianQ(double, unsigned n, double* q, double*, double* jac, unsigned, double*) {
    for (unsigned k = 0; k < n; ++k)
        for (unsigned j = 0; j < n; ++j) jac[j + n * k] = j == k ? -gravityLever(n, j) * std::sin(q[j]) : 0.0;
}

std::vector<Vec2> centres(const SiconosVector& q) {
    std::vector<Vec2> out;
    Vec2 pin(0, 0);
    for (unsigned i = 0; i < q.size(); ++i) {
        const Vec2 e(std::cos(q(i)), std::sin(q(i)));
        out.push_back(pin + 0.5 * kLength * e);
        pin = pin + kLength * e;
    }
    return out;
}

// Kinetic plus gravitational energy; the chain starts at rest at y = 0 with 0.
double energy(const SiconosVector& q, const SiconosVector& v) {
    const unsigned n = q.size();
    std::vector<double> mass(size_t(n) * n), qq(n);
    for (unsigned i = 0; i < n; ++i) qq[i] = q(i);
    chainMass(n, qq.data(), mass.data(), 0, nullptr);
    double e = 0;
    for (unsigned j = 0; j < n; ++j) {
        for (unsigned k = 0; k < n; ++k) e += 0.5 * v(j) * mass[j + n * k] * v(k);
        e += gravityLever(n, j) * std::sin(q(j));  // sum_i m g y_i, regrouped by angle
    }
    return e;
}

// The chain at rest along +x and, with stops, 2 (N - 1) unilateral
// constraints y = stopAngle(N) -+ (q_i - q_{i-1}) >= 0, each its own Interaction so
// that each opens and closes on its own.
// `interactions`: hinge i's two stops at 2 (i - 1) and 2 (i - 1) + 1.
std::shared_ptr<NonSmoothDynamicalSystem> buildChain(int n, bool stops, std::shared_ptr<LagrangianDS>& ds,
                                                     std::vector<std::shared_ptr<Interaction>>& interactions) {
    auto q0 = std::make_shared<SiconosVector>(unsigned(n));
    auto v0 = std::make_shared<SiconosVector>(unsigned(n));
    q0->zero();
    v0->zero();
    ds = std::make_shared<LagrangianDS>(q0, v0);
    ds->setComputeMassFunction(chainMass);
    ds->setComputeFGyrFunction(chainFGyr);
    ds->setComputeJacobianFGyrqFunction(chainFGyrJacobianQ);
    ds->setComputeJacobianFGyrqDotFunction(chainFGyrJacobianV);
    ds->setComputeFIntFunction(chainGravity);
    ds->setComputeJacobianFIntqFunction(chainGravityJacobianQ);
    auto nsds = std::make_shared<NonSmoothDynamicalSystem>(0.0, kDuration);
    nsds->insertDynamicalSystem(ds);
    if (!stops) return nsds;
    auto plastic = std::make_shared<NewtonImpactNSL>(0.0);
    for (int i = 1; i < n; ++i)
        for (double side : {1.0, -1.0}) {
            auto h = std::make_shared<SimpleMatrix>(1u, unsigned(n));
            h->zero();
            (*h)(0, unsigned(i)) = -side;
            (*h)(0, unsigned(i - 1)) = side;
            auto b = std::make_shared<SiconosVector>(1u);
            (*b)(0) = stopAngle(n);
            auto relation = std::make_shared<LagrangianLinearTIR>(h, b);
            interactions.push_back(std::make_shared<Interaction>(plastic, relation));
            nsds->link(interactions.back(), ds);
        }
    return nsds;
}

// What a run reports, gathered as it goes.
class Observer {
public:
    Observer(FoldingRun& run, const SiconosFolding& how, int n)
        : run_(run), how_(how), stop_(stopAngle(n)), previous_(size_t(n - 1), 0.0), previousRate_(size_t(n - 1), 0.0) {
        run_.firstClosing.assign(size_t(n - 1), kNever);
    }

    // The state at time t. `located`: t is an event the scheme located (a
    // hinge within kClosed of its stop closed at t); otherwise a closing is
    // interpolated between the last time and t. `stopped` (time stepping):
    // hinge i's stops took an impulse in the step that ends at t. Moreau-Jean
    // with theta = 1 stops a hinge short of its stop (its position update
    // uses the velocity after the impulse, zero): then the closing is where
    // the rate before the step would have reached the stop.
    bool see(double t, const SiconosVector& q, const SiconosVector& v, bool located,
             const std::vector<bool>& stopped = {}) {
        for (unsigned i = 1; i < q.size(); ++i) {
            const double phi = std::abs(q(i) - q(i - 1));
            double& closing = run_.firstClosing[i - 1];
            const double p0 = previous_[i - 1], rate0 = previousRate_[i - 1], step = t - lastTime_;
            if (std::isnan(closing) && located && phi >= stop_ - kClosed) closing = t;
            if (std::isnan(closing) && !located && phi >= stop_) closing = lastTime_ + step * (stop_ - p0) / (phi - p0);
            if (std::isnan(closing) && !stopped.empty() && stopped[i - 1])
                closing = lastTime_ + (rate0 > 0 ? std::min(step, (stop_ - p0) / rate0) : step);
            previous_[i - 1] = phi;
            previousRate_[i - 1] = (q(i) - q(i - 1) >= 0 ? 1 : -1) * (v(i) - v(i - 1));
        }
        lastTime_ = t;
        for (size_t s = 0; s < kSampleTimes.size(); ++s)
            if (std::abs(t - kSampleTimes[s]) < 1e-9) {
                run_.centres[s] = centres(q);
                run_.dissipated[s] = -energy(q, v);
            }
        if (how_.trace && t >= nextTrace_ - 1e-12) {
            std::fprintf(how_.trace, "%.6f", t);
            for (unsigned i = 1; i < q.size(); ++i) std::fprintf(how_.trace, " %+.5f", q(i) - q(i - 1));
            std::fprintf(how_.trace, "  E %.3e\n", energy(q, v));
            nextTrace_ += how_.traceEvery;
        }
        for (unsigned i = 0; i < q.size(); ++i)
            if (!std::isfinite(q(i)) || !std::isfinite(v(i))) return false;
        return true;
    }

    // rad: a hinge this close to its stop at a located event has closed
    // (Lsodar's root finding leaves it a rounding error away).
    static constexpr double kClosed = 1e-7;

private:
    FoldingRun& run_;
    const SiconosFolding& how_;
    double stop_;  // rad, the stops of this N
    std::vector<double> previous_, previousRate_;
    double lastTime_ = 0, nextTrace_ = 0;
};

// What Siconos says when it throws, on one line.
std::string message(const std::exception& e) {
    std::string text = boost::diagnostic_information(e);
    for (char& c : text)
        if (c == '\n') c = ' ';
    return text;
}

void moreauJean(int n, const SiconosFolding& how, FoldingRun& run) {
    std::shared_ptr<LagrangianDS> ds;
    std::vector<std::shared_ptr<Interaction>> stops;
    auto nsds = buildChain(n, how.stops, ds, stops);
    auto td = std::make_shared<TimeDiscretisation>(0.0, how.step);
    auto osi = std::make_shared<MoreauJeanOSI>(how.theta);
    auto lcp = std::make_shared<LCP>();
    auto s = std::make_shared<TimeStepping>(nsds, td, osi, lcp);
    s->associate(osi, ds);
    s->setWarnOnNonConvergence(false);
    s->initialize();
    Observer observer(run, how, n);
    observer.see(0, *ds->q(), *ds->velocity(), false);
    std::vector<bool> stopped(stops.size() / 2);
    while (s->hasNextEvent()) {
        try {
            s->computeOneStep();
        } catch (const std::exception& e) {
            run.finished = false;
            run.why = "Siconos threw (" + message(e) + ") in the step to t = " + std::to_string(s->nextTime()) + " s";
            return;
        }
        std::fill(stopped.begin(), stopped.end(), false);
        const double t = s->nextTime();
        for (size_t k = 0; k < stops.size(); ++k) stopped[k / 2] = stopped[k / 2] || (*stops[k]->lambda(1))(0) > 0;
        if (!observer.see(t, *ds->q(), *ds->velocity(), false, stopped)) {
            run.finished = false;
            run.why = "NaN at t = " + std::to_string(t) + " s";
            return;
        }
        s->nextStep();
    }
}

// An event-driven LCP (impact or acceleration level) that first brings the
// mass matrix and the free acceleration to the present state. Siconos 4.4
// takes both from Lsodar's last right-hand side: at an event that one may be
// from past the event and from before the impact, and during the smooth
// motion EventDriven::computef solves the acceleration LCP before it
// evaluates the right-hand side. For a chain whose mass matrix depends on q
// and whose gyroscopic forces go as v^2, the LCP then holds a stop with a
// negative or positive acceleration and EventDriven throws ("output[2] and
// lambda[2] ... must be nonnegative") at the first stop that stays closed.
class PresentLCP : public LCP {
public:
    explicit PresentLCP(std::shared_ptr<LsodarOSI> lsodar) : lsodar_(std::move(lsodar)) {}
    bool preCompute(double time) override {
        lsodar_->computeRhs(time);
        return LCP::preCompute(time);
    }

private:
    std::shared_ptr<LsodarOSI> lsodar_;
};

void eventDriven(int n, const SiconosFolding& how, FoldingRun& run) {
    std::shared_ptr<LagrangianDS> ds;
    std::vector<std::shared_ptr<Interaction>> stops;
    auto nsds = buildChain(n, how.stops, ds, stops);
    // Time-discretisation events land the run on the sample times (and the
    // trace's); impacts and releases come between them.
    auto td = std::make_shared<TimeDiscretisation>(0.0, how.trace ? how.traceEvery : kSampleTimes[0]);
    auto s = std::make_shared<EventDriven>(nsds, td);
    auto osi = std::make_shared<LsodarOSI>();
    osi->setTol(1, how.tolerance, how.tolerance);
    s->associate(osi, ds);
    s->insertNonSmoothProblem(std::make_shared<PresentLCP>(osi), SICONOS_OSNSP_ED_IMPACT);
    s->insertNonSmoothProblem(std::make_shared<PresentLCP>(osi), SICONOS_OSNSP_ED_SMOOTH_ACC);
    s->initialize();
    // Lsodar's default, 500 steps between two events, is too few (and its
    // work arrays exist only once the simulation is initialised).
    osi->setMaxNstep(100000000);
    Observer observer(run, how, n);
    observer.see(0, *ds->q(), *ds->velocity(), true);
    const double start = threadSeconds();
    long events = 0;
    while (s->hasNextEvent()) {
        try {
            s->advanceToEvent();
            s->processEvents();
        } catch (const std::exception& e) {
            run.finished = false;
            run.why = "Siconos threw (" + message(e) + ") after " + std::to_string(events) +
                      " events, at t = " + std::to_string(s->startingTime()) + " s";
            return;
        }
        const double t = s->startingTime();
        if (!observer.see(t, *ds->q(), *ds->velocity(), true)) {
            run.finished = false;
            run.why = "NaN at t = " + std::to_string(t) + " s";
            return;
        }
        if (++events >= how.maxEvents || threadSeconds() - start > how.maxCpuSeconds) {
            run.finished = false;
            run.why = "stalled: " + std::to_string(events) + " events and " +
                      std::to_string(int(threadSeconds() - start)) + " s CPU reached only t = " + std::to_string(t) +
                      " s";
            return;
        }
    }
    run.why = std::to_string(events) + " events";
}

std::string setting(const SiconosFolding& how) {
    char text[64];
    if (how.eventDriven)
        std::snprintf(text, sizeof text, "tolerance %.0e", how.tolerance);
    else
        std::snprintf(text, sizeof text, "dt = %.0e s", how.step);
    return text;
}

}  // namespace

FoldingRun runFoldingSiconos(int n, const SiconosFolding& how) {
    FoldingRun run;
    run.engine = "siconos 4.4";
    run.blocks = n;
    run.setting = setting(how);
    if (how.eventDriven) {
        run.method = "event-driven lsodar";
        run.stopModel =
            "complementarity, Newton impact law e = 0; each impact located by Lsodar's root finding "
            "and resolved by an impulse LCP, contact kept by an acceleration-level LCP";
    } else {
        char method[48];
        std::snprintf(method, sizeof method, "moreau-jean theta=%g", how.theta);
        run.method = method;
        run.stopModel =
            "complementarity, Newton impact law e = 0, Moreau-Jean velocity-level LCP each step "
            "(impacts not located)";
    }
    const double start = threadSeconds();
    try {
        if (how.eventDriven)
            eventDriven(n, how, run);
        else
            moreauJean(n, how, run);
    } catch (const std::exception& e) {
        run.finished = false;
        run.why = "Siconos threw: " + message(e);
    }
    run.cpuSeconds = threadSeconds() - start;
    return run;
}

std::vector<FoldingRun> runFoldingSiconos(int n, double minSeconds) {
    // Moreau-Jean's steps: at N = 100 one step takes about N^2 / 100 times
    // as long as at N = 10 (dense mass matrix, 198 stops), and theta = 0.5
    // gains energy until its Newton iterations fail: at N = 10 and 1e-3 s at
    // t = 0.49 s; at N = 100 and 1e-3 s after 230 s CPU, at 1e-4 s still
    // running after 7 min CPU (without stops it failed after 0.5 s, 54 s CPU).
    // So at N = 100 only theta = 1, at 1e-3 and 1e-4 s.
    std::vector<SiconosFolding> settings;
    for (double theta : {0.5, 1.0})
        for (double step : {1e-3, 1e-4, 1e-5}) {
            if (n > 10 && (step < 1e-4 || theta == 0.5)) continue;
            SiconosFolding how;
            how.theta = theta;
            how.step = step;
            settings.push_back(how);
        }
    // Event-driven down to 1e-14, the tightest Lsodar takes (at 1e-16 it
    // stops: "excess accuracy requested"); each takes under 0.2 s at N = 10.
    for (double tolerance : {1e-4, 1e-6, 1e-8, 1e-10, 1e-12, 1e-14}) {
        SiconosFolding how;
        how.eventDriven = true;
        how.tolerance = tolerance;
        settings.push_back(how);
    }
    std::vector<FoldingRun> out;
    for (const SiconosFolding& how : settings) {
        FoldingRun run;
        int repeats = 0;
        double cpu = 0;
        do {  // repeat short runs so the clock resolves them
            run = runFoldingSiconos(n, how);
            cpu += run.cpuSeconds;
            ++repeats;
        } while (cpu < minSeconds && run.finished);
        run.cpuSeconds = cpu / repeats;
        std::fprintf(stderr, "  siconos %-22s N=%-4d %-16s %8.3f s %s\n", run.method.c_str(), n, run.setting.c_str(),
                     run.cpuSeconds, run.finished ? "" : run.why.c_str());
        out.push_back(run);
    }
    return out;
}

std::string siconosVersion() { return "Siconos " JL_SICONOS_VERSION " (Debian libsiconos-kernel-dev)"; }

#else

FoldingRun runFoldingSiconos(int, const SiconosFolding&) {
    FoldingRun run;
    run.finished = false;
    run.why = "not measured: this build has JL_BENCH_PEERS off";
    return run;
}

std::vector<FoldingRun> runFoldingSiconos(int, double) { return {}; }

std::string siconosVersion() { return "not measured: this build has JL_BENCH_PEERS off"; }

#endif

}  // namespace jl::bench
