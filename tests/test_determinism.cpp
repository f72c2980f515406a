// labels: physics;engine
// The same scene and inputs give bit-identical states, whatever the caller's
// frame rate, after a snapshot and restore, and when a recorded drag replays.
#include "tests/scene_run.h"

#include <QtTest>

using namespace jl;
using namespace jl::test;

namespace {

const char* kClassic = "examples/classic.yaml";

std::uint64_t hashAfter(double until, double frame) {
    auto sim = simulateFile(kClassic);
    for (double t = frame; t < until; t += frame) sim->advanceTo(t);
    sim->advanceTo(until);
    return sim->stateHash();
}

}  // namespace

class DeterminismTest : public QObject {
    Q_OBJECT
private slots:
    void hashDoesNotDependOnFrameInterval() {
        const std::uint64_t once = hashAfter(1.2, 1.2);
        QCOMPARE(hashAfter(1.2, 1.0 / 60), once);
        QCOMPARE(hashAfter(1.2, 1.0 / 24), once);
        QCOMPARE(hashAfter(1.2, 0.0137), once);
    }

    void hashChangesWhenTheStateDoes() {
        QVERIFY(hashAfter(1.2, 0.1) != hashAfter(1.0, 0.1));
    }

    void restoreCarriesOnBitIdentically() {
        auto sim = simulateFile(kClassic);
        sim->advanceTo(0.55);  // mid-cascade
        const auto snap = sim->snapshot();
        sim->advanceTo(1.3);
        const std::uint64_t straight = sim->stateHash();
        sim->restore(*snap);
        sim->advanceTo(1.3);
        QCOMPARE(sim->stateHash(), straight);
    }

    // A drag during a run is recorded into the scene; running that scene
    // again replays it to the bit, and the drag did change the motion.
    void recordedDragReplaysBitIdentically() {
        auto live = simulateFile(kClassic);
        live->advanceTo(0.6);
        live->beginDrag(4, Vec2(0, 0.02), Vec2(0.1, -0.25));
        live->advanceTo(0.7);
        live->moveDrag(Vec2(0.15, -0.2));
        live->advanceTo(0.85);
        live->endDrag();
        live->advanceTo(1.4);
        QCOMPARE(int(live->scene().drags.size()), 1);
        QVERIFY(live->scene().drags[0].samples.size() == 2);

        auto replay = Simulation::build(live->scene()).simulation;
        QVERIFY(replay);
        replay->advanceTo(1.4);
        QCOMPARE(replay->stateHash(), live->stateHash());

        auto undisturbed = simulateFile(kClassic);
        undisturbed->advanceTo(1.4);
        QVERIFY(undisturbed->stateHash() != live->stateHash());
        const Vec2 a = undisturbed->frame().poses[4].position, b = live->frame().poses[4].position;
        QVERIFY2((a - b).norm() > 1e-3, qPrintable(QString::number((a - b).norm())));
    }

    // A drag while paused (no simulated time between press and release)
    // moves nothing: it leaves no record to replay or save, and the run
    // carries on exactly as if it had not happened.
    void aDragWhileNoTimePassesLeavesNothing() {
        auto sim = simulateFile(kClassic);
        sim->advanceTo(0.6);
        sim->beginDrag(4, Vec2(0, 0.02), Vec2(0.1, -0.25));
        sim->moveDrag(Vec2(0.15, -0.2));
        sim->endDrag();
        QVERIFY(sim->scene().drags.empty());
        QVERIFY(sim->world().drags().empty());
        sim->advanceTo(1.4);
        auto undisturbed = simulateFile(kClassic);
        undisturbed->advanceTo(0.6);
        undisturbed->advanceTo(1.4);
        QCOMPARE(sim->stateHash(), undisturbed->stateHash());
    }
};

QTEST_GUILESS_MAIN(DeterminismTest)
#include "test_determinism.moc"
