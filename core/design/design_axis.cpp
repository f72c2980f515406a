#include "jl/design/design_axis.h"

#include "jl/base/decimal.h"
#include "jl/scene/scene_ranges.h"

#include <algorithm>
#include <cmath>

namespace jl {

const DesignParameterWord& describe(DesignParameter p) {
    for (const DesignParameterWord& w : kDesignParameters)
        if (w.value == p) return w;
    return kDesignParameters[0];
}

std::vector<double> axisValues(const DesignAxis& a) {
    std::vector<double> v;
    if (!(a.step > 0) || !(a.to >= a.from) || !std::isfinite(a.from) || !std::isfinite(a.to)) return v;
    const double count = std::floor((a.to - a.from) / a.step + 1e-9) + 1;
    if (count > 1e6) return v;
    // Each value is from + i step in decimals, rounded once: the number a
    // scene file holding that text reads (1 + 8 x 1 mm is 0.009 m, where
    // doubles give 0.009000000000000001).
    const auto from = shortestDecimal(a.from), step = shortestDecimal(a.step);
    for (int i = 0; i < int(count); ++i) {
        const auto exact = from && step ? steppedDecimal(*from, *step, i) : std::nullopt;
        v.push_back(exact ? nearestDouble(*exact) : a.from + i * a.step);
    }
    return v;
}

Scene withParameter(Scene s, DesignParameter p, double value) {
    if (!s.ladder) s.ladder = LadderSpec{};
    LadderSpec& l = *s.ladder;
    switch (p) {
        case DesignParameter::Blocks:
            // Clamped before rounding: lround of a value beyond a long (or of
            // a NaN) is unspecified.
            l.blocks =
                std::isnan(value)
                    ? range::kFewestBlocks
                    : int(std::lround(std::clamp(value, double(range::kFewestBlocks), double(range::kMostBlocks))));
            break;
        case DesignParameter::Thickness:
            l.block.thickness = value;
            break;
        case DesignParameter::Length:
            l.block.length = value;
            break;
        case DesignParameter::Width:
            l.block.width = value;
            break;
        case DesignParameter::Density:
            l.block.density = value;
            break;
        case DesignParameter::HingeDamping:
            l.hinges.damping = value;
            break;
        case DesignParameter::TurnDuration:
            for (ScriptAction& a : s.script)
                if (a.kind == ScriptAction::Kind::Turn) a.duration = value;
            break;
    }
    return s;
}

double parameterValue(const Scene& s, DesignParameter p) {
    const double none = std::nan("");
    if (!s.ladder) return none;
    const LadderSpec& l = *s.ladder;
    switch (p) {
        case DesignParameter::Blocks:
            return l.blocks;
        case DesignParameter::Thickness:
            return l.block.thickness;
        case DesignParameter::Length:
            return l.block.length;
        case DesignParameter::Width:
            return l.block.width;
        case DesignParameter::Density:
            return l.block.density;
        case DesignParameter::HingeDamping:
            return l.hinges.damping;
        case DesignParameter::TurnDuration:
            for (const ScriptAction& a : s.script)
                if (a.kind == ScriptAction::Kind::Turn) return a.duration;
            return none;
    }
    return none;
}

}  // namespace jl
