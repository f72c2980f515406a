#include "ui/view3d/spring_coil.h"

#include <algorithm>

namespace jl::ui {

std::vector<jl::Vec2> springCoil(const jl::Vec2& a, const jl::Vec2& b) {
    constexpr int kCoilTurns = 8;
    constexpr double kLead = 0.15;  // of the length, straight at each end
    const jl::Vec2 along = b - a;
    const double length = along.norm();
    if (!(length > 0)) return {a, b};
    const double width = std::clamp(0.2 * length, 0.004, 0.012);
    const jl::Vec2 across = jl::perp(along / length) * (width / 2);
    std::vector<jl::Vec2> points{a, a + kLead * along};
    for (int k = 0; k < 2 * kCoilTurns; ++k) {
        const double s = kLead + (1 - 2 * kLead) * (k + 0.5) / (2 * kCoilTurns);
        points.push_back(a + s * along + (k % 2 ? -across : across));
    }
    points.push_back(b - kLead * along);
    points.push_back(b);
    return points;
}

}  // namespace jl::ui
