#include "app/jladder/recording.h"

#include "app/jladder/interruption.h"
#include "app/jladder/options.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <sstream>

namespace jl::cli {

namespace {

void account(Recording& r, const Frame& f) {
    r.worstBalance = std::max(r.worstBalance, std::abs(f.energy.balance()));
    r.energyEnd = f.energy.total();
}

// The first multiple of `every` after t (a step may pass several): computed,
// not counted up to, so that a step far longer than `every` costs nothing.
double nextMultiple(double t, double every) { return every * (std::floor((t + 1e-12) / every) + 1); }

}  // namespace

Recording record(Simulation& sim, double until, double every, RecordTarget* target) {
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
        if ((r.interrupted = interruption())) break;
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

namespace {

// What step the run took: the scene's, or the engine's choice (its range,
// and how often a step that blew up made it halve the rest).
std::string stepJson(const SolverFrame& f) {
    std::ostringstream s;
    if (!f.automaticStep) {
        s << "{\"chosen_by\":\"scene\"}";
        return s.str();
    }
    s << "{\"chosen_by\":\"engine\",\"smallest\":" << jsonNumber(f.smallestStep)
      << ",\"largest\":" << jsonNumber(f.largestStep) << ",\"halvings\":" << f.stepHalvings << "}";
    return s.str();
}

// Why the run ended before `until`, in words, or null.
std::string failureJson(const Recording& r) {
    if (!r.failure.empty()) return jsonString(r.failure);
    if (r.interrupted)
        return jsonString(std::string("interrupted by ") + (r.interrupted == SIGINT ? "SIGINT" : "SIGTERM") +
                          " at t = " + std::to_string(r.time) + " s");
    if (r.targetFailed) return jsonString("an output could not be written at t = " + std::to_string(r.time) + " s");
    return "null";
}

}  // namespace

std::string summaryJson(const Recording& r, const std::string& scenePath) {
    std::ostringstream s;
    s << "{\"scene\":" << jsonString(scenePath) << ",\"time\":" << jsonNumber(r.time) << ",\"steps\":" << r.steps
      << ",\"evaluations\":" << r.evaluations << ",\"step\":" << stepJson(r.solver) << ",\"events\":" << r.events
      << ",\"energy_start\":" << jsonNumber(r.energyStart) << ",\"energy_end\":" << jsonNumber(r.energyEnd)
      << ",\"worst_energy_balance\":" << jsonNumber(r.worstBalance)
      << ",\"max_residual\":" << jsonNumber(r.worstResidual) << ",\"wall_seconds\":" << jsonNumber(r.wallSeconds)
      << ",\"failure\":" << failureJson(r) << "}";
    return s.str();
}

}  // namespace jl::cli
