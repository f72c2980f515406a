#include "ui/play/rate_window.h"

#include <algorithm>

namespace jl::ui {

void RateWindow::add(double wall, double simulated, double steps) {
    if (!samples_.empty() && wall <= samples_.back().wall) return;
    samples_.push_back({wall, simulated, steps});
    // One sample at or before the window's start stays, to read it from.
    while (samples_.size() > 2 && samples_[1].wall <= wall - kSpan) samples_.pop_front();
}

RateWindow::Sample RateWindow::start() const {
    const Sample& a = samples_.front();
    const double from = samples_.back().wall - kSpan;
    if (samples_.size() < 2 || a.wall >= from) return a;
    const Sample& b = samples_[1];
    const double f = (from - a.wall) / (b.wall - a.wall);
    return {from, a.simulated + f * (b.simulated - a.simulated), a.steps + f * (b.steps - a.steps)};
}

double RateWindow::span() const { return samples_.empty() ? 0 : samples_.back().wall - start().wall; }

std::optional<double> RateWindow::simulatedPerSecond() const {
    if (span() < kShortest) return std::nullopt;
    return std::max(0.0, samples_.back().simulated - start().simulated) / span();
}

std::optional<double> RateWindow::stepsPerSecond() const {
    if (span() < kShortest) return std::nullopt;
    return std::max(0.0, samples_.back().steps - start().steps) / span();
}

}  // namespace jl::ui
