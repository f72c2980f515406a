// labels: ui;timing
// A long ladder played in the window at a laptop's screen size: the UI
// thread must never stall for long, and a click on Pause must take effect
// at once, however slow the engine is. Wall-clock measurements, so the
// label `timing` lets a loaded machine leave this out (ctest -LE timing).
// It also prints where each thread's processor time went and the real-time
// factor, for docs/desktop-performance.md (speed is measured, not asserted).
#include "jl/scene/scene_io.h"
#include "thread_seconds.h"
#include "ui/play/sim_controller.h"
#include "ui/window/main_window.h"
#include "ui_test_support.h"

#include <QElapsedTimer>
#include <QThread>
#include <QtTest>

#include <algorithm>
#include <map>
#include <string>

using namespace jl::ui;

namespace {

constexpr qint64 kLongestStallMs = 100;  // the requirement: no click waits longer

// The classic cascade's design with `blocks` blocks, as a user makes it.
jl::Scene classicWith(int blocks) {
    auto load = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
    if (!load.scene) qFatal("examples/classic.yaml does not load");
    load.scene->ladder->blocks = blocks;
    load.scene->duration = 60;  // plays on through the measurement
    return *load.scene;
}

}  // namespace

class LongLadderTiming : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() {
        jl::test::isolateSettings();
        renderThreadsGiven_ = qEnvironmentVariableIsSet("LP_NUM_THREADS");
    }

    // Software OpenGL draws on all cores but one (ladder_view.cpp): with
    // llvmpipe's two threads on two cores, the simulation thread of the
    // 1,000-block row below lost its core to them at every frame.
    void theRendererLeavesACoreToTheSimulation() {
        if (renderThreadsGiven_) QSKIP("LP_NUM_THREADS is set by the environment");
        MainWindow window(jl::test::quietWindow());
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTest::qWait(500);  // the first frames drawn
        int threads = 0;
        for (const QString& tid : jl::test::threadIds()) threads += jl::test::threadName(tid) == "llvmpipe" ? 1 : 0;
        if (threads == 0) QSKIP("not drawn by llvmpipe");
        QVERIFY2(threads <= std::max(1, QThread::idealThreadCount() - 1),
                 qPrintable(QString("%1 llvmpipe threads on %2 cores").arg(threads).arg(QThread::idealThreadCount())));
    }

    void theWindowAnswersAtOnceWhileALongLadderPlays_data() {
        QTest::addColumn<int>("blocks");
        QTest::newRow("1,000 blocks") << 1000;
        QTest::newRow("10,000 blocks") << 10000;
    }

    void theWindowAnswersAtOnceWhileALongLadderPlays() {
        QFETCH(int, blocks);
        MainWindow window(jl::test::quietWindow());
        window.showMaximized();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        SimController* sim = window.controller();
        const auto before = jl::test::loadsSoFar(sim);
        window.document()->reset(classicWith(blocks), QString());
        QVERIFY(jl::test::loadedAfter(sim, before));
        QTest::qWait(1000);  // the first frames upload the scene's buffers and shaders once
        sim->play();
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return s.playing && s.frameIndex > 0; }));

        jl::test::EventLoopProbe probe;
        // Frames handed to the views: each one the 3-D view draws.
        int framesShown = 0;
        const jl::Frame* lastShown = nullptr;
        const auto counting = connect(sim, &SimController::statusChanged, this, [&](auto st) {
            if (st->frame && st->frame.get() != lastShown) ++framesShown, lastShown = st->frame.get();
        });
        const auto cpuBefore = jl::test::threadSeconds();
        const auto waitBefore = jl::test::threadWaits();
        const double simBefore = sim->status()->frame->time;
        probe.start();
        // The last 2 s on their own too: the span the status bar's factor covers.
        QTest::qWait(4000);
        const double simAt4 = sim->status()->frame->time;
        const qint64 wallAt4 = probe.clock.elapsed();
        const auto cpuAt4 = jl::test::threadSeconds();
        QTest::qWait(2000);
        probe.stop();
        disconnect(counting);
        const double wall = double(probe.clock.elapsed()) / 1000;
        const auto cpuAfter = jl::test::threadSeconds();
        const auto waitAfter = jl::test::threadWaits();
        const auto s = sim->status();

        // A click on Pause while it plays: from the click's event to the
        // worker having stopped.
        QElapsedTimer click;
        click.start();
        QVERIFY(jl::test::clickToolButton(window, "&Pause"));
        while (sim->status()->playing && click.elapsed() < 5000) QThread::usleep(200);
        const qint64 pauseMs = click.elapsed();

        const double simulated = s->frame->time - simBefore;
        const double lastTwo = (s->frame->time - simAt4) / (double(probe.clock.elapsed() - wallAt4) / 1000);
        qInfo(
            "%d blocks: simulated %.3f s (from t = %.3f s) in %.2f s wall (%.3fx; the last 2 s %.3fx; the status bar "
            "said %.2fx over %.1f s); %d frames shown; longest gap between UI ticks %lld ms (%.0f ms waiting for a "
            "processor not counted); pause took effect after %lld ms",
            blocks, simulated, simBefore, wall, simulated / wall, lastTwo, s->realTimeFactor, s->rateSpan, framesShown,
            probe.worst, probe.queued, pauseMs);
        // Each thread's share, and the time it waited for a processor: a
        // simulation thread that falls behind either waits on a run queue
        // (the other threads have the cores) or runs short of its work.
        const auto since = [](const std::map<std::string, double>& from, const std::string& name, double now) {
            return now - (from.count(name) ? from.at(name) : 0.0);
        };
        for (const auto& [name, seconds] : cpuAfter) {
            const double used = since(cpuBefore, name, seconds);
            const double waited = waitAfter.count(name) ? since(waitBefore, name, waitAfter.at(name)) : 0.0;
            if (used > 0.005)
                qInfo(
                    "  thread %-16s %6.2f CPU s (%.2f per simulated s; the last 2 s %.2f), waited %.2f s for a "
                    "processor",
                    name.c_str(), used, used / simulated, since(cpuAt4, name, seconds), waited);
        }
        for (const auto& [at, gap] : probe.gaps) qInfo("  gap of %lld ms ending at %lld ms", gap, at);
        QVERIFY(simulated > 0);
        QVERIFY2(probe.worst < kLongestStallMs,
                 qPrintable(QString("the event loop stalled for %1 ms").arg(probe.worst)));
        QVERIFY2(pauseMs < kLongestStallMs, qPrintable(QString("the pause waited %1 ms").arg(pauseMs)));
    }

private:
    bool renderThreadsGiven_ = false;  // LP_NUM_THREADS set before the program set it
};

QTEST_MAIN(LongLadderTiming)
#include "test_long_ladder_timing.moc"
