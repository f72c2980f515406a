#include "app/jladder/summary.h"

#include "app/jladder/options.h"

#include <csignal>
#include <sstream>

namespace jl::cli {

namespace {

// What step the run took: the adaptive integrator's error control's (the
// range of the steps it chose), the scene's, or the engine's choice (its
// range, and how often a step that blew up made it halve the rest).
std::string stepJson(const SolverFrame& f) {
    std::ostringstream s;
    if (f.adaptiveStep) {
        s << "{\"chosen_by\":\"error control\",\"smallest\":" << jsonNumber(f.smallestStep)
          << ",\"largest\":" << jsonNumber(f.largestStep) << "}";
        return s.str();
    }
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
      << ",\"worst_energy_balance\":" << jsonNumber(r.worstBalance) << ",\"max_residual\":"
      << jsonNumber(r.worstResidual)
      // The first block of the still tail at the end (docs/model.md section 3.7): null if none hangs still.
      << ",\"still_from\":" << (r.solver.stillFrom >= 0 ? std::to_string(r.solver.stillFrom) : std::string("null"))
      << ",\"wall_seconds\":" << jsonNumber(r.wallSeconds) << ",\"failure\":" << failureJson(r) << "}";
    return s.str();
}

}  // namespace jl::cli
