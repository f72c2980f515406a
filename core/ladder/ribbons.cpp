// The ribbons as the toy has them (docs/model.md section 8.8): drawn, never
// simulated. Between blocks j-1 and j three ribbons: the outer pair lies on
// one face of the upper block, wraps round its end at the hinge and crosses
// to the other face of the lower block; the middle ribbon does the same the
// other way. So every face of a block carries either the outer pair or the
// middle ribbon, alternating down the ladder, and a flip-flop, which moves
// the hinge to the blocks' other end, moves the wraps there too.
#include "jl/ladder/ladder.h"

namespace jl {

namespace {

// The face (a side, bit 1 of a corner) of the upper block j-1 that carries
// hinge j's outer pair: hinge 1's lies on block 0's side 1, the face the
// default camera sees, so the top block shows two ribbons (as the paper's
// figures do); it alternates with j, and so does the hinge's own side.
int outerFaceOfUpper(int j) { return (j % 2 == 1) ? 1 : 0; }

}  // namespace

std::vector<RibbonFrame> Ladder::ribbons(const World& w) const {
    std::vector<RibbonFrame> out;
    out.reserve(2 * hinges_.size());
    const double lift = spec_.ribbons.thickness / 2;
    // Corner c of block i, pushed out by the ribbon's half thickness across
    // both faces that meet there, so the ribbon lies on the wood, not in it.
    const auto onCorner = [&](int i, int c) {
        const Vec2 corner = cornerWorld(w, i, c);
        const Vec2 across = (corner - cornerWorld(w, i, c ^ 2)).normalized();
        const Vec2 along = (corner - cornerWorld(w, i, c ^ 1)).normalized();
        return Vec2(corner + (across + along) * lift);
    };
    for (int j = 1; j < blockCount(); ++j) {
        const Hinge& h = hinge(j);
        const int end = h.corner & 1;  // the hinge's end, the same number on both blocks
        const int upper = j - 1, lower = j;
        const Vec2 pin = cornerWorld(w, upper, h.corner);
        for (const bool central : {false, true}) {
            // On the upper block's face `a`, round its end at the hinge, to the lower block's other face.
            const int a = outerFaceOfUpper(j) ^ (central ? 1 : 0), b = a ^ 1;
            RibbonFrame r;
            r.central = central;
            r.visible = spec_.ribbons.visible && h.mode != HingeMode::Cut;
            r.points = {onCorner(upper, 2 * a + (end ^ 1)), onCorner(upper, 2 * a + end), pin,
                        onCorner(lower, 2 * b + end), onCorner(lower, 2 * b + (end ^ 1))};
            out.push_back(std::move(r));
        }
    }
    return out;
}

}  // namespace jl
