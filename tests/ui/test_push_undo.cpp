// labels: ui
// A push in the past, as a teacher makes it on a laptop's screen: the run
// is played to its end, paused in the middle, and a block is dragged there
// with the mouse. The future from that instant is computed anew, and the
// run it replaced is not lost: Ctrl+Z brings it back, every frame the very
// one computed before (not computed again), and Ctrl+Y or Ctrl+Shift+Z the
// pushed run, the same way.
#include "playback_fixture.h"
#include "ui/play/timeline.h"

using namespace jl::test;

namespace {

// What a run on record is, to compare it with the same run brought back:
// its length, its last state, its events and one of its later frames.
struct RunOnRecord {
    int frames = 0;
    double headTime = 0;
    std::uint64_t headHash = 0;
    std::vector<double> eventTimes;
    std::shared_ptr<const jl::Frame> later;  // the frame object itself
};

constexpr int kLater = 100;  // a frame after the push, 1.67 s

}  // namespace

class PushUndoTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void undoBringsBackTheRunAPushReplaced() {
        const jl::Scene scene = jl::test::swingingLadder();  // 2 s long
        Fixture f(scene);
        MainWindow& window = f.window;
        SimController* sim = f.sim;
        window.showMaximized();  // the whole of a 1440 x 900 screen
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        QTRY_VERIFY(window.width() >= 1400);
        LadderView* view = window.ladderView();
        auto* timeline = window.findChild<Timeline*>();
        QVERIFY(view && timeline);
        QVERIFY(QTest::qWaitForWindowExposed(view));

        // Play: the lesson stops at its end, 2 s.
        QVERIFY(jl::test::clickToolButton(window, "&Play"));
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return !s.playing && s.frameIndex == 120; }));
        const RunOnRecord first = onRecord(sim, timeline);
        QCOMPARE(first.frames, 121);
        QVERIFY(!first.eventTimes.empty());
        QVERIFY(samePoses(*first.later, engineFrameAt(scene, kLater)));

        // Paused in the middle, a push on block 3 held while five frames
        // are made (Step forward), the hand moving.
        QVERIFY(clickTimeline(sim, timeline, 1.0));
        const int pushedAt = sim->status()->frameIndex;
        const auto on = f.blockOnScreen(3);
        QVERIFY(on);
        QTest::mousePress(view, Qt::LeftButton, {}, *on);
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return s.dragging; }));
        for (int i = 1; i <= 5; ++i) {
            QTest::mouseMove(view, *on + QPoint(16 * i, -8 * i));
            QVERIFY(jl::test::clickToolButton(window, "Step &forward"));
            QVERIFY(jl::test::waitForStatus(sim, [&](const SimStatus& s) { return s.frameIndex == pushedAt + i; }));
        }
        QTest::mouseRelease(view, Qt::LeftButton, {}, *on + QPoint(80, -40));
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return !s.dragging; }));
        QTRY_COMPARE(window.document()->scene().drags.size(), size_t(1));
        QCOMPARE(window.document()->undoStack()->undoText(), QString("Push a block"));

        // The future from the push is computed anew, and differs.
        QVERIFY(jl::test::clickToolButton(window, "&Play"));
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return !s.playing && s.frameIndex == 120; }));
        const RunOnRecord pushed = onRecord(sim, timeline);
        QCOMPARE(pushed.frames, 121);
        QVERIFY(pushed.headHash != first.headHash);
        const double moved = (pushed.later->poses[3].position - first.later->poses[3].position).norm();
        QVERIFY2(moved > 1e-3, qPrintable(QString("block 3 moved %1 m").arg(moved)));

        // Back in the middle (before the push), Ctrl+Z: the first run, whole.
        QVERIFY(clickTimeline(sim, timeline, 0.5));
        QTest::keyClick(view, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(broughtBack(sim, first, 0));
        QCOMPARE(window.document()->scene().drags.size(), size_t(0));
        QVERIFY(sameRun(sim, timeline, first));

        // Ctrl+Y and Ctrl+Shift+Z: the pushed run, whole.
        QTest::keyClick(view, Qt::Key_Y, Qt::ControlModifier);
        QVERIFY(broughtBack(sim, pushed, 1));
        QVERIFY(sameRun(sim, timeline, pushed));
        QTest::keyClick(view, Qt::Key_Z, Qt::ControlModifier);
        QVERIFY(broughtBack(sim, first, 0));
        QTest::keyClick(view, Qt::Key_Z, Qt::ControlModifier | Qt::ShiftModifier);
        QVERIFY(broughtBack(sim, pushed, 1));
        QVERIFY(sameRun(sim, timeline, pushed));
    }

private:
    // A press on the timeline at `t` (off any event's mark): that frame on screen.
    static bool clickTimeline(SimController* sim, Timeline* timeline, double t) {
        int x = int(std::lround(timeline->xOf(t)));
        while (timeline->eventNear(x)) ++x;
        QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(x, timeline->height() / 3));
        const double dt = sim->status()->interval;
        return jl::test::waitForStatus(sim, [&](const SimStatus& s) {
            return !s.playing && s.seekingTo < 0 && std::abs(s.frameIndex * dt - t) < 0.1;
        });
    }

    // The run on record, its frame kLater looked at on the timeline.
    static RunOnRecord onRecord(SimController* sim, Timeline* timeline) {
        RunOnRecord r;
        const auto s = sim->status();
        r.frames = s->frameCount;
        r.headTime = s->headTime;
        r.headHash = s->headHash;
        for (const jl::Event& e : *s->events) r.eventTimes.push_back(e.time);
        if (clickTimeline(sim, timeline, kLater * s->interval)) r.later = sim->status()->frame;
        if (!r.later || r.later->time != jl::FrameGrid{0, s->interval}.at(sim->status()->frameIndex)) r.later.reset();
        return r;
    }

    // The run `r` (with `drags` drags) is back, with no frame to compute:
    // whole as soon as it is there, never running to a moment.
    static bool broughtBack(SimController* sim, const RunOnRecord& r, size_t drags) {
        bool ranAgain = false;
        const bool back = jl::test::waitForStatus(sim, [&](const SimStatus& s) {
            ranAgain = ranAgain || s.seekingTo >= 0;
            return s.recorded && s.recorded->drags.size() == drags && s.frameCount == r.frames;
        });
        const auto s = sim->status();
        if (!back || ranAgain)
            qWarning("brought back: %d; ran again: %d; %d frames of %d", back, ranAgain, s->frameCount, r.frames);
        return back && !ranAgain && s->headTime == r.headTime && s->headHash == r.headHash;
    }

    // The run on screen is `r`: its events, and its later frame the very
    // object computed the first time (a run computed again makes new ones).
    static bool sameRun(SimController* sim, Timeline* timeline, const RunOnRecord& r) {
        std::vector<double> times;
        for (const jl::Event& e : *sim->status()->events) times.push_back(e.time);
        if (times != r.eventTimes) return false;
        const auto again = onRecord(sim, timeline);
        if (!again.later || !r.later) return false;
        if (again.later != r.later)
            qWarning("frame %d at %.17g s is another object (the same poses: %d)", kLater, again.later->time,
                     samePoses(*again.later, *r.later));
        return again.later == r.later && again.frames == r.frames;
    }
};

QTEST_MAIN(PushUndoTest)
#include "test_push_undo.moc"
