// labels: ladder;soak
// Every cell of the design map of docs/ripple-reach.md (4 to 100 blocks, 1
// to 15 mm thick, blocks solid as by default), run for its whole time: no
// two blocks that are not neighbours inside each other by more than 0.05 mm
// after any step, and no failure. CI runs every seventh cell (28 of 195);
// JL_MAP_CELLS=all runs them all (115 s on one core on 2026-11-29).
#include "jl/design/ripple_reach.h"
#include "tests/block_overlap.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cstdlib>
#include <cstring>
#include <string>

using namespace jl;
using namespace jl::test;

class MapOverlapTest : public QObject {
    Q_OBJECT
private slots:
    void noCellHasBlocksInsideEachOther_data() {
        QTest::addColumn<int>("blocks");
        QTest::addColumn<int>("millimetres");
        const char* cells = std::getenv("JL_MAP_CELLS");
        const bool all = cells && std::strcmp(cells, "all") == 0;
        int k = 0;
        for (int blocks = 4; blocks <= 100; blocks += 8)
            for (int mm = 1; mm <= 15; ++mm, ++k)
                if (all || k % 7 == 0)
                    QTest::newRow(qPrintable(QString("%1 blocks, %2 mm").arg(blocks).arg(mm))) << blocks << mm;
    }
    void noCellHasBlocksInsideEachOther() {
        QFETCH(int, blocks);
        QFETCH(int, millimetres);
        const Scene s = turnedLadder(blocks, 1e-3 * millimetres);
        QCOMPARE(s.solver.blockContact, BlockContact::On);
        auto sim = std::move(Simulation::build(s).simulation);
        QVERIFY(sim);
        double deepest = 0, when = 0;
        const Run r = runUntil(*sim, rippleRunTime(s), [&](const Frame&) {
            const double d = deepestOverlap(*sim);
            if (d > deepest) deepest = d, when = sim->time();
        });
        qInfo("deepest overlap %.3g mm at %.3f s", deepest * 1e3, when);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(deepest <= 0.05e-3);
    }
};

QTEST_APPLESS_MAIN(MapOverlapTest)
#include "test_map_overlap.moc"
