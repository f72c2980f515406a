// labels: physics
// The broad phase of contact between blocks (docs/model.md section 17.5)
// against the plain answer, every pair of blocks tested: the grid, the still
// tail left out of the search and its segments entering the grid only near
// the moving blocks, and the pairs kept from one search to the next until a
// block has moved by half the skin, must find exactly the pairs whose
// bounding circles overlap, neither more nor fewer.
#include "jl/ladder/block_contact.h"
#include "jl/ladder/ladder.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <numbers>

using namespace jl;
using namespace jl::test;

namespace {

// Every pair (i, j), j > i + 1, whose circles (half diagonals about the
// centres) overlap, in different bodies, not both held and not both in the
// still tail.
std::vector<std::pair<int, int>> everyPair(const World& w, const Ladder& ladder) {
    std::vector<std::pair<int, int>> out;
    const int n = ladder.blockCount(), still = ladder.stillFrom();
    for (int i = 0; i < n; ++i)
        for (int j = i + 2; j < n; ++j) {
            if (i >= still && j >= still) continue;
            const int bi = w.part(ladder.block(i)).body, bj = w.part(ladder.block(j)).body;
            if (bi == bj || (w.body(bi).kinematic && w.body(bj).kinematic)) continue;
            const double r = ladder.cornerLocal(i, 3).norm() + ladder.cornerLocal(j, 3).norm();
            const Vec2 d = w.partPose(ladder.block(i)).position - w.partPose(ladder.block(j)).position;
            if (d.squaredNorm() < r * r) out.emplace_back(i, j);
        }
    return out;
}

// Runs `scene` to `until` and compares the broad phase with every pair
// after every `every`-th step; returns how many pairs were compared (-1 if
// they differ, or if `tail` and the ladder never had a still tail).
int compareAlong(const std::string& file, int blocks, double until, int every, bool tail = true) {
    SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/" + file);
    if (!load.scene) return -1;
    load.scene->ladder->blocks = blocks;
    load.scene->solver.blockContact = BlockContact::On;
    auto sim = std::move(Simulation::build(*load.scene).simulation);
    if (!sim) return -1;
    BlockPairs broad;
    std::vector<std::pair<int, int>> found;
    int compared = 0, steps = 0, tails = 0;
    while (sim->time() < until && sim->stepOnce()) {
        if (++steps % every) continue;
        const Ladder& ladder = *sim->ladder();
        broad.find(sim->world(), ladder, found);
        const std::vector<std::pair<int, int>> expected = everyPair(sim->world(), ladder);
        if (found != expected) {
            qWarning("%s, %d blocks, t = %.6f s: %zu pairs found, %zu expected", file.c_str(), blocks, sim->time(),
                     found.size(), expected.size());
            return -1;
        }
        compared += int(found.size());
        tails += ladder.stillFrom() < ladder.blockCount();
    }
    qInfo("%s, %d blocks: %d pairs compared over %d steps (%d with a still tail)", file.c_str(), blocks, compared,
          steps, tails);
    return sim->failure().empty() && (tails > 0 || !tail) ? compared : -1;
}

// The distances of a box's four corners to the face planes of another
// (faces -x, +x, -y, +y of its frame, > 0 outside), as the refresh reads
// them: boxes of half sizes `half`, centred at `a` and `b`, turned by
// angles `ta` and `tb`.
std::array<std::array<double, 4>, 4> cornersBeyond(const Vec2& a, double ta, const Vec2& b, double tb,
                                                   const Vec2& half) {
    std::array<std::array<double, 4>, 4> out;
    const Vec2 signs[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int k = 0; k < 4; ++k) {
        const Vec2 corner = a + rotate(ta, Vec2(signs[k].cwiseProduct(half)));
        const Vec2 l = rotate(-tb, Vec2(corner - b));
        out[size_t(k)] = {-l.x() - half.x(), l.x() - half.x(), -l.y() - half.y(), l.y() - half.y()};
    }
    return out;
}

BlockPairs::CornerDistances both(const Vec2& a, double ta, const Vec2& b, double tb, const Vec2& half) {
    return {cornersBeyond(a, ta, b, tb, half), cornersBeyond(b, tb, a, ta, half)};
}

}  // namespace

class BlockPairsTest : public QObject {
    Q_OBJECT

private slots:
    // The long ladder's 200 blocks fold on themselves after 2.6 s (two
    // strikes with contact on): pairs between moving blocks and with the
    // top of the still tail. At every step, so that the pairs kept between
    // searches are checked at every call (a run searches at about one step
    // in ten); and every fifth, where more has moved between calls.
    void theLongLadderAgreesWithEveryPair() {
        QVERIFY(compareAlong("examples/long-ladder.yaml", 200, 3.0, 1) > 0);
        QVERIFY(compareAlong("examples/long-ladder.yaml", 200, 3.0, 5) > 0);
    }

    // Up to 16 blocks (the moving ones and the still tail's near them) are
    // compared pair by pair, without the grid: the wrong-way turn's 6
    // blocks wedged against the hand, and the two ripples' 12.
    void aFewBlocksAgreeWithEveryPair() {
        QVERIFY(compareAlong("examples/wrong-way.yaml", 6, 2.5, 1, false) > 0);
        QVERIFY(compareAlong("examples/two-ripples.yaml", 12, 4.0, 1, false) > 0);
    }

    // The classic turn with 1,000 blocks for 3 s: a long still tail in
    // segments of 16, 16, 32, ... blocks, parted from the top as the ripple
    // goes down. No two blocks come near (every pair tested finds none), and
    // neither may the grid.
    void aThousandBlocksFindNoPairWhereNoneOverlap() {
        QCOMPARE(compareAlong("examples/classic.yaml", 1000, 3.0, 25), 0);
    }

    // A pair whose circles overlap has its corners watched unless the two
    // boxes are apart along one of their four axes by more than a distance.
    // Blocks 60 x 12 mm, worked by hand: side by side 0.5 mm apart; crossed
    // in an X; one turned 45 deg with its long face 1 mm from the other's
    // corner, apart only along the turned block's own axis (neither box
    // lies beyond a face plane of the upright one).
    void boxesApartAlongAnAxisAreToldFromOverlappingOnes() {
        const Vec2 half(0.006, 0.03);
        const auto sideBySide = both({0, 0}, 0, {0.0125, 0}, 0, half);
        QVERIFY(BlockPairs::apart(sideBySide, 6e-8));
        QVERIFY(BlockPairs::apart(sideBySide, 0.4999e-3));
        QVERIFY(!BlockPairs::apart(sideBySide, 0.5001e-3));
        QVERIFY(!BlockPairs::apart(both({0, 0}, 0, {0, 0}, std::numbers::pi / 2, half), 6e-8));
        const double quarter = std::numbers::pi / 4;
        const Vec2 u(std::cos(quarter), std::sin(quarter));
        const Vec2 corner(0.006, 0.03);
        const auto turned = both(corner + (0.006 + 0.001) * u, quarter, {0, 0}, 0, half);
        for (size_t f = 0; f < 4; ++f) {  // the upright box's planes do not separate them
            bool allBeyond = true;
            for (size_t k = 0; k < 4; ++k) allBeyond = allBeyond && turned[0][k][f] > 0;
            QVERIFY(!allBeyond);
        }
        QVERIFY(BlockPairs::apart(turned, 0.9999e-3));
        QVERIFY(!BlockPairs::apart(turned, 1.0001e-3));
    }
};

QTEST_GUILESS_MAIN(BlockPairsTest)
#include "test_block_pairs.moc"
