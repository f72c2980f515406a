// How much a scene file may ask for before it is refused outright: the
// loader and the readers of each section check these before allocating.
#pragma once

#include "jl/scene/scene_ranges.h"

#include <cstddef>

namespace jl {

// The largest scene the program itself writes, 100,000 blocks each with
// its own size, colour and pose, is a 14 MiB file of 1.5 million values; it
// takes 7 s and 0.9 GB of memory to read on a 2-core machine. The caps leave
// room above that and stop anything far beyond it before it costs much.
struct LoadLimits {
    int maxBlocks = range::kMostBlocks;      // ladder.blocks
    std::size_t maxFileBytes = 24u << 20;    // 24 MiB
    std::size_t maxNodes = 2'000'000;        // YAML values in the file (about 0.5 kB of memory each while read)
    std::size_t maxLineBytes = 1u << 20;     // 1 MiB: no line the writer makes comes near
    std::size_t maxScalarBytes = 64u << 10;  // 64 KiB: the longest value, a description, is at most 20,000 characters
    std::size_t maxErrors = 500;             // problems listed before giving up
};

// Text fields: a title fits a window's title bar and a list; a description
// is a lesson's worth of paragraphs.
inline constexpr std::size_t kMostTitleCharacters = 200;
inline constexpr std::size_t kMostDescriptionCharacters = 20'000;
inline constexpr std::size_t kMostNameCharacters = 200;  // a body's or particle's name

}  // namespace jl
