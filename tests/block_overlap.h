// How deep blocks of a ladder are inside one another, from their corners
// (the tests of docs/model.md section 17: no two blocks overlap).
#pragma once

#include "jl/ladder/ladder.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace jl::test {

// How deep two boxes overlap (m), by separating axes: the least overlap of
// their projections on the four face normals, 0 if any axis separates them.
inline double overlap(const std::array<Vec2, 4>& a, double angleA, const std::array<Vec2, 4>& b, double angleB) {
    double least = std::numeric_limits<double>::infinity();
    for (double angle : {angleA, angleA + std::numbers::pi / 2, angleB, angleB + std::numbers::pi / 2}) {
        const Vec2 axis(std::cos(angle), std::sin(angle));
        double loA = 1e300, hiA = -1e300, loB = 1e300, hiB = -1e300;
        for (const Vec2& p : a) loA = std::min(loA, p.dot(axis)), hiA = std::max(hiA, p.dot(axis));
        for (const Vec2& p : b) loB = std::min(loB, p.dot(axis)), hiB = std::max(hiB, p.dot(axis));
        const double o = std::min(hiA, hiB) - std::max(loA, loB);
        if (o <= 0) return 0;
        least = std::min(least, o);
    }
    return least;
}

// How deep blocks i and j overlap (m).
inline double overlapOf(const Simulation& sim, int i, int j) {
    const Ladder& ladder = *sim.ladder();
    const World& w = sim.world();
    std::array<Vec2, 4> a, b;
    for (int k = 0; k < 4; ++k) a[size_t(k)] = ladder.cornerWorld(w, i, k), b[size_t(k)] = ladder.cornerWorld(w, j, k);
    return overlap(a, w.partPose(ladder.block(i)).angle, b, w.partPose(ladder.block(j)).angle);
}

// The deepest overlap of two blocks that are not neighbours, from their
// corners. Only pairs whose centres are within the largest block's diagonal
// can overlap: the others cost one distance each (a 100-block ladder has
// 4,851 pairs at every step).
inline double deepestOverlap(const Simulation& sim) {
    const Ladder& ladder = *sim.ladder();
    const World& w = sim.world();
    double reach = 0;
    for (int i = 0; i < ladder.blockCount(); ++i) reach = std::max(reach, 2 * ladder.cornerLocal(i, 3).norm());
    double deepest = 0;
    for (int i = 0; i < ladder.blockCount(); ++i) {
        const Vec2 a = w.partPose(ladder.block(i)).position;
        for (int j = i + 2; j < ladder.blockCount(); ++j)
            if ((w.partPose(ladder.block(j)).position - a).squaredNorm() < reach * reach)
                deepest = std::max(deepest, overlapOf(sim, i, j));
    }
    return deepest;
}

}  // namespace jl::test
