// The broad phase of contact between blocks: which pairs are near enough to
// test corner by corner (docs/model.md section 17.5).
#include "jl/ladder/block_contact.h"
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <cmath>

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

// Each block's bounding circle (its half diagonal about its centre) goes
// into the grid cell of its centre, the cells as wide as the widest circle
// is across: two circles that overlap have their centres in the same or
// neighbouring cells. One pass to fill the grid and one over each block's
// nine cells, O(N) for N blocks.
void BlockPairs::find(const World& w, const Ladder& ladder, std::vector<std::pair<int, int>>& out) {
    out.clear();
    const int n = ladder.blockCount();
    if (n < 3) return;
    double reach = 0;
    for (int i = 0; i < n; ++i) reach = std::max(reach, ladder.cornerLocal(i, 3).norm());
    const double cell = 2 * reach;
    size_t buckets = 1;
    while (buckets < 2 * size_t(n)) buckets *= 2;
    const size_t mask = buckets - 1;
    head_.assign(buckets, -1);
    next_.resize(size_t(n));
    key_.resize(size_t(n));
    std::vector<Vec2>& centre = centre_;
    centre.resize(size_t(n));
    for (int i = 0; i < n; ++i) {
        centre[size_t(i)] = w.partPose(ladder.block(i)).position;
        const long long ix = std::llround(std::floor(centre[size_t(i)].x() / cell));
        const long long iy = std::llround(std::floor(centre[size_t(i)].y() / cell));
        key_[size_t(i)] = cellKey(ix, iy);
        const size_t b = bucketOf(key_[size_t(i)], mask);
        next_[size_t(i)] = head_[b];
        head_[b] = i;
    }
    const int still = ladder.stillFrom();
    for (int i = 0; i < n; ++i) {
        const Vec2& c = centre[size_t(i)];
        const long long ix = std::llround(std::floor(c.x() / cell)), iy = std::llround(std::floor(c.y() / cell));
        const int bodyI = w.part(ladder.block(i)).body;
        const bool kinematicI = w.body(bodyI).kinematic;
        const double ri = ladder.cornerLocal(i, 3).norm();
        for (long long dx = -1; dx <= 1; ++dx)
            for (long long dy = -1; dy <= 1; ++dy) {
                const long long key = cellKey(ix + dx, iy + dy);
                for (int j = head_[bucketOf(key, mask)]; j >= 0; j = next_[size_t(j)]) {
                    if (j <= i + 1 || key_[size_t(j)] != key)
                        continue;                            // each pair once; neighbours meet at their hinge
                    if (i >= still && j >= still) continue;  // the still tail does not move within itself
                    const int bodyJ = w.part(ladder.block(j)).body;
                    if (bodyJ == bodyI || (kinematicI && w.body(bodyJ).kinematic)) continue;
                    const double rj = ladder.cornerLocal(j, 3).norm();
                    if ((centre[size_t(j)] - c).squaredNorm() < (ri + rj) * (ri + rj)) out.emplace_back(i, j);
                }
            }
    }
    std::sort(out.begin(), out.end());  // the same order whatever the hashing: the same events in the same order
}

}  // namespace jl
