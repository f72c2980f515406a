#include "jl/scene/ladder_blocks.h"

namespace jl {

std::vector<BlockSpec> ladderBlocks(const LadderSpec& ladder) {
    std::vector<BlockSpec> blocks(size_t(ladder.blocks > 0 ? ladder.blocks : 0), ladder.block);
    std::vector<bool> massGiven(blocks.size(), false);
    for (const BlockOverride& o : ladder.overrides) {
        if (o.index < 0 || o.index >= int(blocks.size())) continue;
        BlockSpec& b = blocks[size_t(o.index)];
        if (o.thickness) b.thickness = *o.thickness;
        if (o.width) b.width = *o.width;
        if (o.density) b.density = *o.density;
        if (o.color) b.color = *o.color;
        if (o.mass) {
            b.mass = o.mass;
            massGiven[size_t(o.index)] = true;
        } else if (o.density && !massGiven[size_t(o.index)]) {
            b.mass.reset();
        }
    }
    return blocks;
}

double massOf(const BlockSpec& block) {
    return block.mass.value_or(block.density * block.length * block.thickness * block.width);
}

}  // namespace jl
