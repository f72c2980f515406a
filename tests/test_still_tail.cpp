// labels: physics;ladder
// The still tail (docs/model.md section 3.7): the blocks of a long ladder
// that the motion has not reached hang as a few rigid segments. Checked
// against a known answer (a ladder lifted straight up moves as one) and
// against the full model, in which every block is its own body from the
// start: the same motion to far below any integrator's error, the same
// events, balanced books, and bit-identical replays of drags and pushes.
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <string>

using namespace jl;
using namespace jl::test;

namespace {

// A ladder of `blocks` default blocks (60 x 12 mm), hanging at rest, with
// the script and solver lines given.
std::string ladderScene(int blocks, const std::string& script, const std::string& solver = "",
                        const std::string& extra = "") {
    return "format: jacobs-ladder/1\n"
           "ladder: {blocks: " +
           std::to_string(blocks) + "}\n" + extra + (script.empty() ? "" : "script:\n" + script) +
           (solver.empty() ? "" : "solver: {" + solver + "}\n");
}

const std::string kTurn = "  - {at: 0, turn: {block: 0, by: 180deg, duration: 0.3}}\n";
// Where the tail of a ladder at rest begins: below the hand's block 0, with
// a wake's worth of blocks to spare.
constexpr int kFirstStill = Ladder::kWakeBlocks + 1;
// The shortest ladder with a tail: the spare blocks and the shortest tail.
constexpr int kShortestWithTail = kFirstStill + Ladder::kLeastStillTail;

std::unique_ptr<Simulation> withTail(const std::string& yaml, bool joined) {
    std::string text = yaml;
    const std::string word = joined ? "joined" : "separate";
    const auto solver = text.find("solver: {");
    if (solver == std::string::npos)
        text += "solver: {still_tail: " + word + "}\n";
    else
        text.insert(solver + 9, "still_tail: " + word + ", ");
    return simulate(text);
}

double largestDistance(const Frame& a, const Frame& b) {
    double d = 0;
    for (size_t i = 0; i < a.poses.size(); ++i) d = std::max(d, (a.poses[i].position - b.poses[i].position).norm());
    return d;
}

}  // namespace

class StillTailTest : public QObject {
    Q_OBJECT
private slots:
    // A known answer: a chain hanging from a point that moves straight up
    // keeps its equilibrium shape (the effective gravity changes in size, not
    // in direction), so every block moves as the hand does and no hinge turns.
    // The tail is never woken, and the blocks end where the lift puts them.
    void aLadderLiftedStraightUpMovesAsOneAndStaysJoined() {
        const double lift = 0.05;
        auto sim = simulate(ladderScene(300, "  - {at: 0, move: {block: 0, by: [0, 0.05], duration: 0.3}}\n"));
        QVERIFY(sim);
        const Frame start = sim->frame();
        QCOMPARE(start.solver.stillFrom, kFirstStill);
        QVERIFY(start.solver.bodies < kFirstStill + 10);  // the blocks above the tail and a few segments
        double worst = 0;
        for (double t = 0.05; t <= 0.5001; t += 0.05) {
            QVERIFY(sim->advanceExactlyTo(t));
            const Frame f = sim->frame();
            QCOMPARE(f.solver.stillFrom, kFirstStill);
            const double s = std::min(t / 0.3, 1.0);
            const double dy = lift * (1 - std::cos(M_PI * s)) / 2;
            for (size_t i = 0; i < f.poses.size(); ++i) {
                const Vec2 expected = start.poses[i].position + Vec2(0, dy);
                worst = std::max(worst, (f.poses[i].position - expected).norm());
                QVERIFY(std::abs(f.poses[i].angle - start.poses[i].angle) < 1e-9);
            }
        }
        QVERIFY2(worst < 1e-9, qPrintable(QString("worst distance from the lifted equilibrium %1 m").arg(worst)));
    }

    // The segments are as docs/model.md section 3.7 says: 16, 16, 32, 64,
    // ... blocks from the tail's top, the last one taking a remnant shorter
    // than a wake. 300 blocks at rest: blocks 1-16 move (16 bodies), the
    // tail 17-299 is 16, 16, 32, 64, 128 and 27 blocks (6 bodies). The
    // sizes came out 16, 32, 64, 128, 43 (5 bodies) before.
    void theTailIsCutIntoTheDocumentedSegments() {
        auto sim = simulate(ladderScene(300, ""));
        QVERIFY(sim);
        const Frame start = sim->frame();
        QCOMPARE(start.solver.stillFrom, kFirstStill);
        QCOMPARE(start.solver.bodies, (kFirstStill - 1) + 6);
    }

    // The turned ladder of the benchmark, RK4 at the engine's step: with the
    // tail and without, the same steps, the same events and block centres
    // within 1e-9 m (the tail wakes at 1e-9 block lengths of strain; every
    // integrator's error here is 1e-7 m or more). At 2,000 blocks the
    // engine's step is below its 1 ms cap, set by the pin forces: after a
    // wake it must come from the pins there are then.
    // Dormand-Prince's error control counts a body once for each of its
    // blocks: it asks the same of a step with the tail as without. Its events
    // are located to 1e-12 s: at the default 1e-9 s, rounding alone (a
    // cosine one unit in the last place off) moved the fold of hinge 1 by
    // 8e-10 s within that tolerance, and the blocks, swinging at metres a
    // second, by 5e-9 m: the root finder's tolerance, not the tail's.
    void aTurnedLadderMovesAsInTheFullModel_data() {
        QTest::addColumn<int>("blocks");
        QTest::addColumn<double>("until");
        QTest::addColumn<QString>("solver");
        QTest::newRow("300 blocks, RK4") << 300 << 0.6 << "";
        QTest::newRow("2,000 blocks, RK4") << 2000 << 0.3 << "";
        QTest::newRow("300 blocks, Dormand-Prince")
            << 300 << 0.6 << "integrator: dormand_prince45, tolerance: 1e-7, event_tolerance: 1e-12";
        // Long steps (Verner at 1e-4 takes 281 for the turn, about 1 ms
        // each, where the motion's front moves a block or more): one wake per
        // step keeps up, and the hinges between the tail's segments, which
        // are not watched, do not turn.
        QTest::newRow("5,000 blocks, Verner") << 5000 << 0.3 << "integrator: verner65, tolerance: 1e-4";
    }
    void aTurnedLadderMovesAsInTheFullModel() {
        QFETCH(int, blocks);
        QFETCH(double, until);
        QFETCH(QString, solver);
        const bool adaptive = !solver.isEmpty();
        const std::string scene = ladderScene(blocks, kTurn, solver.toStdString());
        auto joined = withTail(scene, true), full = withTail(scene, false);
        QVERIFY(joined && full);
        QCOMPARE(full->frame().solver.stillFrom, -1);
        int firstStill = joined->frame().solver.stillFrom;
        QVERIFY(firstStill > 0);
        std::vector<Event> a, b;
        double worst = 0, turned = 0;
        const Frame start = joined->frame();
        for (double t = 0.05; t <= until + 1e-9; t += 0.05) {
            QVERIFY(joined->advanceExactlyTo(t) && full->advanceExactlyTo(t));
            const Frame fa = joined->frame(), fb = full->frame();
            // Every hinge of the tail, its segments' own and those between
            // them: how far it has turned since the start (rad), from the
            // blocks' poses. The wake's threshold is 1e-9 of a turn.
            for (int j = fa.solver.stillFrom + 1; fa.solver.stillFrom > 0 && j < blocks; ++j) {
                const auto relative = [j](const Frame& f) {
                    return f.poses[size_t(j)].angle - f.poses[size_t(j - 1)].angle;
                };
                turned = std::max(turned, std::abs(relative(fa) - relative(start)));
            }
            for (const Event& e : fa.events)
                if (e.hinge > 0) a.push_back(e);
            for (const Event& e : fb.events)
                if (e.hinge > 0) b.push_back(e);
            worst = std::max(worst, largestDistance(fa, fb));
            // The pin forces of a segment and of its blocks one by one differ
            // in rounding, and so may the step chosen from them, in rounding;
            // an error estimate may tip a step's acceptance either way.
            if (adaptive) {
                QVERIFY2(std::abs(double(fa.solver.steps - fb.solver.steps)) <= 1 + 0.01 * double(fb.solver.steps),
                         qPrintable(QString("%1 steps against %2").arg(fa.solver.steps).arg(fb.solver.steps)));
            } else {
                QCOMPARE(fa.solver.steps, fb.solver.steps);
                QVERIFY2(
                    std::abs(fa.solver.largestStep - fb.solver.largestStep) <= 1e-9 * fb.solver.largestStep,
                    qPrintable(QString("%1 s against %2 s").arg(fa.solver.largestStep).arg(fb.solver.largestStep)));
            }
            QCOMPARE(fa.solver.stepHalvings, 0);
            QVERIFY(fa.solver.stillFrom == -1 || fa.solver.stillFrom >= firstStill);  // it only wakes
            firstStill = fa.solver.stillFrom;
            // The books as the full model keeps them (RK4's own imbalance at
            // the engine's step reaches 4 mJ of the hand's 3.5 J after the
            // whip that follows the hand's stop: the integrator's, in both),
            // to 1e-9 J or to what rounding leaves of the books' largest
            // term: a 2,000-block ladder's potential energy is some -23 kJ,
            // summed over its blocks (or its segments) and its steps, and
            // 1e-13 of it is 2.3e-9 J. An adaptive step's imbalance is its
            // own (Verner at 1e-4: 2.5e-5 J on 5,000 blocks), and two runs
            // whose steps differ in rounding book it to 1e-3 of itself.
            const double own = adaptive ? 1e-3 * std::abs(fb.energy.balance()) : 0.0;
            const double books = std::max({1e-9, 1e-13 * std::abs(fb.energy.potential), own});
            QVERIFY2(std::abs(fa.energy.balance() - fb.energy.balance()) < books,
                     qPrintable(QString("%1 J against %2 J (potential energy %3 J)")
                                    .arg(fa.energy.balance())
                                    .arg(fb.energy.balance())
                                    .arg(fb.energy.potential)));
        }
        QVERIFY2(worst < 1e-9, qPrintable(QString("largest distance %1 m").arg(worst)));
        QVERIFY2(turned < 1e-9, qPrintable(QString("a hinge of the tail turned %1 rad").arg(turned)));
        qInfo("largest distance %.3g m, largest turn of a tail's hinge %.3g rad", worst, turned);
        QVERIFY(a.size() >= 2);  // the fold and the flip of hinge 1
        QCOMPARE(a.size(), b.size());
        for (size_t i = 0; i < a.size(); ++i) {
            QCOMPARE(a[i].kind, b[i].kind);
            QCOMPARE(a[i].hinge, b[i].hinge);
            QVERIFY(std::abs(a[i].time - b[i].time) < 1e-9);
        }
        const int woken = joined->frame().solver.stillFrom;
        QVERIFY2(woken > 60 && woken < blocks, qPrintable(QString("tail from block %1 at the end").arg(woken)));
    }

    // A push deep in the tail, a hold, a cut: each wakes what it touches
    // first, and the motion is the full model's.
    void whatTheScriptTouchesMovesOnItsOwn() {
        const std::string pushAndHold =
            ladderScene(240,
                        "  - {at: 0.05, push: {block: 150, impulse: [0.002, 0], point: [0, 0.02]}}\n"
                        "  - {at: 0.1, hold: {block: 190}}\n");
        const std::string cut = ladderScene(240, "  - {at: 0.05, cut: {hinge: 100}}\n");
        for (const bool cutting : {false, true}) {
            const std::string& scene = cutting ? cut : pushAndHold;
            auto joined = withTail(scene, true), full = withTail(scene, false);
            QVERIFY(joined && full);
            QCOMPARE(joined->frame().solver.stillFrom, kFirstStill);
            QVERIFY(joined->advanceExactlyTo(0.06));
            QVERIFY(joined->frame().solver.stillFrom > (cutting ? 100 : 150));
            QVERIFY(joined->advanceExactlyTo(0.3) && full->advanceExactlyTo(0.3));
            const Frame fa = joined->frame(), fb = full->frame();
            QVERIFY2(largestDistance(fa, fb) < 1e-9, qPrintable(QString::number(largestDistance(fa, fb))));
            QVERIFY(std::abs(fa.energy.balance() - fb.energy.balance()) < 1e-12);
            if (cutting) {
                QCOMPARE(fa.hinges[99].mode, HingeMode::Cut);
            } else {
                QVERIFY(fa.solver.stillFrom == -1 || fa.solver.stillFrom > 190 + Ladder::kWakeBlocks - 1);
                QVERIFY(fa.held[190]);
            }
        }
    }

    // A block the script grabs at t = 0 is not swallowed by the tail: 300
    // blocks, none held, block 150 turned from t = 0. The tail used to
    // start at block 33, the hand turning the segment that held block 150
    // rigidly (5.4 cm from the full model at 0.05 s); it now starts below
    // block 150 and the motion is the full model's.
    void aBlockGrabbedAtTheStartIsNotInTheTail() {
        const std::string scene =
            "format: jacobs-ladder/1\n"
            "ladder: {blocks: 300, held: []}\n"
            "script:\n"
            "  - {at: 0, turn: {block: 150, by: 90deg, duration: 0.3}}\n";
        auto joined = withTail(scene, true), full = withTail(scene, false);
        QVERIFY(joined && full);
        QVERIFY(joined->frame().solver.stillFrom > 150);
        QVERIFY(joined->advanceExactlyTo(0.05) && full->advanceExactlyTo(0.05));
        const double d = largestDistance(joined->frame(), full->frame());
        QVERIFY2(d < 1e-9, qPrintable(QString("%1 m from the full model").arg(d)));
    }

    // A drag of a still block wakes it at the moment the drag begins, which
    // a replay of the recorded scene meets at the same moment: bit for bit.
    void aDragOfAStillBlockReplaysBitForBit() {
        auto sim = simulate(ladderScene(200, kTurn));
        QVERIFY(sim && sim->frame().solver.stillFrom == kFirstStill);
        sim->advanceTo(0.1);
        sim->beginDrag(120, Vec2(0, 0.02), sim->frame().poses[120].position + Vec2(0.01, 0.02));
        QVERIFY(sim->frame().solver.stillFrom > 120);
        sim->advanceTo(0.2);
        sim->moveDrag(sim->frame().poses[120].position + Vec2(0.03, 0));
        sim->advanceTo(0.3);
        sim->endDrag();
        sim->advanceTo(0.45);
        const std::uint64_t live = sim->stateHash();
        auto replay = Simulation::build(sim->scene()).simulation;
        QVERIFY(replay);
        replay->advanceTo(0.45);
        QCOMPARE(replay->stateHash(), live);
        // And a snapshot taken with the tail still joined carries on the same.
        auto again = simulate(ladderScene(200, kTurn));
        again->advanceTo(0.2);
        const auto snap = again->snapshot();
        again->advanceTo(0.5);
        const std::uint64_t straight = again->stateHash();
        again->restore(*snap);
        again->advanceTo(0.5);
        QCOMPARE(again->stateHash(), straight);
    }

    // Where a still tail would be wrong or would not pay, there is none: a
    // short ladder, air drag (each block would be slowed by its own speed),
    // welded rigid pairs (a tail of welds is no fewer unknowns), no gravity.
    void noTailWhereItWouldBeWrongOrWouldNotPay() {
        QCOMPARE(simulate(ladderScene(kShortestWithTail - 1, kTurn))->frame().solver.stillFrom, -1);
        QCOMPARE(simulate(ladderScene(kShortestWithTail, kTurn))->frame().solver.stillFrom, kFirstStill);
        QCOMPARE(simulate(ladderScene(300, kTurn, "", "damping: {linear: 0.001}\n"))->frame().solver.stillFrom, -1);
        QCOMPARE(simulate(ladderScene(300, kTurn, "rigid_pairs: weld"))->frame().solver.stillFrom, -1);
        QCOMPARE(simulate(ladderScene(300, kTurn, "", "gravity: [0, 0]\n"))->frame().solver.stillFrom, -1);
        QCOMPARE(simulate(ladderScene(300, kTurn, "still_tail: separate"))->frame().solver.stillFrom, -1);
        // A ladder not at rest (fold angles away from the hanging ones)
        // moves everywhere: nothing is still.
        std::string folded = "format: jacobs-ladder/1\nladder:\n  blocks: 100\n  initial:\n    fold_angles: [";
        for (int j = 1; j < 100; ++j) folded += std::string(j > 1 ? ", " : "") + "0.5";
        folded += "]\n";
        auto moving = simulate(folded);
        QVERIFY(moving);
        QCOMPARE(moving->frame().solver.stillFrom, -1);
    }

    // The tail's hinges are not watched for events, and the blocks a wake
    // frees carry their fold angles on from where they hung.
    void wokenHingesCarryOnFromTheirRestingAngles() {
        auto sim = simulate(ladderScene(400, kTurn));
        const Frame start = sim->frame();
        QVERIFY(sim->advanceExactlyTo(0.3));
        const Frame f = sim->frame();
        QVERIFY(f.solver.stillFrom > kFirstStill);
        for (int j = f.solver.stillFrom + 1; j < 400; ++j)
            QCOMPARE(f.hinges[size_t(j - 1)].foldAngle, start.hinges[size_t(j - 1)].foldAngle);
    }
};

QTEST_GUILESS_MAIN(StillTailTest)
#include "test_still_tail.moc"
