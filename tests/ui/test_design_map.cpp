// labels: ui
// The design map and the ladder editor's live estimate, driven through their
// widgets: a small map's cells are exactly the core's first-ripple reach of
// the same designs, Cancel stops the runs, a click opens a design that one
// Undo takes back, a map opened again comes from the cache without a run, and
// the estimate beside the block count follows an edit.
#include "ui/design/design_map.h"
#include "ui/design/design_map_cache.h"
#include "ui/design/design_map_grid.h"
#include "ui/design/reach_estimate.h"
#include "ui/edit/ladder_panel.h"
#include "ui/edit/scene_fields.h"
#include "ui_test_support.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QImage>
#include <QLabel>
#include <QPainter>
#include <QPushButton>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace jl::ui;
using P = jl::DesignParameter;

namespace {
// 2 x 2 designs of few blocks: each run is a few simulated seconds.
const jl::DesignAxis kBlocks{P::Blocks, 4, 6, 2};
const jl::DesignAxis kThickness{P::Thickness, 0.006, 0.012, 0.006};

bool sameReach(const jl::RippleReach& a, const jl::RippleReach& b) {
    return a.hinges == b.hinges && a.reached == b.reached && a.flipTimes == b.flipTimes &&
           a.meanTimeBetweenFlips == b.meanTimeBetweenFlips && a.failure == b.failure && a.cancelled == b.cancelled;
}

// An edit of the block count, as the Ladder panel makes it.
void setBlocks(MainWindow& w, int n) {
    jl::LadderSpec l = *w.document()->scene().ladder;
    setBlockCount(l, n);
    changeScene(w.document(), ladderField("blocks"), l, "blocks");
}
}  // namespace

class DesignMapTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    // Opened on a design off its axes, the map moves to it: the long-ladder
    // example (200 blocks of 3 mm) opens on 100 .. 300 blocks, its own cell
    // framed; a thickness off the steps gets five values about it. An axis
    // the design is on stays as it was set.
    void aMapOpensAboutTheDesignBeingEdited() {
        Document doc;
        const jl::SceneLoad load = jl::loadScene(JL_SOURCE_DIR "/examples/long-ladder.yaml");
        QVERIFY(load.scene);
        doc.reset(*load.scene, QString());
        DesignMap map(&doc);
        map.show();
        QCOMPARE(map.xAxis(), (jl::DesignAxis{P::Blocks, 100, 300, 50}));
        QCOMPARE(map.yAxis(), axisShown(P::Thickness).first);  // 3 mm is its first value
        QCOMPARE(map.grid()->current(), std::make_pair(2, 0));
        QVERIFY(!map.running());
        map.hide();

        doc.editableScene().ladder->block.thickness = 0.0013;
        doc.notifyChanged(SceneChange::Ladder);
        map.show();
        QCOMPARE(map.xAxis(), (jl::DesignAxis{P::Blocks, 100, 300, 50}));
        const std::vector<double> ys = jl::axisValues(map.yAxis());
        QCOMPARE(int(ys.size()), 5);
        const double expected[] = {0.0009, 0.0011, 0.0013, 0.0015, 0.0017};
        for (size_t i = 0; i < ys.size(); ++i)
            QVERIFY2(std::abs(ys[i] - expected[i]) < 1e-12, qPrintable(QString::number(ys[i])));
        QCOMPARE(map.grid()->current(), std::make_pair(2, 2));
        map.hide();

        // Set by hand to a range the design is on: reopened, it stays.
        const jl::DesignAxis mine{P::Blocks, 150, 250, 25};
        map.setAxes(mine, map.yAxis());
        map.show();
        QCOMPARE(map.xAxis(), mine);
    }

    void smallMapAgreesWithTheCore() {
        Document doc;
        DesignMap map(&doc);
        map.show();
        map.setAxes(kBlocks, kThickness);
        QCOMPARE(map.grid()->columns(), 2);
        QCOMPARE(map.grid()->rows(), 2);
        QSignalSpy done(&map, &DesignMap::mapFinished);
        map.compute();
        QCOMPARE(map.cellsToRun(), 4);
        QVERIFY(map.running());
        QVERIFY(done.wait(120000));
        QVERIFY(!map.running());
        const double blocks[] = {4, 6}, thickness[] = {0.006, 0.012};
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) {
                const auto cell = map.grid()->cell(c, r);
                QVERIFY(cell.has_value());
                // The same design made independently from the document's scene.
                const jl::Scene design =
                    jl::withParameter(jl::withParameter(doc.scene(), P::Blocks, blocks[c]), P::Thickness, thickness[r]);
                QCOMPARE(design.ladder->blocks, int(blocks[c]));
                const jl::RippleReach core = jl::firstRippleReach(design, nullptr);
                QVERIFY2(sameReach(*cell, core), qPrintable(map.grid()->cellText(c, r)));
                QCOMPARE(cell->hinges, int(blocks[c]) - 1);
            }
        // docs/model.md section 15: 6 blocks of 60 x 12 mm flip all 5 hinges.
        QCOMPARE(map.grid()->cell(1, 1)->reached, 5);
        QVERIFY(map.grid()->cellText(1, 1).contains("hinge 5 of 5"));
        // The new ladder (6 blocks, 12 mm) is that cell, framed.
        QCOMPARE(map.grid()->current(), std::pair(1, 1));
        // The axes are written in the window's text colour, whatever was framed
        // last: below the cells (ticks and title) some pixels are dark.
        const QImage shown = map.grid()->grab().toImage();
        const QRect below(0, map.grid()->cellRect(0, 0).bottom() + 4, shown.width(),
                          shown.height() - map.grid()->cellRect(0, 0).bottom() - 4);
        int dark = 0;
        for (int y = below.top(); y < below.bottom(); ++y)
            for (int x = below.left(); x < below.right(); ++x) dark += qGray(shown.pixel(x, y)) < 100 ? 1 : 0;
        QVERIFY2(dark > 20, qPrintable(QString("%1 dark pixels under the map").arg(dark)));
    }

    void reopeningComesFromTheCache() {
        Document doc;
        {
            DesignMap first(&doc);
            first.setAxes(kBlocks, kThickness);
            QSignalSpy done(&first, &DesignMap::mapFinished);
            first.compute();
            if (first.running()) QVERIFY(done.wait(120000));
        }
        const int cached = ReachCache::shared().size();
        DesignMap again(&doc);
        again.setAxes(kBlocks, kThickness);
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) QVERIFY(again.grid()->cell(c, r).has_value());
        QSignalSpy done(&again, &DesignMap::mapFinished);
        again.compute();
        QCOMPARE(again.cellsToRun(), 0);
        QVERIFY(!again.running());
        QCOMPARE(done.count(), 1);
        QCOMPARE(ReachCache::shared().size(), cached);
    }

    // The map's axes meet the scene file's own checks, as `jladder reach`'s
    // do: a ladder held at blocks 0 and 5 cannot be shortened to 4 blocks.
    // The map says so and runs nothing; it used to start all four cells.
    void anAxisTheSceneCannotTakeRunsNothing() {
        Document doc;
        jl::Scene s = doc.scene();
        s.ladder->blocks = 6;
        s.ladder->held = {0, 5};
        doc.reset(s, QString());
        DesignMap map(&doc);
        map.setAxes(kBlocks, kThickness);
        auto* compute = map.findChild<QPushButton*>("computeMap");
        QVERIFY(compute);
        QTest::mouseClick(compute, Qt::LeftButton);
        QCOMPARE(map.cellsToRun(), 0);
        QVERIFY(!map.running());
        auto* status = map.findChild<QLabel*>("mapStatus");
        QVERIFY(status);
        qInfo("%s", qPrintable(status->text()));
        QVERIFY(status->text().contains("held"));
    }

    void cancelStopsTheRuns() {
        Document doc;
        DesignMap map(&doc);
        // Ladders of 1,500 and 2,000 blocks (the panel's largest): a cell
        // stops once its answer is settled, and these take 5 to 8 CPU s each,
        // far longer than the wait before the click.
        map.setAxes({P::Blocks, 1500, 2000, 500}, {P::Thickness, 0.003, 0.004, 0.001});
        QSignalSpy done(&map, &DesignMap::mapFinished);
        map.compute();
        QCOMPARE(map.cellsToRun(), 4);
        QTest::qWait(500);
        QVERIFY(map.running());
        auto* cancel = map.findChild<QPushButton*>("cancelMap");
        QVERIFY(cancel && cancel->isEnabled());
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(!map.running());
        QVERIFY(done.wait(10000));
        // Every run saw the flag and returned: the pool is idle at once.
        QVERIFY(designPool()->waitForDone(10000));
        for (int r = 0; r < 2; ++r)
            for (int c = 0; c < 2; ++c) {
                QVERIFY(!map.grid()->cell(c, r).has_value());
                QVERIFY(!ReachCache::shared().find(ReachCache::designKey(map.cellDesign(c, r))));
            }
    }

    void clickingACellOpensItAndUndoRestores() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const jl::Scene before = w.document()->scene();
        // The Ladder panel's button opens the map.
        auto* button = w.findChild<QPushButton*>("designMapButton");
        QVERIFY(button);
        QTest::mouseClick(button, Qt::LeftButton);
        auto* map = w.findChild<DesignMap*>("designMap");
        QVERIFY(map && map->isVisible());
        map->setAxes(kBlocks, kThickness);
        QSignalSpy done(map, &DesignMap::mapFinished);
        map->compute();
        if (map->running()) QVERIFY(done.wait(120000));
        const int steps = w.document()->undoStack()->count();
        QTest::mouseClick(map->grid(), Qt::LeftButton, {}, map->grid()->cellRect(0, 0).center());
        QCOMPARE(w.document()->scene().ladder->blocks, 4);
        QCOMPARE(w.document()->scene().ladder->block.thickness, 0.006);
        QCOMPARE(w.document()->undoStack()->count(), steps + 1);
        QTRY_COMPARE(map->grid()->current(), std::pair(0, 0));
        // The map follows the ladder: its cells are the same designs, all cached.
        QTRY_VERIFY(map->grid()->cell(1, 1).has_value());
        w.document()->undoStack()->undo();
        QVERIFY(w.document()->scene() == before);
        // The menu entry shows the same window.
        auto* action = w.findChild<QAction*>("designMapAction");
        QVERIFY(action);
        map->hide();
        action->trigger();
        QCOMPARE(w.findChild<DesignMap*>("designMap"), map);
        QVERIFY(map->isVisible());
    }

    void exportsWriteTheMap() {
        Document doc;
        DesignMap map(&doc);
        map.resize(800, 600);
        map.setAxes(kBlocks, kThickness);
        QSignalSpy done(&map, &DesignMap::mapFinished);
        map.compute();
        if (map.running()) QVERIFY(done.wait(120000));
        QTemporaryDir dir;
        QVERIFY(map.exportCsv(dir.filePath("map.csv")));
        QFile csv(dir.filePath("map.csv"));
        QVERIFY(csv.open(QIODevice::ReadOnly));
        const QString text = QString::fromUtf8(csv.readAll());
        QCOMPARE(text.count('\n'), 5);  // a header and one line per cell
        QCOMPARE(text.section('\n', 0, 0),
                 QString("Blocks,Block thickness [mm],hinges,reached,mean time between flips [s],failure"));
        QVERIFY(map.exportSvg(dir.filePath("map.svg")));
        QVERIFY(QFileInfo(dir.filePath("map.svg")).size() > 0);
        QVERIFY(map.exportPng(dir.filePath("map.png")));
        QImage png(dir.filePath("map.png"));
        QCOMPARE(png.size(), map.grid()->size());
        // The cell of 6 blocks, 12 mm (all hinges flip; framed as the ladder
        // being edited) is drawn inside its frame in the legend's top colour.
        QCOMPARE(png.pixelColor(map.grid()->cellRect(1, 1).topLeft() + QPoint(8, 8)), DesignMapGrid::colorOf(1.0));
    }

    void estimateFollowsAnEdit() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* estimate = w.findChild<ReachEstimate*>("reachEstimate");
        QVERIFY(estimate);
        QSignalSpy shown(estimate, &ReachEstimate::estimated);
        // A long ladder of thin blocks first (3 CPU s before its reach is
        // settled): its run starts, and is outdated by the next edit.
        jl::LadderSpec thin = *w.document()->scene().ladder;
        setBlockCount(thin, 300);
        thin.block.thickness = 0.001;
        changeScene(w.document(), ladderField("blocks"), thin, "blocks");
        QVERIFY(estimate->computing());
        QVERIFY(estimate->text().contains("computing"));
        QTest::qWait(600);
        QCOMPARE(shown.count(), 0);
        // Seven blocks: a design no earlier test ran, so it is computed.
        setBlocks(w, 7);
        QVERIFY(shown.wait(60000));
        QVERIFY(!estimate->computing());
        const jl::RippleReach core = jl::firstRippleReach(w.document()->scene(), nullptr);
        QCOMPARE(core.hinges, 6);
        QVERIFY2(estimate->text().contains(QString("hinge %1 of 6").arg(core.reached)), qPrintable(estimate->text()));
        // The 300-block result never showed: the newest design won.
        QCOMPARE(shown.count(), 1);
        QTest::qWait(300);
        QCOMPARE(shown.count(), 1);
    }

    // The estimate runs beside the simulation: a long design is run for its
    // first seconds only (a whole run of 5,000 blocks is 1,001 s simulated;
    // of 10,000 blocks, hours), and says so; that first look is not what
    // the design map shows for the design, unless the run stopped because
    // its reach was settled (jl/design/reach_settled.h): then it is the
    // design's answer. A ladder too long to see even the turn in that
    // budget is not estimated.
    void aLongDesignIsEstimatedFromItsFirstSeconds() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        auto* estimate = w.findChild<ReachEstimate*>("reachEstimate");
        QSignalSpy shown(estimate, &ReachEstimate::estimated);
        // 5,000 blocks 12 mm thick: 2 s, and the reach is not settled yet.
        setBlocks(w, 5000);
        QVERIFY(shown.wait(120000));
        const jl::Scene design = w.document()->scene();
        const double whole = jl::rippleRunTime(design);
        QVERIFY(whole > 1000);
        const jl::RippleReach first = jl::firstRippleReach(design, nullptr, 2.0);
        QVERIFY(!first.whole);
        QCOMPARE(first.until, 2.0);
        const QString expected = QString(
                                     "In the first 2 s (a whole run of this design is %1 s), the first ripple "
                                     "reaches hinge %2 of 4999")
                                     .arg(whole, 0, 'f', 0)
                                     .arg(first.reached);
        QVERIFY2(estimate->text().startsWith(expected), qPrintable(estimate->text()));
        QVERIFY(!ReachCache::shared().find(ReachCache::designKey(design)));

        // 1,000 blocks: too little energy is left to fold hinge 2 at 4.6 s,
        // within the first 10 s, so that answer is the design's, kept for the map.
        setBlocks(w, 1000);
        QVERIFY(shown.wait(120000));
        const jl::Scene settled = w.document()->scene();
        const jl::RippleReach r = jl::firstRippleReach(settled, nullptr, 10.0);
        QVERIFY(r.whole && r.end == jl::RippleEnd::Energy && r.until < 10.0);
        QVERIFY2(estimate->text().startsWith(QString("The first ripple reaches hinge %1 of 999").arg(r.reached)),
                 qPrintable(estimate->text()));
        const auto kept = ReachCache::shared().find(ReachCache::designKey(settled));
        QVERIFY(kept && kept->reached == r.reached && kept->until == r.until);

        setBlocks(w, 20000);
        QTRY_COMPARE(shown.count(), 3);
        QVERIFY(!estimate->computing());
        QVERIFY2(estimate->text().contains("not estimated for a ladder of 20000 blocks"), qPrintable(estimate->text()));
    }
};

QTEST_MAIN(DesignMapTest)
#include "test_design_map.moc"
