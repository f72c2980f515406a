// Which values a design axis may take: the scene file's. A map over values
// the loader refuses gives rows that look like answers (a 1 nm block,
// negative damping, a blocks count rounded without a word), so an axis is
// checked, value by value, before any cell runs.
#pragma once

#include "jl/design/design_axis.h"
#include "jl/scene/bound.h"

#include <cstddef>
#include <string>

namespace jl {

// The most values of one axis: a map a page can show (and a map's shares
// name no larger one).
inline constexpr std::size_t kMostAxisValues = 200;

// The range a parameter's value may take (SI): that of the scene file's
// field it sets (jl/scene/scene_fields.h, jl/scene/scene_ranges.h).
Bound parameterRange(DesignParameter p);

// How many values the axis gives, as a double (it may be huge); 0 when
// FROM > TO, STEP <= 0 or a bound is not finite.
double axisCount(const DesignAxis& a);

// Why `a` cannot be an axis of a map over `base`, or "" when it can: no
// values, more than `most`, a value outside the parameter's range (or not
// whole, for blocks), or a design the scene loader refuses (a held block
// past the end of a shorter ladder). Said of the axis as the user gave it.
std::string axisProblem(const Scene& base, const DesignAxis& a, std::size_t most);

}  // namespace jl
