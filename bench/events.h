// jladder bench: the cost of an event. Ladders of 60 x 3 mm blocks (N = 12,
// 200, 1,000, 10,000) turned over with the engine's automatic step; the CPU
// time of a window that contains events, less what the same number of plain
// steps costs on the same ladder hanging at rest, per event.
#pragma once

#include "bench/cases.h"

#include <string>
#include <vector>

namespace jl::bench {

struct EventCostRow {
    int blocks = 0;
    double from = 0, to = 0;  // s, the measured window of the turned-over run
    // The turned-over ladder over the window (restored from one snapshot
    // for each repetition; the fastest repetition counts).
    long long steps = 0;  // steps taken in the window
    int events = 0;       // hinge events recorded in it (lock, unlock, fold, unfold, flip, bounce)
    int instants = 0;     // distinct instants they happen at (one location and resolve each)
    std::string kinds;    // e.g. "2 fold, 2 flip"
    double meanStep = 0;  // s, (to - from) / steps
    double runCpu = 0;    // CPU s of the window
    int runRepetitions = 0;
    bool repeatable = true;  // every repetition recorded the same events
    // The same ladder hanging at rest, the engine's automatic step, no events.
    double plainStep = 0;      // s, the step the engine chose there
    long long plainSteps = 0;  // steps in one timed repetition
    int plainRepetitions = 0;
    int plainEvents = 0;      // events in the plain run (0 expected)
    double plainStepCpu = 0;  // CPU s per step
    // The control: the same turned-over run from the start of the turn to
    // the window (no events expected there), a ladder in motion.
    long long controlSteps = 0;
    int controlEvents = 0, controlRepetitions = 0;
    double controlStep = 0, controlStepCpu = 0;  // s, CPU s per step
    // (runCpu - steps * plainStepCpu) / events, per instant, the share of
    // the window's CPU that events take; and the cost per event with the
    // control's step cost in place of the hanging ladder's.
    double perEvent = 0, perInstant = 0, eventShare = 0, perEventControl = 0;
    // The direct part: the steps that record the events, each timed alone
    // (fastest of the repetitions after the first), less a plain step each,
    // per event. It leaves out what events make later steps cost.
    int eventfulSteps = 0;
    double eventfulCpu = 0, perEventInStep = 0;
    double setupCpu = 0;  // CPU s of the whole measurement (untimed runs up to the window included)
    std::string failure;
};

std::vector<EventCostRow> eventCostStudy(const BenchPlan& plan);

}  // namespace jl::bench
