#include "jl/design/design_check.h"

#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_io.h"
#include "jl/scene/scene_ranges.h"

#include <cmath>

namespace jl {

namespace {

// The range of the field of `numbers` stored at `member`: the table is the
// one place a range is written.
template <class Section, std::size_t N>
Bound fieldRange(const NumberField<Section> (&numbers)[N], double Section::*member) {
    for (const NumberField<Section>& n : numbers)
        if (n.member == typename NumberField<Section>::Member(member)) return n.range;
    return Bound::any();
}

std::string withUnit(DesignParameter p, double v) {
    // Appended piece by piece: GCC 12's -Wrestrict misreads " " + std::string.
    std::string text = formatNumber(v);
    if (const std::string_view unit = describe(p).unit; !unit.empty()) {
        text += ' ';
        text += unit;
    }
    return text;
}

// Why one value is not one a scene file may hold, or "".
std::string valueProblem(DesignParameter p, double v) {
    const std::string label(describe(p).label);
    if (p == DesignParameter::Blocks) {
        const std::string allowed =
            "a whole number from " + std::to_string(range::kFewestBlocks) + " to " + std::to_string(range::kMostBlocks);
        if (v != std::floor(v) || !parameterRange(p).contains(v))
            return label + " " + formatNumber(v) + " is not allowed: the scene format takes " + allowed;
        return {};
    }
    if (parameterRange(p).contains(v)) return {};
    const std::string_view unit = describe(p).unit;
    return label + " " + withUnit(p, v) + " is out of range: the scene format takes " + parameterRange(p).describe() +
           (unit.empty() ? "" : " (" + std::string(unit) + ")");
}

// Why the loader refuses the design with value `v`, or "": the scene is
// written as a file and read back, so every check of a scene file applies.
std::string loaderProblem(const Scene& base, DesignParameter p, double v) {
    const SceneLoad load = parseScene(sceneToYaml(withParameter(base, p, v)), "design");
    if (load.scene) return {};
    const std::string why = load.errors.empty() ? "it is not a valid scene" : load.errors.front().message;
    return "with " + std::string(describe(p).label) + " " + withUnit(p, v) + " the scene is not valid: " + why;
}

}  // namespace

Bound parameterRange(DesignParameter p) {
    switch (p) {
        case DesignParameter::Blocks:
            return Bound::closed(range::kFewestBlocks, range::kMostBlocks);
        case DesignParameter::Thickness:
            return fieldRange(kBlockNumbers, &BlockSpec::thickness);
        case DesignParameter::Length:
            return fieldRange(kBlockNumbers, &BlockSpec::length);
        case DesignParameter::Width:
            return fieldRange(kBlockNumbers, &BlockSpec::width);
        case DesignParameter::Density:
            return fieldRange(kBlockNumbers, &BlockSpec::density);
        case DesignParameter::HingeDamping:
            return fieldRange(kHingeNumbers, &HingeOptions::damping);
        case DesignParameter::TurnDuration:
            return range::actionDuration;  // a script's turn, as the reader checks it
    }
    return Bound::any();
}

double axisCount(const DesignAxis& a) {
    if (!(a.step > 0) || !(a.to >= a.from) || !std::isfinite(a.from) || !std::isfinite(a.to)) return 0;
    return std::floor((a.to - a.from) / a.step + 1e-9) + 1;
}

std::string axisProblem(const Scene& base, const DesignAxis& a, std::size_t most) {
    const double count = axisCount(a);
    if (count < 1) return "gives no values: FROM must be at most TO, and STEP more than 0";
    if (count > double(most))
        return "gives " + formatNumber(count) + " values, more than the " + std::to_string(most) +
               " a map may have: give a larger STEP or a shorter range";
    const std::vector<double> values = axisValues(a);
    for (const double v : values)
        if (std::string why = valueProblem(a.parameter, v); !why.empty()) return why;
    // The loader's other checks (held blocks, overrides, the script's
    // blocks) bind at the ends of an axis: the fewest blocks, the largest.
    for (const double v : {values.front(), values.back()})
        if (std::string why = loaderProblem(base, a.parameter, v); !why.empty()) return why;
    return {};
}

}  // namespace jl
