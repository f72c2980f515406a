#include "ui/edit/turn_gesture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jl::ui {

namespace {
constexpr double kQuarter = std::numbers::pi / 2;
constexpr double kStill = 1e-3;  // rad: a step smaller is the hand's tremor, not a sweep
double bearing(const Vec2& from, const Vec2& to) { return std::atan2(to.y() - from.y(), to.x() - from.x()); }
}  // namespace

TurnGesture::TurnGesture(int block, const Vec2& centre, const Vec2& point)
    : block_(block), centre_(centre), last_(bearing(centre, point)) {}

// The bearing's step, taken the short way round: a sweep of several turns
// adds up, as the hand moved.
void TurnGesture::moveTo(const Vec2& point, double seconds) {
    const double now = bearing(centre_, point);
    const double step = std::remainder(now - last_, 2 * std::numbers::pi);
    swept_ += step;
    last_ = now;
    if (std::abs(step) > kStill) {
        if (sweepFrom_ < 0) sweepFrom_ = lastAt_;
        sweepTo_ = seconds;
    }
    lastAt_ = seconds;
}

double TurnGesture::snapped(double angle) { return kQuarter * std::round(angle / kQuarter); }

std::optional<Turn> TurnGesture::turn() const {
    const double angle = snapped(swept_);
    if (angle == 0) return std::nullopt;
    // At the speed the hand swept: the snapped angle in the time the hand
    // would have taken to sweep it.
    const double seconds = sweepFrom_ < 0 ? 0.0 : sweepTo_ - sweepFrom_;
    const double duration = std::clamp(seconds * std::abs(angle / swept_), kShortest, kLongest);
    return Turn{block_, angle, duration};
}

}  // namespace jl::ui
