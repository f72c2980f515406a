// labels: ui
// The simulation behind the window: play, pause, step, scrub, edits at the
// moment on screen, events shown at their instants, a failed solve (the
// mouse drags: test_drag_replay.cpp; what the wall clock measures:
// test_answer_times.cpp).
#include "example_runs.h"
#include "playback_fixture.h"
#include "ui/play/timeline.h"
#include "ui/teaching/run_plots.h"
#include "ui/teaching/time_chart.h"

#include <QLabel>
#include <QLineSeries>
#include <QMessageBox>
#include <QRegularExpression>
#include <QScreen>
#include <QTimer>
#include <QToolBar>
#include <QUndoStack>
#include <QValueAxis>
#include <QtTest>

#include <cmath>
#include <fstream>
#include <optional>

using namespace jl::test;

namespace {

// A swinging ladder whose lesson lasts 0.5 s, and playing it (at 4x) until it stops there.
jl::Scene halfSecondLesson() {
    jl::Scene scene = jl::test::swingingLadder();
    scene.duration = 0.5;
    return scene;
}
bool playToTheEnd(Fixture& f) {
    f.window.setSpeed(4.0);
    f.sim->play();
    return jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frame && s.frame->time > 0.1; }) &&
           jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; });
}

}  // namespace

class PlaybackTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void playingForASecondAdvancesTimeAndMovesTheBlocks() {
        Fixture f(jl::test::swingingLadder());
        const auto first = f.sim->status()->frame;
        QCOMPARE(first->time, 0.0);
        f.window.setSpeed(1.0);
        f.sim->play();
        QTest::qWait(1000);
        f.sim->pause();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        const auto s = f.sim->status();
        // Paced to real time: about a second, allowing for a slow, shared machine.
        QVERIFY2(s->frame->time > 0.25 && s->frame->time < 1.3, qPrintable(QString::number(s->frame->time)));
        const double moved = (s->frame->poses[3].position - first->poses[3].position).norm();
        QVERIFY2(moved > 0.002, qPrintable(QString("block 3 moved %1 m").arg(moved)));
        // What is shown is what the engine computes for that frame.
        QVERIFY(samePoses(*s->frame, engineFrameAt(jl::test::swingingLadder(), s->frameIndex)));
    }

    void stepForwardAndBackChangeTheFrameByOne() {
        Fixture f(jl::test::swingingLadder());
        QVERIFY(f.goTo(10));
        const auto at10 = f.sim->status()->frame;
        f.sim->stepForward();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 11; }));
        const auto at11 = f.sim->status()->frame;
        QVERIFY(!samePoses(*at10, *at11));
        QVERIFY(samePoses(*at11, engineFrameAt(jl::test::swingingLadder(), 11)));
        f.sim->stepBack();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 10; }));
        QVERIFY(samePoses(*f.sim->status()->frame, *at10));
        f.sim->stepBack();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 9; }));
        QCOMPARE(f.sim->status()->frameCount, 12);  // stepping back records nothing
    }

    void keysInTheViewDriveTheTransport() {
        Fixture f(jl::test::swingingLadder());
        LadderView* view = f.window.ladderView();
        QVERIFY(QTest::qWaitForWindowExposed(view));
        QTest::keyClick(view, Qt::Key_Period);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 1; }));
        QTest::keyClick(view, Qt::Key_Right);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 2; }));
        QTest::keyClick(view, Qt::Key_Left);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 1; }));
        QTest::keyClick(view, Qt::Key_Space);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.playing && s.frameIndex > 3; }));
        QTest::keyClick(view, Qt::Key_Space);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        QTest::keyClick(view, Qt::Key_R, Qt::ControlModifier);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 0; }));
    }

    void anEditShowsItsEffectAtTheMomentOnScreen() {
        Fixture f(jl::test::swingingLadder());
        QVERIFY(f.goTo(30));
        const auto before = jl::test::loadsSoFar(f.sim);
        auto* thickness = f.window.findChild<QDoubleSpinBox*>("thickness");
        thickness->setValue(6.0);  // mm
        const jl::Scene edited = f.window.document()->scene();
        QCOMPARE(edited.ladder->block.thickness, 0.006);
        QVERIFY(jl::test::waitForStatus(
            f.sim, [before](const SimStatus& s) { return s.loadSerial > before && s.frameIndex == 30; }));
        QVERIFY(samePoses(*f.sim->status()->frame, engineFrameAt(edited, 30)));
        QVERIFY(!samePoses(*f.sim->status()->frame, engineFrameAt(jl::test::swingingLadder(), 30)));
    }

    // On a long ladder the run up to the moment on screen takes a while: the
    // status bar says where it is running to instead of "paused" while the
    // frames move on, and says "paused" again once it is there. Before the
    // first step there is no step to show.
    void anEditOnALongLadderSaysWhereItIsRunningTo() {
        Fixture f(slowHangingLadder(1000));
        auto* rate = f.window.findChild<QLabel*>("rate");
        auto* step = f.window.findChild<QLabel*>("step");
        QTRY_COMPARE(step->text(), QString("no step yet"));
        QVERIFY(f.goTo(60));
        QTRY_VERIFY(step->text().endsWith("ms (auto)"));
        const auto before = f.editThickness(4.0);
        QVERIFY(jl::test::waitForStatus(
            f.sim, [before](const SimStatus& s) { return s.loadSerial > before && s.seekingTo > 0; }));
        QTRY_VERIFY2(rate->text().startsWith("running to t = 1.000 s ("), qPrintable(rate->text()));
        QVERIFY(jl::test::waitForStatus(f.sim, [before](const SimStatus& s) {
            return s.loadSerial > before && s.frameIndex == 60 && s.seekingTo < 0;
        }));
        QTRY_COMPARE(rate->text(), QString("paused at frame 60 of 60"));
    }

    // A long ladder says how many of its blocks the motion has not reached
    // (they hang still, joined into a few bodies), and fewer once it has
    // reached them; a short ladder says nothing of it.
    void theStatusBarSaysHowManyBlocksHangStill() {
        jl::Scene scene = hangingLadder(1000);
        jl::ScriptAction turn;
        turn.angle = M_PI;
        scene.script.push_back(turn);
        Fixture f(scene);
        auto* still = f.window.findChild<QLabel*>("still");
        QVERIFY(still);
        const auto count = [still] { return QString(still->text()).remove(QRegularExpression("[^0-9]")).toInt(); };
        QTRY_VERIFY2(still->isVisible() && still->text().endsWith(" blocks still") &&
                         count() == 1000 - jl::Ladder::kWakeBlocks - 1,
                     qPrintable(still->text()));
        QVERIFY(f.goTo(30));  // 0.5 s: the motion has come some hundred blocks down
        QTRY_VERIFY2(count() > 500 && count() < 1000 - jl::Ladder::kWakeBlocks - 1, qPrintable(still->text()));
        Fixture shortLadder(jl::test::swingingLadder());
        QVERIFY(shortLadder.goTo(3));
        QVERIFY(!shortLadder.window.findChild<QLabel*>("still")->isVisible());
    }

    // A frame of a very long ladder takes seconds: a pause comes between two
    // steps, not at the end of the frame, and the frame is finished later
    // from where it stopped, the same as if it had never been interrupted.
    // Step forward pressed twice at the head makes two frames.
    void aPauseComesBetweenTwoStepsAndTheFrameIsFinishedLater() {
        jl::Scene scene = slowHangingLadder(2000);
        scene.solver.frameInterval = 1.0;  // s: a frame of a thousand steps or so, a second or more
        Fixture f(scene);
        f.sim->stepForward();  // simulated flat out (playing would wait until the frame is due)
        QTest::qWait(200);
        const auto before = f.sim->status()->serial;
        f.sim->pause();
        QVERIFY(jl::test::waitForStatus(f.sim, [before](const SimStatus& s) { return s.serial > before; }));
        QCOMPARE(f.sim->status()->frameCount, 1);  // paused inside the first frame, not after it
        QTest::qWait(300);
        QCOMPARE(f.sim->status()->frameCount, 1);  // and it stays paused there
        f.sim->stepForward();
        f.sim->stepForward();
        QVERIFY(jl::test::waitForStatus(
            f.sim, [](const SimStatus& s) { return s.frameIndex == 2; }, 60000));
        const auto s = f.sim->status();
        QCOMPARE(s->frameCount, 3);
        QCOMPARE(engineHashAt(scene, 2), s->headHash);
        QVERIFY(samePoses(*s->frame, engineFrameAt(scene, 2)));
    }

    // Frame i is the state at exactly i * interval, read off the step that
    // passes it, even where one step passes several frame times; each event
    // comes with the first frame not earlier than it; and a frame simulated
    // again after eviction is the same.
    void framesLieAtExactTimesEvenWhenAStepPassesSeveral() {
        jl::Scene scene = jl::test::swingingLadder();
        scene.solver.step = 0.001;
        scene.solver.frameInterval = 0.0004;  // two or three frames per step
        jl::ScriptAction turn;
        turn.at = 0.0102;  // inside a step
        turn.angle = 1.0;
        turn.duration = 0.1;
        scene.script.push_back(turn);
        // The worker alone: nobody takes the frames it hands on, so all stay.
        SimController sim;
        sim.load(scene);
        const jl::FrameGrid grid{0, scene.solver.frameInterval};
        const auto goTo = [&](int index) {
            sim.seek(grid.at(index) + grid.every / 4);
            return jl::test::waitForStatus(&sim, [index](const SimStatus& st) { return st.frameIndex == index; });
        };
        const bool reached = goTo(300);
        const auto s = sim.status();
        QVERIFY2(reached, qPrintable(QString("frame %1 of %2, %3")
                                         .arg(s->frameIndex)
                                         .arg(s->frameCount)
                                         .arg(QString::fromStdString(s->failure))));
        QCOMPARE(s->frame->time, grid.at(300));
        QVERIFY(samePoses(*s->frame, engineFrameAt(scene, 300)));
        QVERIFY(s->events && s->events->size() >= 2);  // the hand's turn, and its end
        // Every frame handed on lies on the grid, in order, and holds the
        // events inside (frame before, itself].
        QCOMPARE(s->firstNewFrame, std::uint64_t(0));
        const auto& frames = *s->newFrames;
        QCOMPARE(int(frames.size()), 301);
        size_t events = 0;
        for (int i = 0; i <= 300; ++i) {
            const jl::Frame& fr = *frames[size_t(i)];
            QCOMPARE(fr.time, grid.at(i));
            for (const jl::Event& e : fr.events) {
                QVERIFY2(e.time <= fr.time + 1e-12 && (i == 0 || e.time > grid.at(i - 1) + 1e-12),
                         qPrintable(QString("event at %1 s in the frame at %2 s").arg(e.time).arg(fr.time)));
                ++events;
            }
        }
        QCOMPARE(events, s->events->size());
        // Evicted and simulated again from a keyframe: the same frame.
        sim.setMemoryBudget(1);
        QVERIFY(goTo(299));
        QVERIFY(goTo(137));
        QCOMPARE(sim.status()->frame->time, grid.at(137));
        QVERIFY(samePoses(*sim.status()->frame, *frames[137]));
    }

    void scrubbingBackShowsThePosesRecordedThen() {
        const jl::Scene scene = jl::test::swingingLadder();
        Fixture f(scene);
        QVERIFY(f.goTo(60));
        const jl::Frame expected = engineFrameAt(scene, 27);
        QVERIFY(f.goTo(27));
        QVERIFY(samePoses(*f.sim->status()->frame, expected));
        // With a memory budget too small for any frame, the frame is re-simulated
        // from the keyframe before it and must still be the same.
        f.sim->setMemoryBudget(1);
        QVERIFY(f.goTo(59));
        QVERIFY(f.goTo(44));
        QVERIFY(samePoses(*f.sim->status()->frame, engineFrameAt(scene, 44)));
    }

    // Choosing an event shows the ladder at its instant, which lies between
    // two frames (the classic's frames are 17 ms apart, in which a block
    // that locks turns tens of degrees): the hinge is exactly at its limit
    // there, the state is the engine's own at that instant, bit for bit,
    // and the frames either side stay as they were.
    void anEventIsShownAtItsInstant() {
        const jl::Scene scene = loadExample("classic.yaml");
        Fixture f(scene);
        // A run straight through on the engine, stopping at each event:
        // the first lock after the first keyframe (0.5 s) that is not undone
        // at the same instant, and the state there.
        auto built = jl::Simulation::build(scene);
        jl::Simulation& engine = *built.simulation;
        std::optional<jl::Event> lock;
        std::optional<jl::Frame> atLock;
        while (!lock && engine.time() < 3.0) {
            QVERIFY(engine.advanceToNextEvent(3.0) || engine.time() >= 3.0);
            const std::vector<jl::Event> events = engine.takeEvents();
            for (const jl::Event& e : events)
                if (e.kind == jl::EventKind::Lock && e.time > 0.55 && events.back().kind == jl::EventKind::Lock &&
                    !jl::FrameGrid{0, scene.solver.frameInterval}.on(e.time))
                    lock = e;
            if (lock) atLock = engine.frame();
        }
        QVERIFY(lock && atLock && engine.time() == lock->time);
        const double dt = scene.solver.frameInterval;
        const int before = int(std::floor(lock->time / dt));

        f.sim->showInstant(lock->time);
        QVERIFY(
            jl::test::waitForStatus(f.sim, [&](const SimStatus& s) { return s.frame && s.frame->time == lock->time; }));
        const auto s = f.sim->status();
        QCOMPARE(s->frameIndex, before);
        QVERIFY(!s->playing);
        QVERIFY(samePoses(*s->frame, *atLock));
        // The hinge is at its limit, locked end to end (fold angle 0); in the
        // frame before it was not yet.
        const jl::HingeFrame& h = s->frame->hinges[size_t(lock->hinge - 1)];
        QCOMPARE(h.mode, jl::HingeMode::OpenLocked);
        QVERIFY2(std::abs(h.foldAngle) < 1e-9, qPrintable(QString::number(h.foldAngle, 'g', 3)));
        const jl::Frame frameBefore = engineFrameAt(scene, before);
        const double foldBefore = frameBefore.hinges[size_t(lock->hinge - 1)].foldAngle;
        QVERIFY2(foldBefore > 1e-3, qPrintable(QString::number(foldBefore, 'g', 3)));
        qInfo("hinge %d locks at %.6f s; fold angle %.3g rad there, %.3g rad at the frame before (%.6f s)", lock->hinge,
              lock->time, h.foldAngle, foldBefore, jl::FrameGrid{0, dt}.at(before));
        // The frame carries what happened there, and the status bar says it.
        QVERIFY(!s->frame->events.empty());
        QCOMPARE(s->frame->events.front().time, lock->time);
        auto* note = f.window.findChild<QLabel*>("warning");
        QTRY_VERIFY(note->text().contains(QString::fromStdString(lock->text)));
        QVERIFY(note->text().startsWith(QString::number(lock->time, 'f', 3)));

        // Step back: the frame before the instant; forward twice: the frames after it.
        f.sim->stepBack();
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& st) {
            return st.frame->time == jl::FrameGrid{0, dt}.at(before);
        }));
        QVERIFY(samePoses(*f.sim->status()->frame, frameBefore));
        QTRY_VERIFY(note->text().isEmpty());
        f.sim->showInstant(lock->time);
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& st) { return st.frame->time == lock->time; }));
        f.sim->stepForward();
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus& st) { return st.frameIndex == before + 1 && st.frame->time != lock->time; }));
        QVERIFY(samePoses(*f.sim->status()->frame, engineFrameAt(scene, before + 1)));
        // Chosen while playing: it pauses there (a still, not a frame to play on from at once).
        f.sim->play();
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& st) { return st.playing; }));
        f.sim->showInstant(lock->time);
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& st) { return st.frame->time == lock->time; }));
        QTest::qWait(200);
        QVERIFY(!f.sim->status()->playing);
        QCOMPARE(f.sim->status()->frame->time, lock->time);
    }

    // On a long ladder, going to an instant re-runs up to half a second from
    // the keyframe before it: the status says where it is going meanwhile.
    void goingToAnInstantSaysWhereItIsGoing() {
        Fixture f(slowHangingLadder(3000));
        QVERIFY(f.goTo(40, 120000));
        auto* rate = f.window.findChild<QLabel*>("rate");
        const double instant = 0.6601;  // between frames 39 and 40, 0.16 s after the keyframe at 0.5 s
        f.sim->showInstant(instant);
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& s) { return s.seekingTo == instant; }));
        QTRY_VERIFY2(rate->text().startsWith("running to t = 0.660 s ("), qPrintable(rate->text()));
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus& s) { return s.frame->time == instant && s.seekingTo < 0; }));
        QTRY_COMPARE(rate->text(), QString("paused between frames 39 and 40"));
    }

    // The scene's duration is the lesson's length: playing stops there (the
    // classic cascade used to run on to 40 s), and Play goes on past it.
    void playingStopsAtTheScenesDurationThenGoesOnWhenAsked() {
        Fixture f(halfSecondLesson());
        QVERIFY(playToTheEnd(f));
        const auto end = f.sim->status();
        QVERIFY2(std::abs(end->frame->time - 0.5) <= end->interval, qPrintable(QString::number(end->frame->time)));
        f.sim->play();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frame && s.frame->time > 0.6; }));
    }

    // A run with no events at all (the pendulum) is plotted to its end:
    // the curves followed the frames only while events came (a new event
    // redrew the charts), and stopped a few tenths of a second in.
    void thePlotsFollowARunWithoutEventsToItsEnd() {
        jl::SceneLoad load = jl::loadScene(JL_SOURCE_DIR "/examples/pendulum.yaml");
        QVERIFY(load.scene);
        load.scene->duration = 1.0;
        Fixture f(*load.scene);
        f.sim->play();  // at 1x, as a class watches it
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frame && s.frame->time > 0.1; }));
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        QVERIFY(f.sim->status()->events->empty());
        auto* plots = f.window.findChild<RunPlots*>();
        QVERIFY(plots);
        const double end = f.sim->status()->headTime, dt = f.sim->status()->interval;
        QTRY_VERIFY(plots->traces().endTime() >= end - dt / 2);
        const auto* kinetic = qobject_cast<const QLineSeries*>(plots->energyChart()->chart()->series().value(0));
        QVERIFY(kinetic);
        QTRY_VERIFY2(!kinetic->points().isEmpty() && kinetic->points().back().x() >= end - dt / 2,
                     qPrintable(QString("the curve ends at %1 s, the run at %2 s")
                                    .arg(kinetic->points().isEmpty() ? 0.0 : kinetic->points().back().x())
                                    .arg(end)));
        // What the screen shows is what a fresh drawing of the chart shows.
        TimeChart* chart = plots->energyChart();
        QTest::qWait(300);  // past the plots' refresh
        const int differing = jl::test::pixelsOffAFreshDrawing(chart);
        QVERIFY2(differing == 0, qPrintable(QString("%1 pixels on screen differ from a fresh drawing").arg(differing)));
    }

    // The timeline of a 0.5 s lesson ends at 0.5 s (it was drawn to 0.75 s,
    // an empty tail), and once the run goes on past it, at the run's end.
    void theTimelineEndsAtTheScenesDurationOrTheRunsEnd() {
        Fixture f(halfSecondLesson());
        QVERIFY(playToTheEnd(f));
        auto* timeline = f.window.findChild<Timeline*>();
        QVERIFY(timeline);
        const double right = timeline->width() - 8;  // the track's right end
        QCOMPARE(f.sim->status()->headTime, 0.5);
        QTRY_COMPARE(timeline->xOf(0.5), right);  // once the timeline has the run's end
        QCOMPARE(timeline->labels().back().text, QString("0.5 s"));
        // The plots' time axis ends there too.
        auto* plots = f.window.findChild<RunPlots*>();
        QVERIFY(plots);
        const auto* axis = qobject_cast<QValueAxis*>(plots->energyChart()->chart()->axes(Qt::Horizontal).value(0));
        QVERIFY(axis);
        QTRY_COMPARE(axis->max(), 0.5);
        // A click near the right end, off any event's mark, shows the last frames.
        int x = int(right) - 1;
        while (timeline->eventNear(x)) --x;
        const double dt = f.sim->status()->interval;
        const double expected = 0.5 * (x - 8) / (right - 8);  // the time under x
        QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(x, timeline->height() / 3));
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& s) {
            return s.seekingTo < 0 && s.frame && s.frame->time < 0.5 - 1e-9 && std::abs(s.frame->time - expected) <= dt;
        }));
        f.sim->play();  // the last frames: it stops at the end again, then goes on past it
        QVERIFY(jl::test::waitForStatus(
            f.sim, [](const SimStatus& s) { return !s.playing && s.frame && s.frame->time > 0.5 - 1e-9; }));
        f.sim->play();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frame && s.frame->time > 0.6; }));
        f.sim->pause();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        QTRY_COMPARE(timeline->xOf(f.sim->status()->headTime), right);
    }

    // At the scene's end, an edit runs the scene again up to there; one click
    // on Play then goes on (it took two: the first stopped at the end again).
    // The duration has a field of its own, and changing it runs nothing again.
    void anEditAtTheEndThenOneClickOnPlayGoesOn() {
        Fixture f(halfSecondLesson());
        QVERIFY(playToTheEnd(f));
        const auto before = f.editThickness(14);
        QVERIFY(jl::test::loadedAfter(f.sim, before));
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) {
            return s.frame && std::abs(s.frame->time - 0.5) <= s.interval && s.seekingTo < 0;
        }));
        auto* bar = f.window.findChild<QToolBar*>("mainToolBar");
        QVERIFY(bar);
        // Play and Pause are one action (Space) whose words follow the
        // worker's state: the status that ends the rerun may reach the
        // window a moment after its last frame, so wait for the words.
        QAction* play = nullptr;
        for (QAction* a : bar->actions())
            if (a->shortcut() == QKeySequence(Qt::Key_Space)) play = a;
        QVERIFY(play);
        QTRY_COMPARE(play->text(), QString("&Play"));
        QTest::mouseClick(bar->widgetForAction(play), Qt::LeftButton);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.frame && s.frame->time > 0.6; }));

        // The duration, typed into its field: one undo step, the lesson now ends at 1.2 s.
        auto* field = f.window.findChild<QDoubleSpinBox*>("duration");
        QVERIFY(field);
        const auto loads = jl::test::loadsSoFar(f.sim);
        field->selectAll();
        QTest::keyClicks(field, "1.2");
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(f.window.document()->scene().duration, 1.2);
        QCOMPARE(f.window.document()->undoStack()->undoText(), QString("Change duration"));
        QTest::qWait(200);
        QCOMPARE(jl::test::loadsSoFar(f.sim), loads);  // nothing ran again
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        const auto end = f.sim->status();
        QVERIFY2(std::abs(end->frame->time - 1.2) <= end->interval, qPrintable(QString::number(end->frame->time)));
        f.window.document()->undoStack()->undo();
        QCOMPARE(f.window.document()->scene().duration, 0.5);
    }

    void aFailedSolvePausesAndSaysWhyWithTheLastGoodFrame() {
        // Explicit Euler with 10 ms steps: the solver gives up within half a second.
        jl::Scene scene = jl::test::swingingLadder();
        scene.solver.integrator = jl::Integrator::ExplicitEuler;
        scene.solver.step = 0.01;
        Fixture f(scene);
        f.window.setSpeed(4.0);
        f.sim->play();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.failure.empty(); }));
        const auto s = f.sim->status();
        QVERIFY(!s->playing);
        // The same failure, in the same words, as the engine run on its own.
        auto alone = jl::Simulation::build(scene).simulation;
        QVERIFY(!alone->advanceTo(2.0));
        QCOMPARE(s->failure, alone->failure());
        // On screen: the last frame recorded before the failure, nothing past it.
        QCOMPARE(s->frameIndex, s->frameCount - 1);
        QVERIFY(s->frame->failure.empty());
        qInfo("failed after the frame at %.3f s: %s", s->frame->time, s->failure.c_str());
        QVERIFY(s->frame->time > 0 && s->frame->time < 1.0);
        auto* warning = f.window.findChild<QLabel*>("warning");
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus&) { return warning->text().contains(QString::fromStdString(s->failure)); }));
        // Shown whole: the status bar cuts it off (the advice at the end), so
        // a message that does not block the window says all of it.
        QMessageBox* box = nullptr;
        QTRY_VERIFY((box = f.window.findChild<QMessageBox*>("failureMessage")) && box->isVisible());
        QVERIFY(!box->isModal());
        QCOMPARE(box->informativeText(), QString::fromStdString(s->failure));
        // The step the run uses is on show too.
        QVERIFY(f.window.findChild<QLabel*>("step")->text().contains("10 ms"));
        // Play does nothing more until the scene changes.
        f.sim->play();
        QTest::qWait(200);
        QVERIFY(!f.sim->status()->playing);
        QCOMPARE(f.sim->status()->frameCount, s->frameCount);
    }
};

QTEST_MAIN(PlaybackTest)
#include "test_playback.moc"
