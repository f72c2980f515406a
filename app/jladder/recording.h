// Runs a scene headless and records what the command-line tool reports: a
// JSON summary, and frames and events handed on as the run produces them
// (app/jladder/run_outputs.h writes them), so that memory does not grow
// with the length of the run.
#pragma once

#include "jl/sim/frame.h"
#include "jl/sim/simulation.h"

#include <string>

namespace jl::cli {

// Where a recording's frames and events go as they come; false from either
// stops the run (an output could not be written).
class RecordTarget {
public:
    virtual ~RecordTarget() = default;
    virtual bool frame(const Frame& f) = 0;
    virtual bool event(const Event& e) = 0;
};

struct Recording {
    double energyStart = 0, energyEnd = 0, worstBalance = 0, worstResidual = 0, wallSeconds = 0;
    double time = 0;
    long long steps = 0, evaluations = 0, events = 0;
    SolverFrame solver;         // the last frame's statistics (the step the engine chose among them)
    std::string failure;        // the engine's
    int interrupted = 0;        // the signal that ended the run early, or 0
    bool targetFailed = false;  // the target refused a frame or an event
    bool complete() const { return failure.empty() && interrupted == 0 && !targetFailed; }
};

// Runs `sim` to `until`, handing every event to `target` and a frame at t = 0
// and then at the first step at or after each multiple of `every` seconds
// (energy books checked on each), and keeping the largest pin gap after every
// step. Ends early on a failure, a refusal of the target or an interruption
// (app/jladder/interruption.h).
Recording record(Simulation& sim, double until, double every, RecordTarget* target);

std::string summaryJson(const Recording& r, const std::string& scenePath);

}  // namespace jl::cli
