// "Model only what a scene needs" (docs/model.md section 16.2): the same
// cascades with locked and folded pairs merged into one body, and kept as
// two bodies held by a pin and a weld, side by side in cost and error.
#pragma once

#include "bench/cases.h"

namespace jl::bench {

// Rows of study "models": method names the model (merged on the chain
// solver, merged on the sparse solver, welded); the note gives the mean
// unknowns (body coordinates and constraint rows) over the run. Each case
// starts with a row of study "<case>_tight": the welded model against the
// merged one, both at tolerance 1e-12 (how far apart the models themselves are).
std::vector<BenchRow> rigidPairModelStudy(const BenchPlan& plan);

}  // namespace jl::bench
