#include "jl/ladder/block_corners.h"

#include "jl/scene/ladder_blocks.h"

namespace jl {

Vec2 blockCorner(int i, int k, double thickness, double length) {
    const double side = (k & 2) ? thickness / 2 : -thickness / 2;
    const double end = (k & 1) ? length / 2 : -length / 2;
    return {side, i % 2 == 0 ? end : -end};
}

std::vector<std::array<Vec2, 4>> blockCorners(const LadderSpec& spec) {
    const std::vector<BlockSpec> blocks = ladderBlocks(spec);
    std::vector<std::array<Vec2, 4>> out(blocks.size());
    for (size_t i = 0; i < blocks.size(); ++i)
        for (int k = 0; k < 4; ++k) out[i][size_t(k)] = blockCorner(int(i), k, blocks[i].thickness, spec.block.length);
    return out;
}

}  // namespace jl
