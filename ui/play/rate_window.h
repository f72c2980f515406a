// The real-time factor as the status bar says it: simulated time gained per
// wall-clock second over the last few seconds of playing, from samples of
// (wall time, time on screen, solver steps) taken as the run goes.
#pragma once

#include <deque>
#include <optional>

namespace jl::ui {

class RateWindow {
public:
    static constexpr double kSpan = 2.0;  // s of wall time the rates are taken over
    // Readings over less than this much wall time are no rate yet (a frame
    // or two, just after Play, would say anything).
    static constexpr double kShortest = 0.25;  // s

    // Playing stopped, or the time on screen jumped (a seek, a load): the
    // samples before do not belong to the same stretch of playing.
    void restart() { samples_.clear(); }
    // Wall time in s (any fixed origin), simulated time on screen in s, steps so far.
    void add(double wall, double simulated, double steps);

    // Per wall second over the last kSpan s (or since the restart, when
    // that is shorter), the window's start read between the two samples
    // around it; none over less than kShortest s.
    std::optional<double> simulatedPerSecond() const;
    std::optional<double> stepsPerSecond() const;
    double span() const;  // s of wall time the rates cover

private:
    struct Sample {
        double wall, simulated, steps;
    };
    // The state at the window's start, read on the line between the two
    // samples around it.
    Sample start() const;
    std::deque<Sample> samples_;  // in time order; the first at or before the window's start
};

}  // namespace jl::ui
