// Which face of another block a corner stands against, and which it goes
// in through (docs/model.md section 17.1): the blocks placed in the world,
// a point against a box, and the face records kept between refreshes.
#include "block_contact_lengths.h"
#include "jl/ladder/block_contact.h"
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <cmath>

namespace jl {

using namespace block_contact;

BlockContacts::Placed BlockContacts::placed(const World& w, const Ladder& ladder, int block, Need need) {
    Placed out;
    out.pose = w.partPose(ladder.block(block));
    out.half = ladder.cornerLocal(block, 3).cwiseAbs();
    // As rotate() and Pose::apply work them out, to the last bit. The
    // rotation back uses the same cosine and sine: cos and sin are even and
    // odd to the last bit (as libm computes them from |angle|).
    const double c = std::cos(out.pose.angle), s = std::sin(out.pose.angle);
    if (need != Need::Box)
        for (int k = 0; k < 4; ++k) {
            const Vec2 l = ladder.cornerLocal(block, k);
            out.corner[size_t(k)] = out.pose.position + Vec2(c * l.x() - s * l.y(), s * l.x() + c * l.y());
        }
    if (need != Need::Corners) out.backCos = c, out.backSin = -s;
    return out;
}

CornerAgainstBox BlockContacts::nearestFace(const std::array<double, 4>& d) {
    CornerAgainstBox out{d[0], 0};
    for (int f = 1; f < 4; ++f)
        if (d[f] > out.gap) out = {d[f], f};
    return out;
}

CornerAgainstBox BlockContacts::pointAgainst(const Vec2& p, const Placed& box, double flush, int through) {
    const std::array<double, 4> d = box.beyond(box.local(p));
    if (through < 0) return nearestFace(d);
    CornerAgainstBox out{d[through], through};
    for (int f = 0; f < 4; ++f)
        if (f != through && d[f] - flush > out.gap) out = {d[f] - flush, f};
    return out;
}

CornerAgainstBox BlockContacts::cornerAgainst(const World& w, const Ladder& ladder, int block, int corner, int other,
                                              int through) {
    return pointAgainst(ladder.cornerWorld(w, block, corner), placed(w, ladder, other, Need::Box),
                        kFlush * ladder.length(), through);
}

CornerAgainstBox BlockContacts::against(const World& w, const Ladder& ladder, int block, int corner, int other,
                                        int through) const {
    if (other != kFloor) return cornerAgainst(w, ladder, block, corner, other, through);
    return {ladder.cornerWorld(w, block, corner).y() - *floor_, 3};
}

std::ptrdiff_t BlockContacts::throughOf(const std::array<int, 3>& id) const {
    const auto seen = std::lower_bound(through_.begin(), through_.end(), std::pair{id, 0},
                                       [](const auto& x, const auto& y) { return x.first < y.first; });
    return seen != through_.end() && seen->first == id ? seen - through_.begin() : -1;
}

void BlockContacts::keepThrough(const std::array<int, 3>& id, int face) {
    if (const std::ptrdiff_t i = throughOf(id); i >= 0) through_[size_t(i)].second = face;
}

int BlockContacts::throughFace(const Ladder& ladder, const CornerAgainstBox& plain, int block, int corner,
                               int other) const {
    if (plain.gap > kFlush * ladder.length()) return plain.face;
    const std::ptrdiff_t i = throughOf({block, corner, other});
    return i >= 0 ? through_[size_t(i)].second : plain.face;
}

// The face corner `corner` of `block` goes into block `other` through.
// It is the one cornerAgainst finds with the face the corner came through,
// unless the two boxes overlap clearly less along the other axis of
// block `other` and the corner lies within that overlap of the face across
// it. Two blocks side by side with their ends flush, one turned a hair
// about the corners that meet: the far corner of each slides along the
// other's end plane into its side, never clearly past the end, and a
// contact on the end (which the pins already hold) could not stop the
// sides sinking into each other. The least overlap of the boxes, their
// separating axis, is the face that does. A corner where a hinge joins
// its block to a neighbour keeps the face it came through: in the
// wrong-way turn's wedge against the hand, a push there, on a side, closes
// a loop of pins that the hand drives (pushes of 4e10 N), and the books
// miss 1.5e-4 J in the next step (docs/model.md section 17.7).
int BlockContacts::entryFace(const World& w, const Ladder& ladder, int block, int corner, int other,
                             int through) const {
    if (other == kFloor) return 3;
    const Placed box = placed(w, ladder, other, Need::Box);
    const Placed mine = placed(w, ladder, block, Need::Corners);
    const Vec2& p = mine.corner[size_t(corner)];
    const int first = pointAgainst(p, box, kFlush * ladder.length(), through).face;
    for (int j : {block, block + 1})
        if (j >= 1 && j < ladder.blockCount() && ladder.hinge(j).mode != HingeMode::Cut &&
            ladder.hinge(j).corner == corner)
            return first;
    const Vec2 at = box.local(p);
    const std::array<double, 4> d = box.beyond(at);
    Vec2 lo = at, hi = at;
    for (const Vec2& q : mine.corner) lo = lo.cwiseMin(box.local(q)), hi = hi.cwiseMax(box.local(q));
    const Vec2 overlap = hi.cwiseMin(box.half) - lo.cwiseMax(-box.half);
    const double band = kTouchBand * ladder.length();
    int best = first;
    for (int f = 0; f < 4; ++f) {
        const double o = overlap[f < 2 ? 0 : 1];
        if (o < overlap[best < 2 ? 0 : 1] - band && d[f] >= -(o + band) && d[f] <= band) best = f;
    }
    return best;
}

}  // namespace jl
