// labels: ui;timing
// How soon the window answers, on the wall clock: while a long ladder
// simulates flat out, while a design map computes, and how well it says the
// time a long run to an edit has left. Wall-clock measurements, so the label
// `timing` lets a loaded machine leave them out (ctest -LE timing).
#include "playback_fixture.h"
#include "ui/design/design_map.h"

#include <QElapsedTimer>
#include <QImage>
#include <QLabel>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QThreadPool>
#include <QtTest>

#include <cmath>

using namespace jl::test;
using namespace jl::ui;
using P = jl::DesignParameter;

class AnswerTimesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    // A run that takes more than a few seconds to get back to the moment of
    // an edit also says about how long it still needs (here 10,000 blocks to
    // 0.9 s, then blocks of 3 mm: the run again takes well over the two
    // seconds after which the estimate shows, even on a fast machine).
    void aLongRunToAnEditSaysAboutHowLongIsLeft() {
        Fixture f(slowHangingLadder(10000));
        auto* rate = f.window.findChild<QLabel*>("rate");
        QVERIFY(f.goTo(54, 240000));  // a few seconds alone; much longer beside other tests
        const auto before = f.editThickness(3.0);
        const QRegularExpression left(R"(^running to t = 0\.900 s \(\d+ %, about \d+ (s|min) left\)$)");
        QVERIFY(jl::test::waitForStatus(
            f.sim, [before](const SimStatus& s) { return s.loadSerial > before && s.seekingTo > 0; }));
        QTRY_VERIFY(rate->text().startsWith("running to t = 0.900 s (") && !rate->text().contains("left"));
        QTRY_VERIFY2_WITH_TIMEOUT(left.match(rate->text()).hasMatch(), qPrintable(rate->text()), 60000);
        const QRegularExpressionMatch said = left.match(rate->text());
        const QString amount = said.captured(0).section("about ", 1).section(' ', 0, 0);
        const double predicted = amount.toDouble() * (said.captured(1) == "min" ? 60 : 1);
        QElapsedTimer clock;
        clock.start();
        QVERIFY(jl::test::waitForStatus(
            f.sim,
            [before](const SimStatus& s) { return s.loadSerial > before && s.frameIndex == 54 && s.seekingTo < 0; },
            240000));
        // An estimate, from the run's own pace: right to within a few seconds here.
        const double took = clock.elapsed() / 1000.0;
        qInfo("said \"%s\"; it took %.1f s more", qPrintable(said.captured(0)), took);
        QVERIFY2(std::abs(took - predicted) < std::max(3.0, predicted), qPrintable(QString::number(took)));
        QTRY_COMPARE(rate->text(), QString("paused at frame 54 of 54"));
    }

    void theWindowStaysResponsiveWhileALongLadderSimulatesFlatOut() {
        jl::Scene scene;
        scene.title = "a thousand blocks";
        scene.ladder = jl::LadderSpec{};
        scene.ladder->blocks = 1000;
        Fixture f(scene);
        f.window.setSpeed(4.0);
        f.sim->play();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex > 0; }));
        // Not counted: the first frames of a new scene upload its buffers and shaders once.
        QTest::qWait(500);

        jl::test::EventLoopProbe probe;
        const auto startSerial = f.sim->status()->serial;
        const double startTime = f.sim->status()->frame->time;
        probe.start();
        QTest::qWait(3000);
        probe.stop();
        f.sim->pause();
        const auto s = f.sim->status();
        qInfo(
            "longest stall %lld ms over %d ticks (%.0f ms waiting for a processor not counted); simulated %.3f s at "
            "%.2fx real time, %0.f steps/s",
            probe.worst, probe.ticks, probe.queued, s->frame->time - startTime, s->realTimeFactor, s->stepsPerSecond);
        for (const auto& [at, gap] : probe.gaps) qInfo("gap of %lld ms ending at %lld ms", gap, at);
        QVERIFY2(s->serial > startSerial + 10, "the view was not fed new frames");
        QVERIFY(s->frame->time > startTime);
        QVERIFY2(probe.worst < 50, qPrintable(QString("the event loop stalled for %1 ms").arg(probe.worst)));
    }

    // While a map of 50 cells (runs of seconds to minutes) computes, the window still paints and
    // Cancel still answers: painting in Qt uses the global thread pool (the
    // raster engine scales and converts large images there, and waits), so
    // the map's runs must never fill it.
    void aRunningMapNeverFreezesTheWindow() {
        Document doc;
        DesignMap map(&doc);
        map.show();
        QVERIFY(QTest::qWaitForWindowExposed(&map));
        // 100 to 1,000 blocks: a map of 20 to 200 blocks came to finish
        // within the 1.5 s below on a fast machine once the engine was.
        map.setAxes({P::Blocks, 100, 1000, 100}, {P::Thickness, 0.010, 0.030, 0.005});
        QSignalSpy done(&map, &DesignMap::mapFinished);
        map.compute();
        QTest::qWait(1500);
        QVERIFY(map.running());
        // The map's runs are in a pool of their own; Qt's stays free.
        QCOMPARE(QThreadPool::globalInstance()->activeThreadCount(), 0);
        QVERIFY(designPool()->activeThreadCount() > 0);

        // A smooth scale of a large picture, as the raster engine does in a paint.
        QImage big(2400, 1600, QImage::Format_ARGB32_Premultiplied);
        big.fill(Qt::darkCyan);
        QElapsedTimer clock;
        clock.start();
        const QImage small = big.scaled(1200, 800, Qt::IgnoreAspectRatio, Qt::SmoothTransformation);
        QVERIFY(!small.isNull());
        QVERIFY2(clock.elapsed() < 200, qPrintable(QString("a smooth scale took %1 ms").arg(clock.elapsed())));

        // A repaint of the map's own progress bar.
        auto* bar = map.findChild<QProgressBar*>();
        QVERIFY(bar);
        struct PaintCount : QObject {
            int paints = 0;
            bool eventFilter(QObject*, QEvent* e) override {
                if (e->type() == QEvent::Paint) ++paints;
                return false;
            }
        } count;
        bar->installEventFilter(&count);
        clock.restart();
        bar->update();
        while (count.paints == 0 && clock.elapsed() < 2000) QTest::qWait(5);
        QVERIFY2(count.paints > 0 && clock.elapsed() < 200,
                 qPrintable(QString("a repaint took %1 ms").arg(clock.elapsed())));

        // Cancel: the map stops and says so within 200 ms.
        auto* cancel = map.findChild<QPushButton*>("cancelMap");
        QVERIFY(cancel && cancel->isEnabled());
        clock.restart();
        QTest::mouseClick(cancel, Qt::LeftButton);
        QVERIFY(!map.running());
        QVERIFY(done.wait(200) || done.count() == 1);
        QVERIFY2(clock.elapsed() < 200, qPrintable(QString("Cancel took %1 ms").arg(clock.elapsed())));
        QVERIFY(designPool()->waitForDone(10000));
    }
};

QTEST_MAIN(AnswerTimesTest)
#include "test_answer_times.moc"
