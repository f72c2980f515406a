// The broad phase of contact between blocks: which pairs are near enough to
// test corner by corner (docs/model.md section 17.5).
#include "jl/base/heap_bytes.h"
#include "jl/ladder/block_contact.h"
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <utility>

namespace jl {

namespace {

// A cell of the grid, as one number (cells are far fewer than 2^31 a side
// for any ladder that fits in memory).
long long cellKey(long long ix, long long iy) { return (ix << 32) ^ (iy & 0xffffffffll); }

size_t bucketOf(long long key, size_t mask) {
    const unsigned long long h = static_cast<unsigned long long>(key) * 0x9e3779b97f4a7c15ull;
    return size_t(h >> 17) & mask;
}

}  // namespace

// The still tail's segments (docs/model.md section 3.7): each a run of
// blocks of one body, with the box of their centres in that body's frame.
// Built again when the tail changes (it only ever shrinks from the top).
// A wake parts only the top segment or two, so a segment is found whole from
// its body's part count and its box taken from the last listing when the
// same run of blocks was the same body then: O(segments + blocks woken) a wake,
// where reading every block of the tail was 3 % of a 100,000-block turn.
void BlockPairs::listSegments(const World& w, const Ladder& ladder, int still) {
    const std::vector<Segment> before = std::exchange(segments_, {});
    segmentsFor_ = still;
    kept_ = false;
    const int n = ladder.blockCount();
    size_t old = 0;  // the listing before, in the order of its blocks
    for (int j = still; j < n;) {
        Segment s;
        s.body = w.part(ladder.block(j)).body;
        s.first = j;
        // The body's blocks, if it is the run from j that its part count
        // says; else block by block.
        const int count = int(w.body(s.body).parts.size());
        const bool whole = count > 1 && j + count <= n && w.part(ladder.block(j + count - 1)).body == s.body &&
                           (j + count == n || w.part(ladder.block(j + count)).body != s.body);
        s.end = whole ? j + count : j + 1;
        if (!whole)
            while (s.end < n && w.part(ladder.block(s.end)).body == s.body) ++s.end;
        while (old < before.size() && before[old].first < s.first) ++old;
        // A body that a wake did not touch keeps its index and frame
        // (World::regroup remakes only the bodies it is given).
        if (old < before.size() && before[old].first == s.first && before[old].end == s.end &&
            before[old].body == s.body) {
            s.lo = before[old].lo, s.hi = before[old].hi;
        } else {
            s.lo = Vec2::Constant(1e300), s.hi = Vec2::Constant(-1e300);
            for (int k = s.first; k < s.end; ++k) {
                const Vec2& local = w.part(ladder.block(k)).inBody.position;  // its centre in the body's frame
                s.lo = s.lo.cwiseMin(local), s.hi = s.hi.cwiseMax(local);
            }
        }
        segments_.push_back(s);
        j = s.end;
    }
}

// Each moving block's bounding circle (its half diagonal about its centre),
// widened by a skin, goes into the grid cell of its centre, the cells as
// wide as the widest widened circle is across: two circles that overlap
// have their centres in the same or neighbouring cells. The still tail's
// blocks do not move relative to each other, so none of its pairs is
// tested; its blocks go into the grid only from the segments whose box of
// centres comes within a cell of the moving blocks' (a handful of bodies
// however long the ladder). Each pair is found from its lower block, a
// moving one. O(moving blocks + segments) per search.
//
// The pairs whose widened circles overlap are kept, with the centres they
// were found at, until a block has moved by half the skin (a list of
// neighbours with a skin, as molecular dynamics keeps them): until then
// every pair whose circles overlap now is among them, and each call only
// tests those few again at the centres of now: the same pairs as a search
// at every call, in the same order, while most calls only read the centres.
void BlockPairs::find(const World& w, const Ladder& ladder, std::vector<std::pair<int, int>>& out) {
    out.clear();
    const int n = ladder.blockCount();
    if (n < 3) return;
    if (reachFor_ != n) {  // the blocks' sizes are the ladder's, fixed for a run
        radius_.resize(size_t(n));
        for (int i = 0; i < n; ++i) radius_[size_t(i)] = ladder.cornerLocal(i, 3).norm();
        reach_ = *std::max_element(radius_.begin(), radius_.end());
        reachFor_ = n;
        kept_ = false;
    }
    const int moving = std::min(n, ladder.stillFrom());
    if (moving < n &&
        (segmentsFor_ != moving || segments_.empty() || segments_.front().body != w.part(ladder.block(moving)).body))
        listSegments(w, ladder, moving);
    if (moving == n && !segments_.empty()) {  // the whole tail has woken
        segments_.clear();
        kept_ = false;
    }
    if (!(kept_ && keptFor_ == moving && stillNear(w, ladder))) search(w, ladder, moving);
    if (!kept_) {  // a few blocks: compared pair by pair, nothing kept
        comparePairwise(w, ladder, moving, out);
        return;
    }
    for (const auto& [i, j] : near_) {
        const int bodyI = w.part(ladder.block(i)).body, bodyJ = w.part(ladder.block(j)).body;
        if (bodyI == bodyJ || (w.body(bodyI).kinematic && w.body(bodyJ).kinematic)) continue;
        const double reach = radius_[size_t(i)] + radius_[size_t(j)];
        if ((centre_[size_t(j)] - centre_[size_t(i)]).squaredNorm() < reach * reach) out.emplace_back(i, j);
    }
}

// Whether the kept pairs still hold every pair that can overlap: no block
// of the search has moved by half the skin since (two blocks closing by
// less than the skin), nor any segment of the still tail left out of it.
// Reads the centres of now into centre_ as it goes.
bool BlockPairs::stillNear(const World& w, const Ladder& ladder) {
    const double half = 0.5 * skin();
    for (int i : members_) {
        centre_[size_t(i)] = w.partPose(ladder.block(i)).position;
        if ((centre_[size_t(i)] - foundAt_[size_t(i)]).squaredNorm() > half * half) return false;
    }
    for (const Segment& s : segments_) {
        if (s.searched) continue;
        const Pose now = w.bodyPose(s.body);
        const double arm =
            std::max({s.lo.norm(), s.hi.norm(), Vec2(s.lo.x(), s.hi.y()).norm(), Vec2(s.hi.x(), s.lo.y()).norm()});
        const double turned = std::abs(std::remainder(now.angle - s.foundAt.angle, 2 * std::numbers::pi));
        if ((now.position - s.foundAt.position).norm() + turned * arm > half) return false;
    }
    return true;
}

// The search: the members (moving blocks, and the blocks of the tail's
// segments within a cell of them) and their centres; with more than a few,
// the pairs whose widened circles overlap, kept.
void BlockPairs::search(const World& w, const Ladder& ladder, int moving) {
    const double cell = 2 * reach_ + skin();
    const int n = ladder.blockCount();
    members_.clear();
    Vec2 lo = Vec2::Constant(1e300), hi = Vec2::Constant(-1e300);
    centre_.resize(size_t(n));
    for (int i = 0; i < moving; ++i) {
        centre_[size_t(i)] = w.partPose(ladder.block(i)).position;
        lo = lo.cwiseMin(centre_[size_t(i)]), hi = hi.cwiseMax(centre_[size_t(i)]);
        members_.push_back(i);
    }
    lo.array() -= cell, hi.array() += cell;
    for (Segment& s : segments_) {
        const Pose body = w.bodyPose(s.body);
        s.foundAt = body;
        Vec2 slo = Vec2::Constant(1e300), shi = Vec2::Constant(-1e300);
        for (const Vec2& c : {s.lo, s.hi, Vec2(s.lo.x(), s.hi.y()), Vec2(s.hi.x(), s.lo.y())}) {
            const Vec2 p = body.apply(c);
            slo = slo.cwiseMin(p), shi = shi.cwiseMax(p);
        }
        s.searched = !((slo.array() > hi.array()).any() || (shi.array() < lo.array()).any());
        if (!s.searched) continue;
        for (int j = s.first; j < s.end; ++j) {
            centre_[size_t(j)] = w.partPose(ladder.block(j)).position;
            members_.push_back(j);
        }
    }
    keptFor_ = moving;
    kept_ = members_.size() > kDirect;
    if (!kept_) return;
    foundAt_.resize(size_t(n));
    for (int i : members_) foundAt_[size_t(i)] = centre_[size_t(i)];
    size_t buckets = 1;
    while (buckets < 2 * members_.size()) buckets *= 2;
    const size_t mask = buckets - 1;
    head_.assign(buckets, -1);
    next_.resize(size_t(n));
    key_.resize(size_t(n));
    for (int i : members_) {
        const long long ix = std::llround(std::floor(centre_[size_t(i)].x() / cell));
        const long long iy = std::llround(std::floor(centre_[size_t(i)].y() / cell));
        key_[size_t(i)] = cellKey(ix, iy);
        const size_t b = bucketOf(key_[size_t(i)], mask);
        next_[size_t(i)] = head_[b];
        head_[b] = i;
    }
    // Which pairs are one body, or both held, is asked at each call: a lock
    // or an unlock between searches changes it.
    near_.clear();
    for (int i = 0; i < moving; ++i) {
        const Vec2& c = centre_[size_t(i)];
        const long long ix = std::llround(std::floor(c.x() / cell)), iy = std::llround(std::floor(c.y() / cell));
        const double ri = radius_[size_t(i)] + 0.5 * skin();
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy) {
                const long long key = cellKey(ix + dx, iy + dy);
                for (int j = head_[bucketOf(key, mask)]; j >= 0; j = next_[size_t(j)]) {
                    if (j <= i + 1 || key_[size_t(j)] != key)
                        continue;  // each pair once; neighbours meet at their hinge
                    const double reach = ri + radius_[size_t(j)] + 0.5 * skin();
                    if ((centre_[size_t(j)] - c).squaredNorm() < reach * reach) near_.emplace_back(i, j);
                }
            }
    }
    std::sort(near_.begin(), near_.end());  // the same order whatever the hashing: the same events in the same order
}

// A few blocks: every pair's circles compared directly, the same pairs as
// the grid finds at a fraction of its cost (the examples' ladders of 4 to 12
// blocks). The members are in the order of their blocks, so the pairs come
// out sorted.
void BlockPairs::comparePairwise(const World& w, const Ladder& ladder, int moving,
                                 std::vector<std::pair<int, int>>& out) const {
    struct Near {
        int block, body;
        bool kinematic;
    };
    std::array<Near, kDirect> near;
    const size_t count = members_.size();
    for (size_t a = 0; a < count; ++a) {
        const int body = w.part(ladder.block(members_[a])).body;
        near[a] = {members_[a], body, w.body(body).kinematic};
    }
    for (size_t a = 0; a < count && near[a].block < moving; ++a) {
        const Near& p = near[a];
        const Vec2& c = centre_[size_t(p.block)];
        const double r = radius_[size_t(p.block)];
        for (size_t b = a + 1; b < count; ++b) {
            const Near& q = near[b];
            if (q.block == p.block + 1 || q.body == p.body || (p.kinematic && q.kinematic)) continue;
            const double reach = r + radius_[size_t(q.block)];
            if ((centre_[size_t(q.block)] - c).squaredNorm() < reach * reach) out.emplace_back(p.block, q.block);
        }
    }
}

bool BlockPairs::apart(const CornerDistances& beyond, double by) {
    for (const auto& corners : beyond)
        for (size_t f = 0; f < 4; ++f)
            if (corners[0][f] > by && corners[1][f] > by && corners[2][f] > by && corners[3][f] > by) return true;
    return false;
}

std::size_t BlockPairs::heapBytes() const {
    using jl::heapBytes;
    return heapBytes(head_) + heapBytes(next_) + heapBytes(members_) + heapBytes(key_) + heapBytes(centre_) +
           heapBytes(foundAt_) + heapBytes(near_) + heapBytes(radius_) + heapBytes(segments_);
}

}  // namespace jl
