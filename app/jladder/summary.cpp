#include "app/jladder/summary.h"

#include "app/jladder/json_text.h"

#include <csignal>

namespace jl::cli {

namespace {

// What step the run took: the adaptive integrator's error control's (the
// range of the steps it chose), the scene's, or the engine's choice (its
// range, how many steps it took again, and how often a step that blew up
// made it halve the rest).
Json stepJson(const SolverFrame& f) {
    if (f.adaptiveStep)
        return Json{{"chosen_by", "error control"},
                    {"smallest", f.smallestStep},
                    {"largest", f.largestStep},
                    {"rejected", f.rejected}};
    if (!f.automaticStep) return Json{{"chosen_by", "scene"}};
    return Json{{"chosen_by", "engine"},
                {"smallest", f.smallestStep},
                {"largest", f.largestStep},
                {"rejected", f.rejected},
                {"halvings", f.stepHalvings}};
}

// Why the run ended before `until`, in words, or null.
Json failureJson(const Recording& r) {
    if (!r.failure.empty()) return r.failure;
    if (r.interrupted)
        return std::string("interrupted by ") + (r.interrupted == SIGINT ? "SIGINT" : "SIGTERM") +
               " at t = " + std::to_string(r.time) + " s";
    if (r.targetFailed) return "an output could not be written at t = " + std::to_string(r.time) + " s";
    return nullptr;
}

}  // namespace

std::string summaryJson(const Recording& r, const std::string& scenePath) {
    Json s;
    s["scene"] = scenePath;
    s["time"] = r.time;
    s["steps"] = r.steps;
    s["evaluations"] = r.evaluations;
    s["step"] = stepJson(r.solver);
    s["events"] = r.events;
    s["energy_start"] = r.energyStart;
    s["energy_end"] = r.energyEnd;
    s["worst_energy_balance"] = r.worstBalance;
    s["max_residual"] = r.worstResidual;
    // The first block of the still tail at the end (docs/model.md section 3.7): null if none hangs still.
    s["still_from"] = r.solver.stillFrom >= 0 ? Json(r.solver.stillFrom) : Json(nullptr);
    s["wall_seconds"] = r.wallSeconds;
    s["failure"] = failureJson(r);
    return jsonText(s);
}

}  // namespace jl::cli
