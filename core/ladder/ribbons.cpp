// The ribbons as the toy has them (docs/model.md section 8.8): drawn, never
// simulated. Between blocks j-1 and j three ribbons: the outer pair lies on
// one face of the upper block, wraps round its end at the hinge and crosses
// to the other face of the lower block; the middle ribbon does the same the
// other way. So every face of a block carries either the outer pair or the
// middle ribbon, alternating down the ladder, and a flip-flop, which moves
// the hinge to the blocks' other end, moves the wraps there too.
#include "jl/ladder/block_corners.h"
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace jl {

namespace {

// The face (a side, bit 1 of a corner) of the upper block j-1 that carries
// hinge j's outer pair: hinge 1's lies on block 0's side 1, the face the
// default camera sees, so the top block shows two ribbons (as the paper's
// figures do); it alternates with j, and so does the hinge's own side.
int outerFaceOfUpper(int j) { return (j % 2 == 1) ? 1 : 0; }

// The ribbons of `n` blocks: block i at pose(i), thickness(i) thick;
// hinge j (1 .. n-1) at its corner with its mode, from hinge(j) as a
// {corner, mode} pair. Each block's corners are made once, from one sine
// and cosine, as the hinge loop reaches it, and each pushed out by the
// ribbon's half thickness across both faces that meet there, so the
// ribbon lies on the wood, not in it.
template <typename PoseOf, typename ThicknessOf, typename HingeOf>
std::vector<RibbonFrame> ribbonsOf(const LadderSpec& spec, int n, PoseOf pose, ThicknessOf thickness, HingeOf hinge) {
    const double lift = spec.ribbons.thickness / 2;
    struct Corners {
        std::array<Vec2, 4> at, lifted;
    };
    const auto cornersOf = [&](int i) {
        const Pose p = pose(i);
        const double c = std::cos(p.angle), s = std::sin(p.angle);
        Corners k;
        for (size_t j = 0; j < 4; ++j) {
            const Vec2 local = blockCorner(i, int(j), thickness(i), spec.block.length);
            k.at[j] = p.position + Vec2(c * local.x() - s * local.y(), s * local.x() + c * local.y());
        }
        for (size_t j = 0; j < 4; ++j) {
            const Vec2 across = (k.at[j] - k.at[j ^ 2]).normalized();
            const Vec2 along = (k.at[j] - k.at[j ^ 1]).normalized();
            k.lifted[j] = Vec2(k.at[j] + (across + along) * lift);
        }
        return k;
    };
    std::vector<RibbonFrame> out;
    if (n <= 0) return out;
    out.reserve(2 * size_t(n - 1));
    Corners lower = cornersOf(0);
    for (int j = 1; j < n; ++j) {
        const Corners upper = lower;  // block j - 1's, made for the hinge above
        lower = cornersOf(j);
        const auto [corner, mode] = hinge(j);
        const int end = corner & 1;  // the hinge's end, the same number on both blocks
        for (const bool central : {false, true}) {
            // On the upper block's face `a`, round its end at the hinge, to the lower block's other face.
            const int a = outerFaceOfUpper(j) ^ (central ? 1 : 0), b = a ^ 1;
            RibbonFrame r;
            r.central = central;
            r.visible = spec.ribbons.visible && mode != HingeMode::Cut;
            r.points = {upper.lifted[size_t(2 * a + (end ^ 1))], upper.lifted[size_t(2 * a + end)],
                        upper.at[size_t(corner)], lower.lifted[size_t(2 * b + end)],
                        lower.lifted[size_t(2 * b + (end ^ 1))]};
            out.push_back(r);
        }
    }
    return out;
}

}  // namespace

std::vector<RibbonFrame> Ladder::ribbons(const World& w) const {
    return ribbonsOf(
        spec_, blockCount(), [&](int i) { return w.partPose(block(i)); }, [&](int i) { return thickness_[size_t(i)]; },
        [&](int j) { return std::pair(hinge(j).corner, hinge(j).mode); });
}

std::vector<RibbonFrame> ladderRibbons(const LadderSpec& spec, std::span<const BlockSpec> blocks,
                                       std::span<const Pose> poses, std::span<const HingeFrame> hinges) {
    const int n = int(std::min({blocks.size(), poses.size(), hinges.size() + 1}));
    return ribbonsOf(
        spec, n, [&](int i) { return poses[size_t(i)]; }, [&](int i) { return blocks[size_t(i)].thickness; },
        [&](int j) { return std::pair(hinges[size_t(j - 1)].corner, hinges[size_t(j - 1)].mode); });
}

}  // namespace jl
