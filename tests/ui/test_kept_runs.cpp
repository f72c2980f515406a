// labels: ui
// The runs a push in the past replaced, kept for Undo: found by their
// drags, one per list of drags, and the oldest let go when they hold more
// history than the budget allows (the newest always kept).
#include "ui/play/kept_runs.h"
#include "ui_test_support.h"

#include <QtTest>

using namespace jl::ui;

namespace {

// A run of the swinging ladder with `drags` recorded drags (of block 1)
// and `frames` frames on record.
KeptRun runWith(int drags, int frames) {
    jl::Scene scene = jl::test::swingingLadder();
    for (int i = 0; i < drags; ++i) {
        jl::DragRecord d;
        d.block = 1;
        d.end = 0.1 * (i + 1);
        d.samples.push_back({0.1 * i, {0.0, -0.1}});
        scene.drags.push_back(d);
    }
    KeptRun run;
    run.sim = jl::Simulation::build(scene).simulation;
    if (!run.sim) qFatal("the test scene does not build");
    run.recorded = std::make_shared<const jl::Scene>(scene);
    run.history.reset(scene.solver.frameInterval, std::size_t(1) << 30);
    for (int i = 0; i < frames; ++i)
        run.history.append(std::make_shared<const jl::Frame>(run.sim->frame()), run.sim->snapshot(), i);
    return run;
}

}  // namespace

class KeptRunsTest : public QObject {
    Q_OBJECT
private slots:
    void aRunIsFoundByItsDragsAndTakenOut() {
        KeptRuns kept;
        kept.keep(runWith(0, 3), std::size_t(1) << 30);
        kept.keep(runWith(1, 4), std::size_t(1) << 30);
        QCOMPARE(kept.count(), 2);
        QVERIFY(!kept.take(runWith(2, 1).recorded->drags));
        auto one = kept.take(runWith(1, 1).recorded->drags);
        QVERIFY(one);
        QCOMPARE(one->history.count(), 4);
        QCOMPARE(kept.count(), 1);
        QVERIFY(!kept.take(one->recorded->drags));  // taken: no longer kept
    }

    void aRunOfTheSameDragsReplacesTheOneKept() {
        KeptRuns kept;
        kept.keep(runWith(1, 3), std::size_t(1) << 30);
        kept.keep(runWith(1, 5), std::size_t(1) << 30);
        QCOMPARE(kept.count(), 1);
        QCOMPARE(kept.take(runWith(1, 1).recorded->drags)->history.count(), 5);
    }

    void theOldestGoOverTheBudgetAndTheNewestStays() {
        // A run's keyframes hold its drags: the runs differ a little in size.
        const std::size_t one = runWith(0, 6).history.bytes();
        const std::size_t newestTwo = runWith(1, 6).history.bytes() + runWith(2, 6).history.bytes();
        QVERIFY(one > 0 && newestTwo < 3 * one);
        KeptRuns kept;
        for (int drags = 0; drags < 3; ++drags) kept.keep(runWith(drags, 6), newestTwo);
        QCOMPARE(kept.count(), 2);
        QCOMPARE(kept.bytes(), newestTwo);
        QVERIFY(!kept.take(runWith(0, 1).recorded->drags));  // the oldest went
        kept.trim(one / 2);
        QCOMPARE(kept.count(), 1);
        QVERIFY(kept.take(runWith(2, 1).recorded->drags));  // the newest stays, whatever the budget
    }
};

QTEST_GUILESS_MAIN(KeptRunsTest)
#include "test_kept_runs.moc"
