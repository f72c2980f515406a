#include "jl/sim/recording.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace jl {

namespace {

void account(Recording& r, const Frame& f) {
    r.worstBalance = std::max(r.worstBalance, std::abs(f.energy.balance()));
    r.energyEnd = f.energy.total();
}

// The first multiple of `every` after t (a step may pass several): computed,
// not counted up to, so that a step far longer than `every` costs nothing.
double nextMultiple(double t, double every) { return every * (std::floor((t + 1e-12) / every) + 1); }

}  // namespace

Recording record(Simulation& sim, double until, double every, RecordTarget* target, const std::function<int()>& interruption) {
    Recording r;
    const auto handOn = [&](const std::vector<Event>& events) {
        for (const Event& e : events) {
            ++r.events;
            r.targetFailed = r.targetFailed || (target && !target->event(e));
        }
    };
    const Frame first = sim.frame();
    handOn(first.events);
    r.energyStart = first.energy.total();
    account(r, first);
    r.targetFailed = r.targetFailed || (target && !target->frame(first));
    double nextFrame = every;
    const auto start = std::chrono::steady_clock::now();
    while (!r.targetFailed && sim.time() < until && sim.failure().empty()) {
        if (interruption && (r.interrupted = interruption())) break;
        if (!sim.stepOnceUpTo(until)) break;  // the run ends at exactly `until`
        handOn(sim.takeEvents());
        r.worstResidual = std::max(r.worstResidual, sim.lastResidual());
        const bool due = every > 0 && sim.time() >= nextFrame - 1e-12;
        if (!due && sim.time() < until) continue;
        const Frame f = sim.frame();
        handOn(f.events);
        account(r, f);
        if (due) {
            r.targetFailed = r.targetFailed || (target && !target->frame(f));
            nextFrame = nextMultiple(sim.time(), every);
        }
    }
    const Frame last = sim.frame();
    r.failure = last.failure;
    r.time = sim.time();
    r.steps = last.solver.steps;
    r.evaluations = last.solver.evaluations;
    r.solver = last.solver;
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace jl
