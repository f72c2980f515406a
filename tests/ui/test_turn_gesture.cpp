// labels: ui
// The toy's famous move with the mouse: Shift and a drag on a block turns
// it. The angle snaps to a quarter turn, the turn takes as long as the hand
// took, and it is a script row: undoable, and replayed bit for bit.
#include "playback_fixture.h"
#include "ui/edit/document.h"
#include "ui/edit/turn_gesture.h"
#include "ui/teaching/side_view.h"
#include "ui/teaching/teaching_docks.h"

#include <QDockWidget>
#include <QUndoStack>

#include <cmath>
#include <numbers>

using namespace jl::test;
using jl::ui::TurnGesture;

namespace {
constexpr double kPi = std::numbers::pi;
}

class TurnGestureTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    // The sweep adds up the short way round at each move, so one and a
    // half turns are 540 degrees, not 180; it snaps to the nearest quarter
    // turn and takes the hand's time for the snapped angle, from the last
    // still moment before the sweep to its last move: waits before and
    // after do not count.
    void aSweepSnapsToQuarterTurnsAtTheHandsSpeed() {
        const jl::Vec2 c(1, 2);
        const auto at = [&](double degrees) -> jl::Vec2 {
            return c + 0.01 * jl::Vec2(std::cos(degrees * kPi / 180), std::sin(degrees * kPi / 180));
        };
        TurnGesture g(3, c, at(0));
        g.moveTo(at(0), 2.0);  // held still for 2 s after the press
        for (int k = 1; k <= 27; ++k) g.moveTo(at(10 * k), 2.0 + 0.6 * k / 27);
        g.moveTo(at(270), 5.0);                            // and 2.4 s before the release
        QVERIFY(std::abs(g.swept() - 1.5 * kPi) < 1e-12);  // 270 degrees
        const auto turn = g.turn();
        QVERIFY(turn);
        QCOMPARE(turn->block, 3);
        QCOMPARE(turn->angle, 1.5 * kPi);
        QVERIFY(std::abs(turn->duration - 0.6) < 1e-12);
        QCOMPARE(TurnGesture::snapped(2.0), kPi / 2);  // 115 degrees -> 90
        QCOMPARE(TurnGesture::snapped(2.5), kPi);      // 143 degrees -> 180
        QCOMPARE(TurnGesture::snapped(-3.5), -kPi);    // clockwise
        QVERIFY(!TurnGesture(0, c, at(0)).turn());     // no sweep, no turn
        TurnGesture flick(0, c, at(0));
        flick.moveTo(at(90), 0.001);
        QCOMPARE(flick.turn()->duration, TurnGesture::kShortest);
        TurnGesture slow(0, c, at(0));
        slow.moveTo(at(90), 60);
        QCOMPARE(slow.turn()->duration, TurnGesture::kLongest);
    }

    // In the 3-D view, on the held block of a paused run: half a turn
    // counter-clockwise in the plane becomes a script row at the frame
    // shown, the run from there turns the block, undo takes it away.
    void shiftAndADragOnABlockTurnsIt() {
        const jl::Scene scene = jl::test::swingingLadder();
        Fixture f(scene);
        LadderView* view = f.window.ladderView();
        QVERIFY(QTest::qWaitForWindowExposed(view));
        QVERIFY(f.goTo(10));
        const double shownTime = f.sim->status()->frame->time;
        QVERIFY(QTest::qWaitFor([&] { return view->shownTime() == shownTime; }));
        QVERIFY(f.blockOnScreen(0));
        const jl::Pose pose = f.sim->status()->frame->poses[0];
        // A point 20 mm along the block from its centre, swept about it.
        const auto pixel = [&](double turned) {
            const jl::Vec2 arm = jl::rotate(pose.angle + turned, jl::Vec2(0, 0.02));
            return view->pixelOf(pose.position + arm).toPoint();
        };
        QTest::mousePress(view, Qt::LeftButton, Qt::ShiftModifier, pixel(0));
        for (int k = 1; k <= 12; ++k) QTest::mouseMove(view, pixel(k * kPi / 12));
        QTest::mouseRelease(view, Qt::LeftButton, Qt::ShiftModifier, pixel(kPi));

        jl::ui::Document* doc = f.window.document();
        QCOMPARE(int(doc->scene().script.size()), int(scene.script.size()) + 1);
        const jl::ScriptAction& turn = doc->scene().script.back();
        QVERIFY(turn.kind == jl::ScriptAction::Kind::Turn);
        QCOMPARE(turn.block, 0);
        QCOMPARE(turn.angle, kPi);
        QCOMPARE(turn.at, shownTime);
        QVERIFY(turn.duration >= TurnGesture::kShortest && turn.duration <= TurnGesture::kLongest);
        QVERIFY(!f.sim->status()->dragging);  // a turn, not a push

        // The run from there is the scene's, turned: bit for bit.
        const jl::Scene turned = doc->scene();
        QVERIFY(f.goTo(40));
        QCOMPARE(f.sim->status()->headHash, engineHashAt(turned, 40));
        QVERIFY(engineHashAt(scene, 40) != engineHashAt(turned, 40));

        doc->undoStack()->undo();
        QCOMPARE(doc->scene().script.size(), scene.script.size());
    }

    // The same in the side view: a quarter turn clockwise on block 0.
    void shiftAndADragInTheSideViewTurnsIt() {
        const jl::Scene scene = jl::test::swingingLadder();
        Fixture f(scene);
        QVERIFY(QTest::qWaitForWindowExposed(&f.window));
        jl::ui::SideView* side = f.window.teaching()->sideView();
        f.window.teaching()->sideViewDock()->show();
        QVERIFY(f.goTo(10));
        const double shown = f.sim->status()->frame->time;
        QVERIFY(QTest::qWaitFor([&] { return side->isVisible() && side->frame().time == shown; }));
        const jl::Pose pose = side->frame().poses[0];
        const double shownTime = side->frame().time;
        const auto pixel = [&](double turned) {
            const jl::Vec2 arm = jl::rotate(pose.angle + turned, jl::Vec2(0, 0.02));
            return side->pixelOf(pose.position + arm, side->rect()).toPoint();
        };
        QCOMPARE(side->blockAt(side->planePoint(pixel(0))), 0);
        QTest::mousePress(side, Qt::LeftButton, Qt::ShiftModifier, pixel(0));
        for (int k = 1; k <= 6; ++k) QTest::mouseMove(side, pixel(-k * kPi / 12));
        QTest::mouseRelease(side, Qt::LeftButton, Qt::ShiftModifier, pixel(-kPi / 2));
        const auto& script = f.window.document()->scene().script;
        QCOMPARE(int(script.size()), int(scene.script.size()) + 1);
        QCOMPARE(script.back().block, 0);
        QCOMPARE(script.back().angle, -kPi / 2);
        QCOMPARE(script.back().at, shownTime);
    }
};

QTEST_MAIN(TurnGestureTest)
#include "test_turn_gesture.moc"
