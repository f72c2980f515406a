// labels: ui
// Teaching and analysis: the plots draw the engine's numbers and the energy
// books balance, clicks seek, exports write what they promise, lessons list
// the examples (the side view has tests/ui/test_side_view.cpp).
#include "example_runs.h"
#include "jl/sim/simulation.h"
#include "ui/play/pacing.h"
#include "ui/teaching/events_panel.h"
#include "ui/teaching/exporter.h"
#include "ui/teaching/lessons.h"
#include "ui/teaching/run_plots.h"
#include "ui/teaching/time_chart.h"
#include "ui_test_support.h"

#include <QApplication>
#include <QDir>
#include <QGraphicsRectItem>
#include <QLineSeries>
#include <QListWidget>
#include <QMouseEvent>
#include <QScreen>
#include <QSignalSpy>
#include <QSvgRenderer>
#include <QTemporaryDir>
#include <QValueAxis>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace jl::ui;

class TeachingTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void energyCurvesAreTheEnginesNumbers() {
        const jl::Scene scene = loadExample("classic.yaml");
        const Run run = runHeadless(scene, 1.0);
        RunPlots plots;
        plots.resize(900, 700);
        plots.setHistory(run.frames);
        for (int t = 0; t < int(EnergyTrace::Count); ++t) {
            const QList<QPointF> pts = plots.energyCurve(EnergyTrace(t))->points();
            // 61 samples are fewer than the plot has pixels: every one is drawn as it is.
            QCOMPARE(pts.size(), int(run.frames.size()));
            for (size_t i = 0; i < run.frames.size(); ++i) {
                const jl::EnergyFrame& e = run.frames[i].energy;
                const double expected[] = {e.kinetic,     e.potential, e.total(),  e.impactLoss,
                                           e.dampingLoss, e.heldWork,  e.userWork, e.balance()};
                QCOMPARE(pts[int(i)].x(), run.frames[i].time);
                QCOMPARE(pts[int(i)].y(), expected[t] * plots.energyScale());
            }
        }
        QCOMPARE(plots.energyScale(), 1e3);  // drawn in mJ: a 6-block toy holds a fraction of a joule
        QCOMPARE(plots.energyChart()->valueAxis()->titleText(),
                 QString("energy (mJ)"));  // a lone J, turned on its side, reads as a hook
        // The hand turns the top block: it does work and the impacts take some.
        QVERIFY(run.frames.back().energy.heldWork > 1e-3);
        QVERIFY(run.frames.back().energy.impactLoss > 1e-4);
        // Fold angles are drawn in degrees.
        const auto* hinge1 = static_cast<QLineSeries*>(plots.foldChart()->chart()->series().first());
        QCOMPARE(hinge1->name(), QString("hinge 1"));
        QVERIFY(std::abs(hinge1->points()[30].y() - run.frames[30].hinges[0].foldAngle * (180 / std::numbers::pi)) <
                1e-12);
    }

    // A particle has no angle: the blocks plotted at first are the scene's
    // boxes, whether the plots learn that before the frames or after them.
    void particlesAreNotPlottedForAngularSpeed() {
        const jl::Scene scene = loadExample("particles-and-springs.yaml");
        const Run run = runHeadless(scene, 0.5);
        QCOMPARE(int(scene.bodies.size()), 1);
        QVERIFY(run.frames.front().poses.size() > 1);  // the box, then the particles
        RunPlots before;
        before.setTurning(int(scene.bodies.size()));
        before.setHistory(run.frames);
        QCOMPARE(before.chosenBlocks(), std::vector<int>{0});
        RunPlots after;
        after.setHistory(run.frames);
        QCOMPARE(int(after.chosenBlocks().size()), 3);
        after.setTurning(int(scene.bodies.size()));
        QCOMPARE(after.chosenBlocks(), std::vector<int>{0});
    }

    void theEnergyBooksBalanceToAFlatLineInTheClassicCascade() {
        jl::Scene scene = loadExample("classic.yaml");
        QCOMPARE(scene.ladder->hinges.damping, 0.0);
        QCOMPARE(scene.angularDamping, 0.0);
        const Run run = runHeadless(scene, scene.duration);
        QVERIFY(run.events.size() >= 10);  // the cascade happened: folds and flips all the way down
        RunPlots plots;
        plots.resize(900, 700);
        plots.setHistory(run.frames);
        const QList<QPointF> books = plots.energyCurve(EnergyTrace::Balance)->points();
        QVERIFY(books.size() > 100);
        double worst = 0, swing = 0;
        const double joules = 1 / plots.energyScale();
        for (const QPointF& p : books) worst = std::max(worst, std::abs(p.y()) * joules);
        const QList<QPointF> total = plots.energyCurve(EnergyTrace::Total)->points();
        for (const QPointF& p : total) swing = std::max(swing, std::abs(p.y() - total.front().y()) * joules);
        QVERIFY2(worst < 1e-6, qPrintable(QString("the books are off by %1 J").arg(worst)));
        // ...while the energy itself changes by far more: the flat line says something.
        QVERIFY(swing > 1e-2);
    }

    // What is on the screen is what a chart draws, while a run comes in
    // frame by frame and its values grow a hundredfold (a block that starts
    // to spin): the value axis widens, its labels grow, the plot moves right,
    // and the cursor moves on. The cursor and the event marks are painted
    // over the chart, so a repaint that forgot where they were left old
    // cursors standing on screen.
    void theScreenShowsWhatAChartDrawsWhileARunComesIn() {
        TimeChart chart("Angular speeds", "rad/s");
        QLineSeries* curve = chart.addCurve("block 1", QColor(255, 127, 14));
        chart.resize(480, 230);
        chart.setTimeRange(0, 5);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        auto events = std::make_shared<std::vector<jl::Event>>();
        std::vector<QPointF> points;
        int compared = 0;
        for (int i = 0; i < 240; ++i) {
            const double t = 0.0125 * i;
            const double amplitude = std::pow(150.0, std::min(1.0, t / 2));
            points.emplace_back(t, amplitude * std::sin(40 * t));
            if (i % 16 == 0) events->push_back(jl::Event{t, jl::EventKind::Lock, 1, 0, "lock"});
            chart.setPoints(curve, points);
            chart.fitValues(1);
            chart.setEvents(std::make_shared<const std::vector<jl::Event>>(*events));
            chart.setCursorTime(t);
            QTest::qWait(1);
            if (i % 8 != 7) continue;
            QTest::qWait(20);  // painted and flushed what it was asked to
            const int differing = jl::test::pixelsOffAFreshDrawing(&chart);
            QVERIFY2(differing == 0,
                     qPrintable(
                         QString("%1 pixels on screen at t = %2 s differ from a fresh drawing").arg(differing).arg(t)));
            ++compared;
        }
        QCOMPARE(compared, 30);
    }

    // The cursor moves at every frame a run plays; the curves change a few
    // times a second. A move of the cursor alone must not draw the scene
    // again (each curve is stroked whole whatever the strip repainted).
    void movingTheCursorAloneDrawsNoCurveAgain() {
        TimeChart chart("Angular speeds", "rad/s");
        QLineSeries* curve = chart.addCurve("block 1", QColor(255, 127, 14));
        chart.resize(480, 230);
        chart.setTimeRange(0, 5);
        std::vector<QPointF> points;
        for (int i = 0; i <= 400; ++i) points.emplace_back(0.0125 * i, std::sin(0.5 * i));
        chart.setPoints(curve, points);
        chart.fitValues(1);
        // An item of the scene over the whole chart, drawn whenever the scene
        // under any part of it is (as the curves are).
        struct Counted : QGraphicsRectItem {
            using QGraphicsRectItem::QGraphicsRectItem;
            int paints = 0;
            void paint(QPainter*, const QStyleOptionGraphicsItem*, QWidget*) override { ++paints; }
        };
        auto* counted = new Counted(QRectF(-2000, -2000, 4000, 4000));
        chart.scene()->addItem(counted);
        chart.show();
        QVERIFY(QTest::qWaitForWindowExposed(&chart));
        QTest::qWait(50);
        const int before = counted->paints;
        for (int i = 1; i <= 30; ++i) {
            chart.setCursorTime(0.1 * i);
            QTest::qWait(5);
        }
        QTest::qWait(50);
        qInfo("the scene was drawn %d times for 30 moves of the cursor", counted->paints - before);
        QCOMPARE(counted->paints, before);
        // Where the cursor is now, red; where it was, the chart again.
        const QImage shown = chart.viewport()->grab().toImage();
        const QPointF at = chart.viewPointOf(3.0, 0);
        QColor cursor = Qt::white;  // the reddest pixel across the line (antialiased)
        for (int dx = -1; dx <= 1; ++dx) {
            const QColor c = shown.pixelColor(int(at.x()) + dx, int(at.y()));
            if (c.red() - c.green() > cursor.red() - cursor.green()) cursor = c;
        }
        QVERIFY2(cursor.red() > 150 && cursor.green() < 100, qPrintable(cursor.name()));
        // A change of the curves draws the scene again.
        points.back().setY(2);
        chart.setPoints(curve, points);
        QTest::qWait(50);
        QVERIFY(counted->paints > before);
    }

    void decimationKeepsEveryPeakOfALongRun() {
        std::vector<double> t(200000), y(200000, 1.0);
        for (size_t i = 0; i < t.size(); ++i) t[i] = i * 1e-4;
        y[123457] = 7.0;  // one sample wide
        y[54321] = -3.0;
        const auto pts = decimate(t, y, 0, 20, 500);
        QVERIFY(pts.size() <= 4 * 500 + 2);
        double hi = -1e9, lo = 1e9;
        for (size_t i = 0; i < pts.size(); ++i) {
            hi = std::max(hi, pts[i].y()), lo = std::min(lo, pts[i].y());
            if (i > 0) QVERIFY(pts[i].x() > pts[i - 1].x());
        }
        QCOMPARE(hi, 7.0);
        QCOMPARE(lo, -3.0);
    }

    void clickingAPlotSeeksToThatTime() {
        const Run run = runHeadless(loadExample("classic.yaml"), 1.5);
        RunPlots plots;
        plots.resize(900, 700);
        plots.show();
        QVERIFY(QTest::qWaitForWindowExposed(&plots));
        plots.setHistory(run.frames);
        QTest::qWait(50);  // the charts lay out their new axes
        QSignalSpy seeks(&plots, &RunPlots::seekRequested);
        for (TimeChart* chart : {plots.energyChart(), plots.foldChart(), plots.speedChart()}) {
            const QPoint at =
                chart->viewPointOf(0.7, chart->valueAxis()->min() * 0.5 + chart->valueAxis()->max() * 0.5).toPoint();
            QTest::mouseClick(chart->viewport(), Qt::LeftButton, {}, at);
            QVERIFY(!seeks.isEmpty());
            const double t = seeks.takeLast().at(0).toDouble();
            // Within the time one pixel spans.
            const double pixel =
                (chart->timeAxis()->max() - chart->timeAxis()->min()) / chart->chart()->plotArea().width();
            QVERIFY2(std::abs(t - 0.7) < 1.5 * pixel,
                     qPrintable(QString("%2: asked for 0.7 s, got %1 s").arg(t).arg(chart->chart()->title())));
        }
        // A click beside the plot (on the axis labels) asks for nothing.
        QTest::mouseClick(plots.energyChart()->viewport(), Qt::LeftButton, {}, QPoint(2, 2));
        QVERIFY(seeks.isEmpty());
    }

    void clickingAnEventInTheLogSeeksToIt() {
        const Run run = runHeadless(loadExample("classic.yaml"), 1.0);
        QVERIFY(run.events.size() >= 3);
        EventsPanel panel;
        panel.resize(400, 500);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        panel.setEvents(std::make_shared<const std::vector<jl::Event>>(run.events));
        auto* list = panel.findChild<QListWidget*>("events");
        // One row per event, but a lock and an unlock of one hinge at one
        // instant (a knock) share theirs.
        int knocks = 0;
        for (size_t i = 0; i + 1 < run.events.size(); ++i) {
            const jl::Event &a = run.events[i], &b = run.events[i + 1];
            if (a.kind == jl::EventKind::Lock && b.kind == jl::EventKind::Unlock && a.hinge == b.hinge &&
                a.time == b.time)
                ++knocks;
        }
        QVERIFY(knocks > 0);  // the classic cascade has knocks down the ladder
        QCOMPARE(list->count(), int(run.events.size()) - knocks);
        // Each entry says when and what, in words.
        QCOMPARE(
            list->item(2)->text(),
            QString("%1 s: %2").arg(run.events[2].time, 0, 'f', 3).arg(QString::fromStdString(run.events[2].text)));
        QVERIFY(!run.events[2].text.empty());
        QSignalSpy seeks(&panel, &EventsPanel::instantRequested);
        list->scrollToItem(list->item(2));
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(2)).center());
        QCOMPARE(seeks.size(), 1);
        QCOMPARE(seeks.first().at(0).toDouble(), run.events[2].time);
    }

    // A pair resting against each other with almost no force locks and
    // unlocks every few milliseconds; from two cycles on the log shows the
    // run as one row (which seeks to its start), even with other hinges'
    // events in between. One lock and unlock stay two rows.
    void aRunOfLocksAndUnlocksIsOneRow() {
        using K = jl::EventKind;
        std::vector<jl::Event> events{{0.100, K::Lock, 1, 0, "blocks 0 and 1 lock end to end"},
                                      {0.200, K::Unlock, 1, 0, "blocks 0 and 1 unlock"}};
        for (int k = 0; k < 10; ++k) {
            events.push_back({0.300 + 0.002 * k, k % 2 ? K::Unlock : K::Lock, 1, 0,
                              k % 2 ? "blocks 0 and 1 unlock" : "blocks 0 and 1 lock end to end"});
            if (k == 4) events.push_back({0.3085, K::FlipFlop, 2, 1, "block 2 flips over the far end of block 1"});
        }
        events.push_back({1.000, K::Lock, 3, 0, "blocks 2 and 3 lock end to end"});
        events.push_back({1.005, K::Unlock, 3, 0, "blocks 2 and 3 unlock"});
        EventsPanel panel;
        panel.resize(600, 400);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        // Delivered as a player would: a few events at a time.
        auto shown = std::make_shared<std::vector<jl::Event>>();
        for (const jl::Event& e : events) {
            shown->push_back(e);
            panel.setEvents(std::make_shared<const std::vector<jl::Event>>(*shown));
        }
        auto* list = panel.findChild<QListWidget*>("events");
        QStringList rows;
        for (int i = 0; i < list->count(); ++i) rows << list->item(i)->text();
        QCOMPARE(list->count(), 6);
        QVERIFY2(rows[2].startsWith("0.300–0.318 s: blocks 0 and 1 lock and unlock again and again (10 events)"),
                 qPrintable(rows[2]));
        QVERIFY2(rows[3].contains("block 2 flips"), qPrintable(rows[3]));
        QVERIFY(rows[4].startsWith("1.000 s:") && rows[5].startsWith("1.005 s:"));
        QSignalSpy seeks(&panel, &EventsPanel::instantRequested);
        QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(list->item(2)).center());
        QCOMPARE(seeks.size(), 1);
        QCOMPARE(seeks.first().at(0).toDouble(), 0.300);
        // Rebuilt at once (a seek back replaces the log), the same rows.
        panel.setEvents(nullptr);
        panel.setEvents(std::make_shared<const std::vector<jl::Event>>(events));
        QCOMPARE(list->count(), 6);
        QCOMPARE(list->item(2)->text(), rows[2]);
    }

    // A lock and an unlock of one hinge at one instant (a knock) is one row;
    // a lock and a later unlock stay two.
    void aKnockIsOneRow() {
        using K = jl::EventKind;
        const std::vector<jl::Event> events{{4.032, K::Lock, 198, 0, "blocks 197 and 198 lock end to end"},
                                            {4.032, K::Unlock, 198, 0, "blocks 197 and 198 unlock"},
                                            {4.061, K::Lock, 196, 0, "blocks 195 and 196 lock end to end"},
                                            {4.162, K::Unlock, 196, 0, "blocks 195 and 196 unlock"}};
        EventsPanel panel;
        auto shown = std::make_shared<std::vector<jl::Event>>();
        for (const jl::Event& e : events) {
            shown->push_back(e);
            panel.setEvents(std::make_shared<const std::vector<jl::Event>>(*shown));
        }
        auto* list = panel.findChild<QListWidget*>("events");
        QCOMPARE(list->count(), 3);
        QCOMPARE(list->item(0)->text(), QString("4.032 s: blocks 197 and 198 knock end to end"));
        QVERIFY(list->item(0)->toolTip().contains("A lock and an unlock at one instant"));
        QVERIFY(list->item(1)->text().startsWith("4.061 s: blocks 195 and 196 lock"));
        QVERIFY(list->item(2)->text().startsWith("4.162 s: blocks 195 and 196 unlock"));
        QCOMPARE(list->item(0)->data(Qt::UserRole).toDouble(), 4.032);
        // Two more cycles within milliseconds make the knock the start of a
        // run: one row, whose tooltip no longer says it was a knock.
        for (double t : {4.034, 4.036}) {
            shown->push_back({t, K::Lock, 198, 0, "blocks 197 and 198 lock end to end"});
            panel.setEvents(std::make_shared<const std::vector<jl::Event>>(*shown));
        }
        QVERIFY2(list->item(0)->text().startsWith("4.032–4.036 s: blocks 197 and 198 lock and unlock again and again"),
                 qPrintable(list->item(0)->text()));
        QVERIFY(list->item(0)->toolTip().isEmpty());
    }

    void exportsWriteWhatTheyPromise() {
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const jl::Scene scene = loadExample("classic.yaml");
        const Run run = runHeadless(scene, 0.7);

        // A picture of the side view.
        const QString shot = dir.filePath("side.png");
        QVERIFY(Exporter::sideViewPicture(scene, run.frames.back(), QSize(640, 480), {}, shot).ok);
        QCOMPARE(QImage(shot).size(), QSize(640, 480));

        // An image sequence: 0.5 s to 1.0 s at 20 pictures a second is 11 pictures.
        SequenceRequest r;
        r.from = 0.5, r.to = 1.0, r.fps = 20, r.size = QSize(320, 240), r.directory = dir.filePath("seq");
        QCOMPARE(Exporter::frameCount(r.from, r.to, r.fps), 11);
        const ExportResult seq = Exporter::imageSequence(scene, r);
        QVERIFY2(seq.ok, qPrintable(seq.error));
        QCOMPARE(seq.files.size(), 11);
        QCOMPARE(QDir(r.directory).entryList({"*.png"}, QDir::Files).size(), 11);
        for (const QString& f : seq.files) QCOMPARE(QImage(f).size(), QSize(320, 240));
        // The pictures follow the motion.
        QVERIFY(QImage(seq.files.first()) != QImage(seq.files.last()));

        // A painter of one's own (the 3-D view's capture) gets the engine's frames.
        std::vector<double> times;
        r.directory = dir.filePath("custom");
        r.painter = [&times](const jl::Frame& f) {
            times.push_back(f.time);
            QImage i(64, 48, QImage::Format_RGB32);
            i.fill(Qt::black);
            return i;
        };
        QVERIFY(Exporter::imageSequence(scene, r).ok);
        QCOMPARE(int(times.size()), 11);
        // At exactly the times asked for, read off the steps (not at step ends).
        for (int i = 0; i < 11; ++i) QCOMPARE(times[size_t(i)], 0.5 + i * (1 / 20.0));

        // The event log as CSV: a header and one row per event, times that read back exactly.
        const ExportResult csv = Exporter::eventsCsv(run.events, dir.filePath("events.csv"));
        QVERIFY2(csv.ok, qPrintable(csv.error));
        QFile file(dir.filePath("events.csv"));
        QVERIFY(file.open(QIODevice::ReadOnly | QIODevice::Text));
        const QStringList rows = QString::fromUtf8(file.readAll()).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), int(run.events.size()) + 1);
        QCOMPARE(rows.front(), QString("t [s],hinge,event,corner,text"));
        for (size_t i = 0; i < run.events.size(); ++i) {
            const QStringList cells = rows[int(i) + 1].split(',');
            QVERIFY(cells.size() >= 5);  // the text may hold commas (quoted)
            QCOMPARE(cells[0].toDouble(), run.events[i].time);
            QCOMPARE(cells[1].toInt(), run.events[i].hinge);
            QCOMPARE(cells[2], QString(jl::toString(run.events[i].kind)));
        }

        // Poses, energies and events of 0 to 1 s every 0.1 s: 11 frames of 6 blocks.
        const ExportResult tables = Exporter::tables(scene, 0, 1.0, 0.1, dir.filePath("tables"));
        QVERIFY2(tables.ok, qPrintable(tables.error));
        auto rowsOf = [&](const char* name) {
            QFile f(QDir(dir.filePath("tables")).filePath(name));
            if (!f.open(QIODevice::ReadOnly | QIODevice::Text)) return QStringList();
            return QString::fromUtf8(f.readAll()).split('\n', Qt::SkipEmptyParts);
        };
        const QStringList poses = rowsOf("poses.csv"), energies = rowsOf("energy.csv");
        QCOMPARE(poses.size(), 11 * 6 + 1);
        QCOMPARE(poses.front(), QString("t [s],block,x [m],y [m],angle [rad]"));
        QCOMPARE(energies.size(), 11 + 1);
        QCOMPARE(energies.front().split(',').size(), 9);
        QCOMPARE(energies.front().split(',').last(), QString("balance [J]"));
        for (const QString& row : energies.mid(1)) QVERIFY(std::abs(row.split(',').last().toDouble()) < 1e-6);
        // Block 3 at 0.5 s (frame 5) is where the engine puts it, to the last bit.
        auto engine = jl::Simulation::build(scene).simulation;
        engine->advanceTo(0.5);
        const jl::Pose at05 = engine->frame().poses[3];
        const QStringList cells = poses[5 * 6 + 3 + 1].split(',');
        QCOMPARE(cells[1].toInt(), 3);
        QCOMPARE(cells[2].toDouble(), at05.position.x());
        QCOMPARE(cells[3].toDouble(), at05.position.y());
        QCOMPARE(cells[4].toDouble(), at05.angle);

        // The plots as PNG and SVG.
        RunPlots plots;
        plots.resize(800, 600);
        plots.setHistory(run.frames);
        QString error;
        QVERIFY(plots.savePng(dir.filePath("plots.png"), QSize(1000, 800), &error));
        QCOMPARE(QImage(dir.filePath("plots.png")).size(), QSize(1000, 800));
        QVERIFY(plots.saveSvg(dir.filePath("plots.svg"), QSize(800, 600), &error));
        QSvgRenderer svg(dir.filePath("plots.svg"));
        QVERIFY(svg.isValid());
        QCOMPARE(svg.viewBox(), QRect(0, 0, 800, 600));

        // A video needs ffmpeg; without it the answer says so in words.
        r.painter = {};
        const ExportResult video = Exporter::video(scene, r, dir.filePath("run.mp4"));
        if (Exporter::ffmpeg().isEmpty()) {
            QVERIFY(!video.ok);
            QVERIFY(video.error.contains("ffmpeg"));
            QVERIFY(video.error.contains("not installed"));
        } else {
            QVERIFY2(video.ok, qPrintable(video.error));
            QVERIFY(QFileInfo(dir.filePath("run.mp4")).size() > 0);
        }
    }

    void lessonsListTheExamplesWithTitlesInTeachingOrder() {
        const std::vector<Lesson> lessons = findLessons(QString(JL_SOURCE_DIR) + "/examples");
        QCOMPARE(int(lessons.size()), int(QDir(QString(JL_SOURCE_DIR) + "/examples").entryList({"*.yaml"}).size()));
        QCOMPARE(lessons.front().title, QString("The classic cascade"));
        QStringList order;
        for (const Lesson& l : lessons) order << QFileInfo(l.path).completeBaseName();
        // docs/teaching.md's order: the paper's observations (one hinge, over
        // and back, a second ripple, the results sequence) between the cascade
        // and the other ladders.
        QCOMPARE(order.mid(0, 7), QStringList({"classic", "wrong-way", "one-hinge", "back-and-forth", "two-ripples",
                                               "pushed-down-pulled-up", "heavy-middle"}));
        for (const Lesson& l : lessons) {
            QVERIFY(!l.title.isEmpty());
            QVERIFY2(l.description.size() > 40, qPrintable(l.path));
        }
        LessonsMenu menu(lessons);
        QSignalSpy open(&menu, &LessonsMenu::openRequested);
        QCOMPARE(menu.actions().size(), int(lessons.size()));
        menu.actions().at(3)->trigger();
        QCOMPARE(open.size(), 1);
        QCOMPARE(open.first().at(0).toString(), lessons[3].path);

        LessonPanel panel;
        panel.showScene(loadExample("classic.yaml"));
        QVERIFY(panel.text().contains("The classic cascade"));
        QVERIFY(panel.text().contains("flip-flop"));
    }

    // N shows the ladder at the instant of the next event (between two
    // frames), simulating on when none is recorded yet; N again, the next
    // instant after that one (events of one instant come together).
    void runToTheNextEventShowsItsInstant() {
        const jl::Scene scene = loadExample("classic.yaml");
        const Run run = runHeadless(scene, 1.0);
        QVERIFY(run.events.size() >= 2);
        SimController sim;
        Pacing pacing(&sim);
        const auto before = jl::test::loadsSoFar(&sim);
        sim.load(scene);
        QVERIFY(jl::test::loadedAfter(&sim, before));
        const double dt = scene.solver.frameInterval;
        // Nothing recorded yet: it simulates on until the first event happens.
        pacing.runToNextEvent();
        const double first = run.events[0].time;
        QVERIFY(jl::test::waitForStatus(
            &sim, [&](const SimStatus& s) { return !pacing.seekingEvent() && s.frame->time == first; }));
        // (the hand's turn starts at 0.2 s, a frame's time: that frame)
        const jl::FrameGrid grid{0, dt};
        QCOMPARE(sim.status()->frameIndex, int(grid.on(first) ? grid.nearest(first) : std::floor(first / dt)));
        const jl::Event* next = nullptr;
        for (const jl::Event& e : run.events)
            if (e.time > first) {
                next = &e;
                break;
            }
        QVERIFY(next);
        pacing.runToNextEvent();
        QVERIFY(jl::test::waitForStatus(
            &sim, [&](const SimStatus& s) { return !pacing.seekingEvent() && s.frame->time == next->time; }));
        QVERIFY(!sim.status()->playing);
        QVERIFY(!sim.status()->frame->events.empty());
        QCOMPARE(sim.status()->frame->events.front().time, next->time);
        QVERIFY(!grid.on(next->time));
        QCOMPARE(sim.status()->frameIndex, int(std::floor(next->time / dt)));
    }

    void aLoopReturnsToItsStart() {
        SimController sim;
        Pacing pacing(&sim);
        const auto before = jl::test::loadsSoFar(&sim);
        sim.load(jl::test::swingingLadder());
        QVERIFY(jl::test::loadedAfter(&sim, before));
        pacing.setLoop(0.1, 0.3);
        sim.setSpeed(2.0);
        sim.play();
        double latest = 0;
        bool wrapped = false;
        QVERIFY(jl::test::waitForStatus(
            &sim,
            [&](const SimStatus& s) {
                if (s.frame->time < latest - 0.1) wrapped = true;
                latest = s.frame->time;
                return wrapped && s.frame->time > 0.15;
            },
            10000));
        sim.pause();
        QVERIFY(latest < 0.3 + 0.2);
    }
};

QTEST_MAIN(TeachingTest)
#include "test_teaching.moc"
