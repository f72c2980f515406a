// A design question asks about a range of ladders: one parameter of the
// design (the number of blocks, their thickness, ...) stepped over a range.
// An axis gives the values; withParameter makes the scene of one of them.
#pragma once

#include "jl/scene/scene.h"

#include <string_view>
#include <vector>

namespace jl {

enum class DesignParameter { Blocks, Thickness, Length, Width, Density, HingeDamping, TurnDuration };

// Their words on the command line and in files, with the SI unit of values.
struct DesignParameterWord {
    std::string_view word;
    DesignParameter value;
    std::string_view label;
    std::string_view unit;  // SI; empty for a count
};
inline constexpr DesignParameterWord kDesignParameters[] = {
    {"blocks", DesignParameter::Blocks, "blocks", ""},
    {"thickness", DesignParameter::Thickness, "block thickness", "m"},
    {"length", DesignParameter::Length, "block length", "m"},
    {"width", DesignParameter::Width, "block width", "m"},
    {"density", DesignParameter::Density, "density", "kg/m^3"},
    {"hinge_damping", DesignParameter::HingeDamping, "hinge damping", "N m s"},
    {"turn_duration", DesignParameter::TurnDuration, "turn duration", "s"},
};
const DesignParameterWord& describe(DesignParameter p);

struct DesignAxis {
    DesignParameter parameter = DesignParameter::Blocks;
    double from = 4, to = 12, step = 2;  // SI; from <= to, step > 0
    bool operator==(const DesignAxis&) const = default;
};

// from, from + step, ... up to `to` (within rounding), each computed from
// its index so that long axes do not drift, in decimals (jl/base/decimal.h):
// the value a scene file holding from + i step as text has. Empty for a bad
// axis.
std::vector<double> axisValues(const DesignAxis& a);

// The scene with one parameter set (the blocks count rounded and kept within
// range::kFewestBlocks..kMostBlocks, a NaN taken as the fewest; a turn
// duration given to every scripted turn).
Scene withParameter(Scene s, DesignParameter p, double value);
// The parameter's value in a scene (SI): what withParameter sets. NaN when
// the scene has none (no ladder; no scripted turn for the turn duration).
double parameterValue(const Scene& s, DesignParameter p);

}  // namespace jl
