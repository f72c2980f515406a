// The ribbons as the toy has them (docs/model.md section 8.8): drawn, never
// simulated. Between blocks j-1 and j three ribbons: the outer pair lies on
// one face of the upper block, wraps round its end at the hinge and crosses
// to the other face of the lower block; the middle ribbon does the same the
// other way. So every face of a block carries either the outer pair or the
// middle ribbon, alternating down the ladder, and a flip-flop, which moves
// the hinge to the blocks' other end, moves the wraps there too.
#include "jl/ladder/ladder.h"

#include <array>

namespace jl {

namespace {

// The face (a side, bit 1 of a corner) of the upper block j-1 that carries
// hinge j's outer pair: hinge 1's lies on block 0's side 1, the face the
// default camera sees, so the top block shows two ribbons (as the paper's
// figures do); it alternates with j, and so does the hinge's own side.
int outerFaceOfUpper(int j) { return (j % 2 == 1) ? 1 : 0; }

}  // namespace

std::vector<RibbonFrame> Ladder::ribbons(const World& w) const {
    const double lift = spec_.ribbons.thickness / 2;
    // Every block's corners, and each pushed out by the ribbon's half
    // thickness across both faces that meet there, so the ribbon lies on
    // the wood, not in it. Once per block: a frame of a long ladder is made
    // 60 times a simulated second, and a block's pose is not cheap to read.
    const size_t n = size_t(blockCount());
    std::vector<std::array<Vec2, 4>> corners(n), lifted(n);
    for (int i = 0; i < blockCount(); ++i) {
        const Pose pose = w.partPose(block(i));
        auto& c = corners[size_t(i)];
        for (int k = 0; k < 4; ++k) c[size_t(k)] = pose.apply(cornerLocal(i, k));
        for (size_t k = 0; k < 4; ++k) {
            const Vec2 across = (c[k] - c[k ^ 2]).normalized();
            const Vec2 along = (c[k] - c[k ^ 1]).normalized();
            lifted[size_t(i)][k] = Vec2(c[k] + (across + along) * lift);
        }
    }
    std::vector<RibbonFrame> out;
    out.reserve(2 * hinges_.size());
    for (int j = 1; j < blockCount(); ++j) {
        const Hinge& h = hinge(j);
        const int end = h.corner & 1;  // the hinge's end, the same number on both blocks
        const auto& upper = lifted[size_t(j - 1)];
        const auto& lower = lifted[size_t(j)];
        const Vec2 pin = corners[size_t(j - 1)][size_t(h.corner)];
        for (const bool central : {false, true}) {
            // On the upper block's face `a`, round its end at the hinge, to the lower block's other face.
            const int a = outerFaceOfUpper(j) ^ (central ? 1 : 0), b = a ^ 1;
            RibbonFrame r;
            r.central = central;
            r.visible = spec_.ribbons.visible && h.mode != HingeMode::Cut;
            r.points = {upper[size_t(2 * a + (end ^ 1))], upper[size_t(2 * a + end)], pin, lower[size_t(2 * b + end)],
                        lower[size_t(2 * b + (end ^ 1))]};
            out.push_back(r);
        }
    }
    return out;
}

}  // namespace jl
