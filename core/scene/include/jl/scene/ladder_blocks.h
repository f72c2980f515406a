// Each block of a ladder as the file makes it: the ladder's block with that
// block's overrides applied (docs/scene-format.md, `overrides`). The one
// statement of the rule, for the engine's ladder and the views alike.
#pragma once

#include "jl/scene/scene.h"

#include <vector>

namespace jl {

// Every block, in order. An override's size, density and colour replace the
// ladder's; its mass replaces the ladder's mass, and an override that gives
// a density but no mass lets the mass follow from that density. Overrides
// of blocks that do not exist are ignored. O(blocks + overrides).
std::vector<BlockSpec> ladderBlocks(const LadderSpec& ladder);

// The block's mass: the one given, or density x length x thickness x width.
double massOf(const BlockSpec& block);

}  // namespace jl
