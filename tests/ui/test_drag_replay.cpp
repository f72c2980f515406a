// labels: ui
// The user's hand in a running simulation: a mouse drag on a block pulls it
// with a spring that is drawn, is recorded into the scene and replays bit
// for bit, rewrites the run from an earlier frame, and grabs the block as
// the window showed it while the worker runs ahead.
#include "playback_fixture.h"

using namespace jl::test;

class DragReplayTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void aMouseDragChangesTheMotionAndReplaysBitIdentically() {
        const jl::Scene scene = jl::test::swingingLadder();
        Fixture f(scene);
        LadderView* view = f.window.ladderView();
        QVERIFY(QTest::qWaitForWindowExposed(view));
        QVERIFY(f.goTo(12));
        const jl::Vec2 centre = f.sim->status()->frame->poses[3].position;
        const auto on = f.blockOnScreen(3);
        QVERIFY(on);
        const QPoint at = *on;
        QVERIFY(((*view->planePoint(at)) - centre).norm() < 0.003);  // picking ray hits where the block is

        QTest::mousePress(view, Qt::LeftButton, {}, at);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.dragging && s.frame->dragging; }));
        QVERIFY(f.goTo(20));
        QTest::mouseMove(view, at + QPoint(80, -40));
        QVERIFY(f.goTo(30));
        // The spring is drawn: a red line from the block to the hand.
        auto redPixels = [&] {
            const QImage image = jl::test::captureView(view);
            int n = 0;
            for (int y = 0; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    n += c.red() > 180 && c.green() < 80 && c.blue() < 80;
                }
            return n;
        };
        QVERIFY2(redPixels() > 30, "no drag line drawn");
        QTest::mouseRelease(view, Qt::LeftButton, {}, at + QPoint(80, -40));
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.dragging; }));
        QVERIFY(f.goTo(60));
        QCOMPARE(redPixels(), 0);  // released: no line
        const auto s = f.sim->status();
        QCOMPARE(int(s->recorded->drags.size()), 1);
        QCOMPARE(s->recorded->drags[0].block, 3);
        QVERIFY(s->recorded->drags[0].samples.size() >= 2);

        // The push changed the motion...
        const jl::Frame without = engineFrameAt(scene, 60);
        const double diff = (without.poses[3].position - s->frame->poses[3].position).norm();
        QVERIFY2(diff > 0.001, qPrintable(QString("block 3 differs by %1 m").arg(diff)));
        // ...and the recorded scene replays it exactly.
        QCOMPARE(engineHashAt(*s->recorded, 60), s->headHash);
        QVERIFY(engineHashAt(scene, 60) != s->headHash);
        // The drag is part of the document now (saved with it, undoable).
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus&) { return f.window.document()->scene().drags == s->recorded->drags; }));
        QVERIFY(f.window.document()->isModified());
    }

    // A push at an earlier frame rewrites the run from that frame: the block
    // grabbed is the one shown there, and the recorded scene replays it.
    void aDragAtAnEarlierFrameRewritesTheRunFromThere() {
        const jl::Scene scene = jl::test::swingingLadder();
        Fixture f(scene);
        LadderView* view = f.window.ladderView();
        QVERIFY(QTest::qWaitForWindowExposed(view));
        QVERIFY(f.goTo(45));
        QVERIFY(f.goTo(12));
        const auto on = f.blockOnScreen(3);
        QVERIFY(on);
        const QPoint at = *on;
        QTest::mousePress(view, Qt::LeftButton, {}, at);
        const bool pressed = jl::test::waitForStatus(
            f.sim, [](const SimStatus& s) { return s.dragging && s.frameCount == 13 && s.frameIndex == 12; });
        const auto p = f.sim->status();
        QVERIFY2(pressed, qPrintable(QString("dragging %1, frame %2 of %3, %4")
                                         .arg(p->dragging)
                                         .arg(p->frameIndex)
                                         .arg(p->frameCount)
                                         .arg(QString::fromStdString(p->failure))));
        QCOMPARE(f.sim->status()->recorded->drags.size(), size_t(0));  // recorded when it ends
        QVERIFY(f.goTo(20));
        QTest::mouseMove(view, at + QPoint(60, -30));
        QVERIFY(f.goTo(30));
        QTest::mouseRelease(view, Qt::LeftButton, {}, at + QPoint(60, -30));
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.dragging; }));
        QVERIFY(f.goTo(60));
        const auto s = f.sim->status();
        QCOMPARE(int(s->recorded->drags.size()), 1);
        QCOMPARE(s->recorded->drags[0].block, 3);
        // From the end of the step that passes frame 12 (a step is 1 ms here).
        const double frame12 = jl::FrameGrid{0, s->interval}.at(12);
        QVERIFY(s->recorded->drags[0].samples.front().t >= frame12);
        QVERIFY(s->recorded->drags[0].samples.front().t < frame12 + 0.001 + 1e-12);
        QCOMPARE(engineHashAt(*s->recorded, 60), s->headHash);
        QVERIFY(samePoses(*s->frame, engineFrameAt(*s->recorded, 60)));

        // Back inside that drag: a second push there cuts the first one short
        // (the run is rebuilt from the scene with the drag cut) and replays too.
        QVERIFY(f.goTo(25));
        const auto on2 = f.blockOnScreen(2);
        QVERIFY(on2);
        const QPoint at2 = *on2;
        QTest::mousePress(view, Qt::LeftButton, {}, at2);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& st) { return st.dragging && st.frameCount == 26; }));
        QVERIFY(f.goTo(40));
        QTest::mouseRelease(view, Qt::LeftButton, {}, at2 + QPoint(-50, 0));
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& st) { return !st.dragging; }));
        QVERIFY(f.goTo(70));
        const auto again = f.sim->status();
        QCOMPARE(int(again->recorded->drags.size()), 2);
        const double frame25 = jl::FrameGrid{0, again->interval}.at(25);
        QCOMPARE(again->recorded->drags[0].end, frame25);
        QCOMPARE(again->recorded->drags[1].block, 2);
        QCOMPARE(engineHashAt(*again->recorded, 70), again->headHash);
        QVERIFY(samePoses(*again->frame, engineFrameAt(*again->recorded, 70)));
    }

    // The window draws the worker's frames a moment after the worker makes
    // them, and playing moves on meanwhile: a press grabs the block as the
    // window showed it, in the frame it showed, not where the block is in
    // the frame the worker has reached.
    void aPushLandsInTheFrameOnScreenWhenTheWorkerIsAhead() {
        const jl::Scene scene = jl::test::swingingLadder();
        Fixture f(scene);
        LadderView* view = f.window.ladderView();
        QVERIFY(QTest::qWaitForWindowExposed(view));
        QVERIFY(f.goTo(30));
        // The window still shows frame 12 while the worker is at frame 30.
        const jl::Frame frame12 = engineFrameAt(scene, 12);
        view->showFrame(frame12);
        const QPoint at = view->pixelOf(frame12.poses[3].position).toPoint();
        const auto plane = view->planePoint(at);
        QVERIFY(plane);
        const auto grab = view->grabAt(*plane);
        QVERIFY(grab && grab->block == 3);
        QTest::mousePress(view, Qt::LeftButton, {}, at);
        QVERIFY(jl::test::waitForStatus(
            f.sim, [](const SimStatus& s) { return s.dragging && s.frameCount == 13 && s.frameIndex == 12; }));
        QVERIFY(f.goTo(20));
        QTest::mouseRelease(view, Qt::LeftButton, {}, at + QPoint(40, 0));
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.dragging; }));
        QVERIFY(f.goTo(40));
        const auto s = f.sim->status();
        QCOMPARE(int(s->recorded->drags.size()), 1);
        const jl::DragRecord& d = s->recorded->drags[0];
        QCOMPARE(d.block, 3);
        QCOMPARE(d.point[0], grab->local.x());
        QCOMPARE(d.point[1], grab->local.y());
        const double t12 = jl::FrameGrid{0, s->interval}.at(12);
        QVERIFY(d.samples.front().t >= t12 && d.samples.front().t < t12 + 0.001 + 1e-12);
        QCOMPARE(engineHashAt(*s->recorded, 40), s->headHash);
    }

    // Playing on time, the worker has made frames ahead of the one on
    // screen and keeps them back (sim_worker_ahead.cpp): a push in the
    // frame the worker is at starts from the run as recorded up to it,
    // and the recorded scene replays the run it makes. (With the head
    // simulation left ahead, the run stopped: the frame it asked for was
    // behind it.)
    void aPushWhilePlayingReplaysBitIdentically() {
        jl::Scene scene = jl::test::swingingLadder();
        scene.duration = 60;
        Fixture f(scene);
        f.sim->play();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.playing && s.frameIndex >= 20; }));
        const jl::Vec2 centre = f.sim->status()->frame->poses[3].position;
        f.sim->beginDrag(centre, 3, jl::Vec2::Zero());
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.dragging; }));
        QTest::qWait(200);
        f.sim->moveDrag(centre + jl::Vec2(0.05, 0.02));
        QTest::qWait(200);
        f.sim->endDrag();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.dragging; }));
        QVERIFY(jl::test::waitForStatus(f.sim,
                                        [](const SimStatus& s) { return s.frameIndex >= 70 || !s.failure.empty(); }));
        f.sim->pause();
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        const auto s = f.sim->status();
        QVERIFY2(s->failure.empty(), s->failure.c_str());
        QCOMPARE(int(s->recorded->drags.size()), 1);
        QCOMPARE(engineHashAt(*s->recorded, s->frameCount - 1), s->headHash);
        QVERIFY(samePoses(*s->frame, engineFrameAt(*s->recorded, s->frameIndex)));
    }
};

QTEST_MAIN(DragReplayTest)
#include "test_drag_replay.moc"
