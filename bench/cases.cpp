#include "bench/cases.h"

#include "jl/base/thread_clock.h"
#include "jl/engine/motion.h"
#include "jl/reference/elliptic.h"
#include "jl/reference/falling_chain.h"
#include "jl/reference/reference_chain.h"
#include "jl/scene/scene_fields.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

namespace jl::bench {

namespace {

// Every integrator, by its word in scene files (jl/scene/scene_fields.h).
struct Method {
    Integrator kind;
    std::string name;
};
std::vector<Method> methods() {
    std::vector<Method> out;
    for (const Word<Integrator>& w : kIntegrators) out.push_back({w.value, std::string(w.word)});
    return out;
}

bool adaptive(Integrator k) { return isAdaptive(k); }

}  // namespace

bool namesAdaptiveMethod(const std::string& method) {
    for (const Word<Integrator>& w : kIntegrators)
        if (isAdaptive(w.value) && method.find(w.word) != std::string::npos) return true;
    return false;
}

namespace {

// Runs `once` until at least `minSeconds` of CPU time have passed; returns the
// CPU seconds of one run. `once` returns false on failure (then one run only).
double timed(double minSeconds, const std::function<bool()>& once, bool& ok) {
    int runs = 0;
    const double start = threadSeconds();
    do {
        ok = once();
        ++runs;
    } while (ok && threadSeconds() - start < minSeconds);
    return (threadSeconds() - start) / runs;
}

// Steps (or, for the adaptive method, tolerances) for a study.
// The third-order Rosenbrock-W method stops at 1e-10: tighter, it takes
// tens of thousands of steps where Dormand-Prince takes hundreds.
std::vector<double> parameters(Integrator k, const std::vector<double>& steps, const std::vector<double>& tolerances) {
    if (!adaptive(k)) return steps;
    std::vector<double> out;
    for (double t : tolerances)
        if (k != Integrator::RosenbrockW || t >= 1e-10) out.push_back(t);
    return out;
}

// Advances w to `duration` with method `kind`: fixed steps of p, or (the
// adaptive method) tolerance p with steps of its choosing. False on failure.
bool advanceFor(World& w, Integrator kind, double p, double duration, double projection) {
    Dynamics d;
    Stepper s(kind, adaptive(kind) ? p : 1e-8);
    Ledger ledger;
    double t = 0;
    const double h = adaptive(kind) ? duration : p;
    while (t < duration * (1 - 1e-12)) {
        const MotionStep ms = advanceAndProject(w, d, s, t, std::min(h, duration - t), ledger, projection);
        if (!ms.ok()) return false;
        t += ms.step.taken;
    }
    return true;
}

void log(const BenchRow& r) {
    std::fprintf(stderr, "  %-10s %-30s N=%-6d %s=%.1e  cost %.3e s/s  error %.3e%s\n", r.study.c_str(),
                 r.method.c_str(), r.blocks, namesAdaptiveMethod(r.method) ? "tol" : "h", r.parameter, r.cost, r.error,
                 r.finished ? "" : "  (failed)");
}

}  // namespace

ScriptAction halfTurn(double at) {
    ScriptAction turn;
    turn.at = at;
    turn.angle = std::numbers::pi;
    turn.duration = 0.3;
    return turn;
}

// ---- the physical pendulum: one exact period ----

std::vector<BenchRow> pendulumStudy(const BenchPlan& plan) {
    constexpr double L = 0.06, T = 0.012, W = 0.045, rho = 600, g = 9.81, theta0 = 2.0;
    const double mass = rho * L * T * W, r = std::hypot(L / 2, T / 2);
    const double ip = mass * (L * L + T * T) / 12 + mass * r * r;
    const double period = pendulumPeriod(ip, mass, g, r, theta0);
    const Vec2 corner(-L / 2, -T / 2);
    const double rest = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x());
    const std::vector<double> perPeriod = plan.quick
                                              ? std::vector<double>{100, 1000, 10000}
                                              : std::vector<double>{50, 100, 300, 1000, 3000, 10000, 30000, 100000};
    const std::vector<double> tolerances =
        plan.quick ? std::vector<double>{1e-4, 1e-8, 1e-12} : std::vector<double>{1e-3, 1e-5, 1e-7, 1e-9, 1e-11, 1e-12};
    std::vector<BenchRow> rows;
    for (const Method& m : methods()) {
        std::vector<double> steps;
        for (double n : perPeriod) steps.push_back(period / n);
        for (double p : parameters(m.kind, steps, tolerances)) {
            BenchRow row{"pendulum", m.name, 1, p, 0, 0, true, ""};
            auto once = [&] {
                World w;
                const PartId block = w.addBox(mass, Vec2(L, T), W, Pose{-rotate(rest + theta0, corner), rest + theta0});
                w.combine(w.anchor(Vec2::Zero()), w.addParticle(block, corner));
                makeConsistentAfter(w, "combine");
                if (!advanceFor(w, m.kind, p, period, 1e-12)) return false;
                const double omegaScale = std::sqrt(mass * g * r / ip);
                row.error =
                    std::hypot(w.partPose(block).angle - rest - theta0, w.partVelocity(block).angular / omegaScale);
                return true;
            };
            row.cost = timed(plan.minSeconds, once, row.finished) / period;
            if (!row.finished) row.error = NAN;
            log(row);
            rows.push_back(row);
        }
    }
    return rows;
}

// ---- the falling chain against the reduced-coordinate reference ----

std::vector<BenchRow> chainStudy(const BenchPlan& plan, int n, bool independent, std::vector<Vec2>& referenceOut) {
    constexpr double duration = 0.5;
    referenceOut.clear();
    if (independent) {
        ReferenceChainSpec spec;
        spec.links = n;
        ReferenceChain reference(spec);
        // As tight as double precision allows: the best runs below reach
        // 1e-13 m, and a peer at 1e-11 m needs 1e-13 m to be shown 100x worse.
        reference.advanceTo(duration, 1e-14);
        for (int i = 0; i < n; ++i) referenceOut.push_back(reference.centre(i));
    } else {
        World w;
        const std::vector<PartId> parts = buildFallingChain(w, n);
        Dynamics d;
        Stepper s(Integrator::RK4);
        Ledger ledger;
        constexpr double h = 2e-5;
        for (int i = 0; i < int(std::lround(duration / h)); ++i) advanceAndProject(w, d, s, i * h, h, ledger, 1e-12);
        for (PartId p : parts) referenceOut.push_back(w.partPose(p).position);
    }

    const std::vector<double> steps =
        plan.quick ? std::vector<double>{1e-3, 1e-4} : std::vector<double>{2e-3, 1e-3, 5e-4, 2.5e-4, 1e-4, 5e-5, 2e-5};
    const std::vector<double> tolerances =
        plan.quick ? std::vector<double>{1e-5, 1e-9}
                   : std::vector<double>{1e-3, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13};
    std::vector<BenchRow> rows;
    for (const Method& m : methods())
        for (double p : parameters(m.kind, steps, tolerances)) {
            BenchRow row{"chain" + std::to_string(n), m.name, n, p, 0, 0, true, ""};
            auto once = [&] {
                World w;
                const std::vector<PartId> parts = buildFallingChain(w, n);
                if (!advanceFor(w, m.kind, p, duration, 1e-10)) return false;
                row.error = 0;
                for (int i = 0; i < n; ++i)
                    row.error =
                        std::max(row.error, (w.partPose(parts[size_t(i)]).position - referenceOut[size_t(i)]).norm());
                return true;
            };
            row.cost = timed(plan.minSeconds, once, row.finished) / duration;
            if (!row.finished) row.error = NAN;
            log(row);
            rows.push_back(row);
        }
    return rows;
}

// ---- the ladder cascade: events and final poses against a tight run ----

namespace {

Scene cascade(int blocks, double duration) {
    Scene s;
    s.ladder = LadderSpec{};
    s.ladder->blocks = blocks;
    s.script.push_back(halfTurn(0.2));
    s.duration = duration;
    return s;
}

struct CascadeResult {
    std::vector<Event> events;
    std::vector<Pose> poses;
    std::string failure;
};

CascadeResult runCascade(const Scene& scene) {
    CascadeResult r;
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        r.failure = built.errors.empty() ? "not built" : built.errors.front();
        return r;
    }
    built.simulation->advanceExactlyTo(scene.duration);
    Frame f = built.simulation->frame();
    r.events = f.events;
    r.poses = f.poses;
    r.failure = f.failure;
    return r;
}

}  // namespace

std::vector<BenchRow> ladderStudy(const BenchPlan& plan) {
    constexpr int blocks = 6;
    constexpr double duration = 1.2;
    Scene tight = cascade(blocks, duration);
    tight.solver.integrator = Integrator::DormandPrince45;
    tight.solver.tolerance = 1e-12;
    tight.solver.eventTolerance = 1e-12;
    const CascadeResult reference = runCascade(tight);
    std::fprintf(stderr, "  ladder reference: %zu events%s\n", reference.events.size(),
                 reference.failure.empty() ? "" : (" failed: " + reference.failure).c_str());

    struct Config {
        Integrator kind;
        std::vector<double> params;
    };
    const std::vector<Config> configs =
        plan.quick ? std::vector<Config>{{Integrator::ExplicitEuler, {1e-4}},
                                         {Integrator::RK4, {1e-3}},
                                         {Integrator::DormandPrince45, {1e-7}}}
                   : std::vector<Config>{{Integrator::ExplicitEuler, {1e-4, 3e-5, 1e-5}},
                                         {Integrator::SymplecticEuler, {1e-3, 3e-4, 1e-4, 3e-5}},
                                         {Integrator::RK4, {2e-3, 1e-3, 5e-4, 2e-4}},
                                         {Integrator::DormandPrince45, {1e-5, 1e-7, 1e-9, 1e-11}}};
    std::vector<BenchRow> rows;
    for (const Config& c : configs)
        for (EventPolicy policy : {EventPolicy::Located, EventPolicy::EndOfStep})
            for (double p : c.params) {
                Scene s = cascade(blocks, duration);
                s.solver.integrator = c.kind;
                if (adaptive(c.kind))
                    s.solver.tolerance = p;
                else
                    s.solver.step = p;
                s.solver.events = policy;
                const std::string method = std::string(integratorWord(c.kind)) +
                                           (policy == EventPolicy::Located ? " located" : " end-of-step");
                BenchRow row{"ladder", method, blocks, p, 0, 0, true, ""};
                CascadeResult result;
                row.cost = timed(
                               plan.minSeconds,
                               [&] {
                                   result = runCascade(s);
                                   return result.failure.empty();
                               },
                               row.finished) /
                           duration;
                // Error: the worst block-centre distance at the end (m); the
                // note: event sequence match and worst event-time error.
                if (row.finished && result.poses.size() == reference.poses.size()) {
                    for (size_t i = 0; i < result.poses.size(); ++i)
                        row.error =
                            std::max(row.error, (result.poses[i].position - reference.poses[i].position).norm());
                    size_t same = 0;
                    double worstTime = 0;
                    while (same < result.events.size() && same < reference.events.size() &&
                           result.events[same].kind == reference.events[same].kind &&
                           result.events[same].hinge == reference.events[same].hinge) {
                        worstTime =
                            std::max(worstTime, std::abs(result.events[same].time - reference.events[same].time));
                        ++same;
                    }
                    char note[160];
                    std::snprintf(note, sizeof note,
                                  "%zu of %zu events in the reference order; worst time error %.2e s", same,
                                  reference.events.size(), worstTime);
                    row.note = note;
                } else {
                    row.error = NAN;
                    row.note = result.failure;
                }
                log(row);
                rows.push_back(row);
            }
    return rows;
}

// ---- scaling: cost per block-step against N ----

std::vector<BenchRow> scalingStudy(const BenchPlan& plan) {
    const std::vector<int> sizes =
        plan.quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 1000, 10000, 100000};
    const double blockSteps = plan.quick ? 2e5 : 2e6;
    // Each measurement is made again and again from the same start, and the
    // fastest counts: on a shared machine a run can be slowed by its
    // neighbours, never sped up (as for the cost of an event). The runs go
    // round in rounds, every method at every size once per round (and again
    // within the round until it has run 0.1 CPU s: a short ladder's 2,000
    // steps take a few milliseconds), so that a slow minute on the machine
    // slows every size alike, not the sizes measured in it: the table is read
    // as a ratio between sizes.
    const int rounds = plan.quick ? 1 : 5;
    const double leastSecondsPerRound = plan.quick ? 0.0 : 0.1;
    struct Measured {
        Integrator kind;
        BenchRow row;
        double best = std::numeric_limits<double>::infinity(), simulated = 0;
        long long taken = 0, rejected = 0;
        int repetitions = 0;
    };
    std::vector<Measured> measured;
    for (const Method& m : methods())
        for (int n : sizes) {
            // Each method at a step it is stable at for the whole run (the
            // Euler methods blow up on the chain at 1 ms, and a run that stops
            // early measures too few steps): the cost of a step hardly
            // depends on its size.
            const double h = m.kind == Integrator::ExplicitEuler || m.kind == Integrator::SymplecticEuler ? 1e-4 : 1e-3;
            measured.push_back({m.kind, BenchRow{"scaling", m.name, n, h, 0, 0, true, ""}});
        }
    for (int round = 0; round < rounds; ++round)
        for (Measured& c : measured) {
            const Integrator kind = c.kind;
            const int n = c.row.blocks;
            const double h = c.row.parameter;
            const long long steps = std::clamp<long long>((long long)(blockSteps / n), 20, 2000);
            double spent = 0;
            for (int here = 0; here < 1 || (spent < leastSecondsPerRound && here < 40); ++here, ++c.repetitions) {
                World w;
                buildFallingChain(w, n);
                Dynamics d;
                Stepper s(kind, 1e-6);
                Ledger ledger;
                double t = 0;
                long long made = 0, thrown = 0;
                bool finished = true;
                // One step to warm the caches and size the work vectors.
                advanceAndProject(w, d, s, t, h, ledger, 1e-10);
                t += h;
                const double start = threadSeconds();
                for (; made < steps; ++made) {
                    const MotionStep ms = advanceAndProject(w, d, s, t, h, ledger, 1e-10);
                    if (!ms.ok()) {
                        finished = false;
                        break;
                    }
                    t += ms.step.taken;
                    thrown += ms.step.rejected;
                }
                const double cpu = threadSeconds() - start;
                spent += cpu;
                c.row.finished = c.row.finished && finished;
                if (cpu < c.best) c.best = cpu, c.taken = made, c.rejected = thrown, c.simulated = t - h;
            }
        }
    std::vector<BenchRow> rows;
    for (Measured& c : measured) {
        BenchRow& row = c.row;
        // error column: ns per block-step; cost: CPU s per simulated s.
        // A step the adaptive methods' error control rejects is as much
        // work as one it accepts, and counts as one: this is the cost of
        // a step's work per block, whatever the controller does with it
        // (it rejects most while it finds its step, which is all that a
        // run of 20 steps sees).
        row.cost = c.best / std::max(c.simulated, 1e-300);
        row.error = 1e9 * c.best / (double(row.blocks) * double(std::max<long long>(c.taken + c.rejected, 1)));
        char note[96];
        std::snprintf(note, sizeof note, "%lld steps%s%s", c.taken,
                      c.rejected > 0 ? (" + " + std::to_string(c.rejected) + " rejected").c_str() : "",
                      row.finished ? "" : ", stopped: a step failed");
        row.note = note;
        std::fprintf(stderr, "  scaling %-18s N=%-7d %5lld steps  %8.1f ns/block-step (fastest of %d)\n",
                     row.method.c_str(), row.blocks, c.taken, row.error, c.repetitions);
        rows.push_back(row);
    }
    return rows;
}

// ---- a long ladder turned over: RK4 and the linearly implicit method ----

namespace {

std::vector<BenchRow> longLadderRuns(int blocks, double duration) {
    struct Config {
        Integrator kind;
        double parameter;  // the step (0: the engine's), or the adaptive method's tolerance
        StillTail tail = StillTail::Joined;
    };
    // The reference: Dormand-Prince at 1e-10 on the full model (every block
    // its own body from the start), an independent method of the engine
    // without the still tail (docs/model.md section 3.7). After the first
    // fold the ladder is sensitive: at 1,000 blocks RK4 at 0.125 and
    // 0.0625 ms end 2e-4 m apart, and the latter 1e-5 m from this reference,
    // which rosenbrock_w at 1e-6 meets to 6e-7 m. Dormand-Prince at several
    // tolerances: its error per tolerance on this ladder is not known
    // beforehand, and the cheapest run within 1e-6 m (the target) may be a
    // looser one; the same for Verner's 6(5) pair, whose stability interval
    // on the imaginary axis (2.58 against 0.997) lets it past the hanging
    // ladder's fastest vibration in longer steps. One run on the full model
    // shows what the still tail saves.
    //
    // At 100,000 blocks the full model is out of reach (Verner at 1e-4 took
    // 229 CPU s on it, docs/model.md section 3.7): the reference there keeps
    // the still tail, and the runs are the engine's defaults (RK4 at its own
    // step) and the method that is cheapest within 1e-6 m at 10,000 blocks
    // (Verner's pair) at five tolerances (at 1e-6 it is 2.2e-6 m off).
    const bool huge = blocks >= 100000;
    const Config reference{Integrator::DormandPrince45, 1e-10, huge ? StillTail::Joined : StillTail::Separate};
    const std::vector<Config> hugeConfigs = {reference,
                                             {Integrator::RK4, 0},
                                             {Integrator::Verner65, 1e-4},
                                             {Integrator::Verner65, 1e-5},
                                             {Integrator::Verner65, 1e-6},
                                             {Integrator::Verner65, 3e-7},
                                             {Integrator::Verner65, 1e-7}};
    const std::vector<Config> configs =
        huge ? hugeConfigs
             : std::vector<Config>{reference,
                                   {Integrator::RK4, 1e-3},
                                   {Integrator::RK4, 5e-4},
                                   {Integrator::RK4, 0},
                                   {Integrator::DormandPrince45, 1e-4},
                                   {Integrator::DormandPrince45, 3e-5},
                                   {Integrator::DormandPrince45, 1e-5},
                                   {Integrator::DormandPrince45, 1e-5, StillTail::Separate},
                                   {Integrator::DormandPrince45, 3e-6},
                                   {Integrator::DormandPrince45, 1e-6},
                                   {Integrator::Verner65, 1e-4},
                                   {Integrator::Verner65, 3e-5},
                                   {Integrator::Verner65, 1e-5},
                                   {Integrator::Verner65, 3e-6},
                                   {Integrator::Verner65, 1e-6},
                                   {Integrator::RosenbrockW, 1e-4},
                                   {Integrator::RosenbrockW, 1e-5},
                                   {Integrator::RosenbrockW, 1e-6}};
    const auto sceneOf = [&](const Config& c) {
        Scene s = cascade(blocks, duration);
        s.script.front().at = 0.0;
        s.solver.integrator = c.kind;
        s.solver.stillTail = c.tail;
        if (adaptive(c.kind))
            s.solver.tolerance = c.parameter;
        else
            s.solver.step = c.parameter;
        return s;
    };
    const auto run = [&](const Config& c, Frame& f) {
        Simulation::Built built = Simulation::build(sceneOf(c));
        if (!built.simulation) {  // a row that says why, as for the 10,000-block classic
            f = Frame{};
            f.failure = built.errors.empty() ? "not built" : built.errors.front();
            return 0.0;
        }
        const double start = threadSeconds();
        built.simulation->advanceExactlyTo(duration);
        const double cpu = threadSeconds() - start;
        f = built.simulation->frame();
        return cpu;
    };
    // Every run under two seconds is made five times (the same run each
    // time, bit for bit) and the fastest counts: this machine's speed drifts
    // by up to 1.5x from one minute to the next, and the targets are read
    // off these rows. The repetitions go round in rounds, every run once per
    // round, so that a slow minute slows the runs compared alike.
    struct Measured {
        Frame frame;
        double cpu = 0;
        int runs = 1;
    };
    std::vector<Measured> measured(configs.size());
    for (size_t i = 0; i < configs.size(); ++i) measured[i].cpu = run(configs[i], measured[i].frame);
    for (int round = 1; round < 5; ++round)
        for (size_t i = 0; i < configs.size(); ++i)
            if (measured[i].cpu < 2.0) {
                Frame again;
                measured[i].cpu = std::min(measured[i].cpu, run(configs[i], again));
                ++measured[i].runs;
            }
    std::vector<BenchRow> rows;
    std::vector<Pose> exact;
    for (size_t i = 0; i < configs.size(); ++i) {
        const Config& c = configs[i];
        const Frame& f = measured[i].frame;
        const double cpu = measured[i].cpu;
        const int runs = measured[i].runs;
        BenchRow row{"long_ladder",
                     std::string(integratorWord(c.kind)) + " located" +
                         (!adaptive(c.kind) && c.parameter == 0 ? " (the engine's step)" : "") +
                         (c.tail == StillTail::Separate ? ", full model" : ""),
                     blocks,
                     c.parameter,
                     0,
                     NAN,
                     true,
                     ""};
        row.finished = f.failure.empty();
        row.cost = cpu / std::max(f.time, 1e-300);
        if (i == 0) {
            exact = f.poses;
            row.method += huge ? " (reference, with the still tail)" : " (reference)";
            row.error = 0;
        } else if (row.finished && f.poses.size() == exact.size()) {
            row.error = 0;
            for (size_t k = 0; k < exact.size(); ++k)
                row.error = std::max(row.error, (f.poses[k].position - exact[k].position).norm());
        }
        // A run that stopped has no error to give (no NaN in a file).
        char error[64] = "no block-centre error (it stopped)";
        if (std::isfinite(row.error)) std::snprintf(error, sizeof error, "block-centre error %.2e m", row.error);
        char note[400];
        std::snprintf(note, sizeof note,
                      "simulated %.4f s in %.3f CPU s (%.3fx real time), %lld steps, %.0f ns per block-step, %s%s%s%s",
                      f.time, cpu, f.time / cpu, f.solver.steps,
                      1e9 * cpu / (double(blocks) * double(std::max<long long>(f.solver.steps, 1))), error,
                      runs > 1 ? (" (fastest of " + std::to_string(runs) + " runs)").c_str() : "",
                      row.finished ? "" : "; stopped: ", f.failure.c_str());
        row.note = note;
        std::fprintf(stderr, "  long ladder N=%d %s %.1e: %s\n", blocks, row.method.c_str(), c.parameter, note);
        rows.push_back(row);
    }
    return rows;
}

}  // namespace

LongClassicRun longClassicRun(const BenchPlan& plan) {
    LongClassicRun r;
    if (plan.quick) return r;
    r.blocks = 10000;
    r.asked = 3.0;
    // Twice, the fastest counts (the same run bit for bit; the machine's
    // speed drifts from one minute to the next).
    for (int run = 0; run < 2; ++run) {
        Simulation::Built built = Simulation::build(cascade(r.blocks, r.asked));
        if (!built.simulation) {
            r.failure = built.errors.empty() ? "not built" : built.errors.front();
            break;
        }
        const double start = threadSeconds();
        built.simulation->advanceExactlyTo(r.asked);
        const double cpu = threadSeconds() - start;
        const Frame f = built.simulation->frame();
        if (run > 0 && cpu >= r.cpu) continue;
        r.cpu = cpu;
        r.simulated = f.time;
        r.steps = f.solver.steps;
        r.evaluations = f.solver.evaluations;
        r.rejected = f.solver.rejected;
        r.halvings = f.solver.stepHalvings;
        r.books = f.energy.balance();
        r.failure = f.failure;
    }
    r.runs = 2;
    std::fprintf(stderr, "  classic N=%d for %.1f s: %.3f CPU s, %lld steps\n", r.blocks, r.asked, r.cpu, r.steps);
    return r;
}

std::vector<BenchRow> longLadderStudy(const BenchPlan& plan) {
    std::vector<BenchRow> rows;
    for (int blocks : plan.quick ? std::vector<int>{1000} : std::vector<int>{1000, 10000, 100000}) {
        std::vector<BenchRow> some = longLadderRuns(blocks, plan.quick ? 0.03 : 0.5);
        rows.insert(rows.end(), some.begin(), some.end());
    }
    return rows;
}

}  // namespace jl::bench
