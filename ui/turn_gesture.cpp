#include "ui/turn_gesture.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jl::ui {

namespace {
constexpr double kQuarter = std::numbers::pi / 2;
double bearing(const Vec2& from, const Vec2& to) { return std::atan2(to.y() - from.y(), to.x() - from.x()); }
}  // namespace

TurnGesture::TurnGesture(int block, const Vec2& centre, const Vec2& point)
    : block_(block), centre_(centre), last_(bearing(centre, point)) {}

// The bearing's step, taken the short way round: a sweep of several turns
// adds up, as the hand moved.
void TurnGesture::moveTo(const Vec2& point) {
    const double now = bearing(centre_, point);
    swept_ += std::remainder(now - last_, 2 * std::numbers::pi);
    last_ = now;
}

double TurnGesture::snapped(double angle) { return kQuarter * std::round(angle / kQuarter); }

std::optional<Turn> TurnGesture::turn(double seconds) const {
    const double angle = snapped(swept_);
    if (angle == 0) return std::nullopt;
    // At the speed the hand swept: the snapped angle in the time the hand
    // would have taken to sweep it.
    const double duration = std::clamp(seconds * std::abs(angle / swept_), kShortest, kLongest);
    return Turn{block_, angle, duration};
}

}  // namespace jl::ui
