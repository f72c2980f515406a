// How much a scene file may ask for before it is refused outright: the
// loader and the readers of each section check these before allocating.
#pragma once

#include "jl/scene/scene_ranges.h"

#include <cstddef>

namespace jl {

struct LoadLimits {
    int maxBlocks = range::kMostBlocks;      // ladder.blocks
    std::size_t maxFileBytes = 64u << 20;    // 64 MiB
    std::size_t maxNodes = 2'000'000;        // YAML values in the file (a tree costs ~0.3 kB each)
    std::size_t maxErrors = 500;             // problems listed before giving up
};

}  // namespace jl
