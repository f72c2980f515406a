// How long work has left, on one line of stderr that is redrawn in place,
// for a person watching a terminal: shown only when stderr is one (a log or
// a pipe gets none of it) and not asked to be --quiet. Redrawn at most five
// times a second, so the work pays almost nothing for it.
#pragma once

#include "jl/sim/simulation.h"

#include <chrono>
#include <functional>
#include <mutex>
#include <string>

namespace jl::cli {

class ProgressLine {
public:
    // Shown when `wanted` and stderr is a terminal.
    explicit ProgressLine(bool wanted);
    ~ProgressLine();
    ProgressLine(const ProgressLine&) = delete;
    ProgressLine& operator=(const ProgressLine&) = delete;

    bool shown() const { return shown_; }
    // A run at simulated time t of `until` (s): the time, the rate
    // (simulated seconds per second) and the time left at that rate.
    void simulated(double t, double until);
    // Cells of a map: done of total, and the time left at the rate so far.
    // Safe to call from several threads.
    void cells(int done, int total);
    // One line that stays, for a stage of work (the benchmark's studies):
    // "[done of total, elapsed] what".
    void stage(const std::string& what, int done, int total);
    // Clears the line (before other messages, and at the end).
    void clear();

private:
    bool due();
    void draw(const std::string& text);

    bool shown_ = false;
    std::chrono::steady_clock::time_point start_, last_;
    std::size_t width_ = 0;  // of the line drawn, to blank it
    std::mutex mutex_;
};

// What a recording asks between two steps (jl/sim/recording.h): whether
// the run was interrupted (interruption.h), the line drawn from `sim`'s time
// on the way, and once, after `command`, slowRunWarning's words if any.
std::function<int()> watchedRun(ProgressLine& line, const Simulation& sim, double until, const char* command);

// Why a run `wall` seconds in will take far longer than the time it
// simulates (over a minute more, and a hundred times the simulated time
// left), in words: where it is, what it would take, the step and the
// stiffest mode that sets it, and the integrator that copes; "" when it
// will not (or less than 3 s have passed to tell).
std::string slowRunWarning(const Simulation& sim, double until, double wall);

// "2 min 05 s", "41 s", "3 h 20 min": a duration as a person reads it.
std::string spokenDuration(double seconds);

}  // namespace jl::cli
