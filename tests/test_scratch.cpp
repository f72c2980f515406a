// labels: engine
// The engine's scratch (core/engine/scratch.h) belongs to a world: a run
// leaves none of it behind on its thread once the simulation is gone, and
// steps at a steady state allocate no more as the run goes on. Counted by
// replacing the global operator new and delete (tests/counting_new.h).
#include "tests/counting_new.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <thread>

using namespace jl;
using namespace jl::test;

namespace {

// The classic cascade for a second: locks, folds, flips (each a regroup of
// bodies, a rebuild of the pins, a trial of the slow-release rule). Whether
// it ran and met events.
bool runClassic() {
    auto sim = simulateFile("examples/classic.yaml");
    return sim && sim->advanceTo(1.0) && !sim->takeEvents().empty();
}

}  // namespace

class ScratchTest : public QObject {
    Q_OBJECT
private slots:
    // A worker thread that has run a simulation and dropped it holds nothing
    // of it (scratch kept per thread held the largest world it had seen, a
    // whole copy of it for a trial contact, until the thread ended).
    void aRunLeavesNothingOnItsThread() {
        QVERIFY(runClassic());  // what is built once per program (the loader's tables) is built here
        long long before = 0, after = 0;
        bool ran = false;
        std::thread worker([&] {
            before = live();
            ran = runClassic();
            after = live();
        });
        worker.join();
        QVERIFY(ran);
        QCOMPARE(after, before);
    }

    // A ladder hanging at rest from its held top block: every step the same
    // work, and once the buffers have grown no step allocates at all.
    void steadyStepsAllocateNoMore() {
        auto sim = simulate(R"(
format: jacobs-ladder/1
ladder: {blocks: 40, held: [0]}
duration: 10
)");
        QVERIFY(sim);
        QVERIFY(sim->advanceTo(0.2));  // buffers at their size
        bool stepped = true;
        auto perStep = [&](int steps) {
            const long long start = allocations.load();
            for (int i = 0; i < steps; ++i) stepped = sim->stepOnce() && stepped;
            sim->takeEvents();
            return double(allocations.load() - start) / steps;
        };
        const double early = perStep(200), late = perStep(200);
        QVERIFY(stepped);
        qInfo("allocations per step: %.2f, then %.2f", early, late);
        QVERIFY2(late <= early, qPrintable(QString("%1 then %2").arg(early).arg(late)));
        QCOMPARE(late, 0.0);
    }
};

QTEST_APPLESS_MAIN(ScratchTest)
#include "test_scratch.moc"
