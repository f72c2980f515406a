// A run recorded from start to end: the frames an export or a report wants
// (one at t = 0, then one at exactly each multiple of the frame interval,
// read off the steps' dense output) and every event, handed on as the run produces them so that
// memory does not grow with the length of the run; and what the run was like
// (energy books, pin gaps, steps, why it ended). The command line's run and
// export and the desktop program's table export all record this way.
#pragma once

#include "jl/sim/frame.h"
#include "jl/sim/simulation.h"

#include <functional>
#include <string>
#include <vector>

namespace jl {

// Where a recording's frames and events go as they come; false from any of
// these stops the run (an output could not be written, or the target has
// seen what it wanted).
class RecordTarget {
public:
    virtual ~RecordTarget() = default;
    virtual bool frame(const Frame& f) = 0;
    virtual bool event(const Event& e) = 0;
    // After every step, its events handed on: a target that checks each
    // step (the pins on the world, the books of sim.frame()) looks here.
    virtual bool step(Simulation& /*sim*/) { return true; }
    // A target that draws the frames (a video of the 3-D view) wants the
    // ribbons in them; one that keeps numbers does not pay for them.
    virtual bool drawsRibbons() const { return false; }
};

// A target that keeps every frame and every event of a run: for a run short
// enough to hold (a test's, a picture's); `ribbons` for frames to draw.
struct WholeRun : RecordTarget {
    std::vector<Frame> frames;
    std::vector<Event> events;
    bool ribbons = false;
    bool frame(const Frame& f) override {
        frames.push_back(f);
        return true;
    }
    bool event(const Event& e) override {
        events.push_back(e);
        return true;
    }
    bool drawsRibbons() const override { return ribbons; }
};

struct Recording {
    double energyStart = 0, energyEnd = 0, worstBalance = 0, worstResidual = 0, wallSeconds = 0;
    double time = 0;
    long long steps = 0, evaluations = 0, events = 0;
    SolverFrame solver;         // the last frame's statistics (the step the engine chose among them)
    std::string failure;        // the engine's
    int interrupted = 0;        // what `interruption` returned when it ended the run early, or 0
    bool targetFailed = false;  // the target refused a frame, an event or a step
    bool complete() const { return failure.empty() && interrupted == 0 && !targetFailed; }
};

// Runs `sim` to exactly `until` (the last step shortened to land on it),
// handing every event to `target` and a frame (with ribbons only when the
// target draws them) at t = 0
// and then at exactly each instant of `grid` up to `until` (energy books
// checked on each; the frame times never change the steps), and keeping the
// largest pin gap after every step; the target sees the simulation after
// each step. Ends early on a failure, a refusal of the target or when
// `interruption` (asked between two steps) returns non-zero.
Recording record(Simulation& sim, double until, const FrameGrid& grid, RecordTarget* target,
                 const std::function<int()>& interruption = {});

}  // namespace jl
