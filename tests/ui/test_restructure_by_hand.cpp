// labels: ui
// Restructuring by hand, with the mouse and keys on the real views: a
// click by a hinge and Delete (or the menu) cuts it, a block's menu holds
// or releases it, a free corner dragged onto another joins them. Each is a
// script row at the instant shown: undoable, and a saved file replays it
// bit for bit.
#include "jl/ladder/block_corners.h"
#include "playback_fixture.h"
#include "ui/edit/document.h"
#include "ui/teaching/side_view.h"
#include "ui/teaching/teaching_docks.h"

#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QTemporaryDir>
#include <QUndoStack>

using namespace jl::test;
using Kind = jl::ScriptAction::Kind;

namespace {

// The scene's swinging ladder, its hinge 2 cut at 0.05 s: block 2 falls free.
jl::Scene cutLadder() {
    jl::Scene scene = swingingLadder(3);
    jl::ScriptAction cut;
    cut.kind = Kind::Cut;
    cut.at = 0.05;
    cut.hinge = 2;
    scene.script.push_back(cut);
    return scene;
}

// The menu the last right click opened.
QMenu* openMenu() {
    QMenu* menu = nullptr;
    const bool open = QTest::qWaitFor([&] {
        menu = qobject_cast<QMenu*>(QApplication::activePopupWidget());
        return menu && menu->isVisible();
    });
    return open ? menu : nullptr;
}
// A right click at `at` in either view, and the menu it opened.
template <typename View>
QMenu* menuAt(View* view, const QPoint& at) {
    QTest::mouseClick(view, Qt::RightButton, {}, at);
    return openMenu();
}
QStringList itemsOf(QMenu* menu) {
    QStringList items;
    for (QAction* a : menu->actions()) items << a->text();
    return items;
}
// Clicks the item, as a hand does.
bool choose(QMenu* menu, const QString& text) {
    for (QAction* a : menu->actions())
        if (a->text() == text) {
            QTest::mouseClick(menu, Qt::LeftButton, {}, menu->actionGeometry(a).center());
            return true;
        }
    return false;
}

// The window at a laptop's size, paused at frame `index` of `scene`: `t`
// is that frame's time once both views show it (else -1).
struct Hand : Fixture {
    const jl::Scene scene;
    double t = -1;
    Hand(const jl::Scene& s, int index) : Fixture(s), scene(s) {
        window.resize(1440, 900);
        t = showFrame(index);
    }
    jl::ui::SideView* side() { return window.teaching()->sideView(); }
    // Paused at frame `index`, shown by both views; its time.
    double showFrame(int index) {
        window.teaching()->sideViewDock()->show();
        if (!QTest::qWaitForWindowExposed(window.ladderView()) || !goTo(index)) return -1;
        const double t = sim->status()->frame->time;
        const bool shown = QTest::qWaitFor(
            [&] { return window.ladderView()->shownTime() == t && side()->isVisible() && side()->frame().time == t; });
        return shown ? t : -1;
    }
    const std::vector<jl::ScriptAction>& script() { return window.document()->scene().script; }
    QPoint inView(const jl::Vec2& p) { return window.ladderView()->pixelOf(p).toPoint(); }
    QPoint inSide(const jl::Vec2& p) { return side()->pixelOf(p, side()->rect()).toPoint(); }
    jl::Vec2 corner(int block, int k) {
        const auto local = jl::blockCorners(*window.document()->scene().ladder);
        return sim->status()->frame->poses[size_t(block)].apply(local[size_t(block)][size_t(k)]);
    }
    // The run of the edited scene, saved and opened again, is the engine's
    // run of that scene at frame `index`, bit for bit.
    bool replaysFromFile(int index) {
        const jl::Scene edited = window.document()->scene();
        QTemporaryDir dir;
        const QString path = dir.filePath("edited.yaml");
        if (!window.saveTo(path)) return false;
        const auto before = loadsSoFar(sim);
        if (!window.openFile(path) || !loadedAfter(sim, before)) return false;
        if (window.document()->scene().script != edited.script || !goTo(index)) return false;
        return sim->status()->headHash == engineHashAt(edited, index);
    }
};

}  // namespace

class RestructureByHandTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { isolateSettings(); }

    // 3-D view: a click on hinge 2 selects it (no push begins), Delete
    // cuts it at the instant shown; the blocks below fall away.
    void aClickAndDeleteCutsAHingeInThe3DView() {
        Hand f(swingingLadder(), 10);
        QVERIFY(f.t > 0);
        LadderView* view = f.window.ladderView();
        QTest::mouseClick(view, Qt::LeftButton, {}, f.inView(f.sim->status()->frame->hinges[1].position));
        QVERIFY(!f.sim->status()->dragging);
        QVERIFY(f.window.document()->scene().drags.empty());
        QCOMPARE(f.script().size(), f.scene.script.size());  // selected, not cut yet
        QTest::keyClick(view, Qt::Key_Delete);
        QCOMPARE(f.script().size(), f.scene.script.size() + 1);
        const jl::ScriptAction& cut = f.script().back();
        QVERIFY(cut.kind == Kind::Cut);
        QCOMPARE(cut.hinge, 2);
        QCOMPARE(cut.at, f.t);
        // The run from there has the hinge cut, as the engine's of the edited scene.
        QVERIFY(f.goTo(40));
        QVERIFY(f.sim->status()->frame->hinges[1].mode == jl::HingeMode::Cut);
        QVERIFY(engineHashAt(f.scene, 40) != engineHashAt(f.window.document()->scene(), 40));
        // One undo step; then, done again, saved and opened: the same run.
        f.window.document()->undoStack()->undo();
        QCOMPARE(f.script(), f.scene.script);
        f.window.document()->undoStack()->redo();
        QVERIFY(f.replaysFromFile(40));
    }

    // Side view: the right click's menu by hinge 1 offers its cut, and a
    // click there and Delete cut hinge 2; two undo steps.
    void theMenuAndDeleteCutHingesInTheSideView() {
        Hand f(swingingLadder(), 10);
        QVERIFY(f.t > 0);
        QMenu* menu = menuAt(f.side(), f.inSide(f.side()->frame().hinges[0].position));
        QVERIFY(menu && itemsOf(menu).contains("Cut hinge 1"));
        QVERIFY(choose(menu, "Cut hinge 1"));
        QCOMPARE(f.script().size(), f.scene.script.size() + 1);
        QVERIFY(f.script().back().kind == Kind::Cut && f.script().back().hinge == 1 && f.script().back().at == f.t);

        QVERIFY(f.showFrame(10) == f.t);
        QTest::mouseClick(f.side(), Qt::LeftButton, {}, f.inSide(f.side()->frame().hinges[1].position));
        QTest::keyClick(f.side(), Qt::Key_Delete);
        QCOMPARE(f.script().size(), f.scene.script.size() + 2);
        QCOMPARE(f.script().back().hinge, 2);
        f.window.document()->undoStack()->undo();
        QCOMPARE(f.script().size(), f.scene.script.size() + 1);
        f.window.document()->undoStack()->undo();
        QCOMPARE(f.script(), f.scene.script);
        f.window.document()->undoStack()->redo();
        f.window.document()->undoStack()->redo();
        QVERIFY(f.replaysFromFile(30));
    }

    // A block's menu in the 3-D view: the held top block can be released,
    // block 2 held where it is; each a row at the instant shown.
    void theBlockMenuHoldsAndReleases() {
        Hand f(swingingLadder(), 10);
        QVERIFY(f.t > 0);
        LadderView* view = f.window.ladderView();
        QMenu* menu = menuAt(view, f.inView(f.sim->status()->frame->poses[2].position));
        QVERIFY(menu);
        QCOMPARE(itemsOf(menu), QStringList{"Hold block 2 here"});
        QVERIFY(choose(menu, "Hold block 2 here"));
        QCOMPARE(f.script().size(), f.scene.script.size() + 1);
        QVERIFY(f.script().back().kind == Kind::Hold && f.script().back().block == 2 && f.script().back().at == f.t);

        QVERIFY(f.showFrame(10) == f.t);
        menu = menuAt(view, f.inView(f.sim->status()->frame->poses[0].position));
        QVERIFY(menu && choose(menu, "Release block 0"));
        QVERIFY(f.script().back().kind == Kind::Release && f.script().back().block == 0);
        // Let go at the top and held at block 2: the ladder hangs from block 2.
        QVERIFY(f.goTo(30));
        QVERIFY(f.sim->status()->frame->held[2] && !f.sim->status()->frame->held[0]);
        QVERIFY(f.replaysFromFile(30));
    }

    // The cut hinge's lower corner, dragged near its upper one, snaps
    // there and joins them: the hinge again. Let go far from any corner,
    // it gives nothing.
    void aCornerDraggedOntoAnotherJoinsThem() {
        Hand f(cutLadder(), 10);
        QVERIFY(f.t > 0);
        const jl::HingeFrame hinge = f.sim->status()->frame->hinges[1];
        QVERIFY(hinge.mode == jl::HingeMode::Cut);
        QVERIFY(f.sim->status()->frame->hinges[0].mode != jl::HingeMode::Folded);  // block 1's corner is free
        const int k = hinge.corner;
        LadderView* view = f.window.ladderView();
        const QPoint from = f.inView(f.corner(2, k)), onto = f.inView(f.corner(1, k));
        QVERIFY((from - onto).manhattanLength() > 30);  // apart: the drag has somewhere to go
        const auto drag = [&](const QPoint& to) {
            QTest::mousePress(view, Qt::LeftButton, {}, from);
            for (int s = 1; s <= 8; ++s) QTest::mouseMove(view, from + (to - from) * s / 8);
            QTest::mouseRelease(view, Qt::LeftButton, {}, to);
        };
        drag(from + QPoint(from.x() > view->width() / 2 ? -80 : 80, 0));  // off the ladder, in the view
        QCOMPARE(f.script().size(), f.scene.script.size());
        QVERIFY(!f.sim->status()->dragging);
        drag(onto + QPoint(5, -4));  // near: it snaps
        QCOMPARE(f.script().size(), f.scene.script.size() + 1);
        const jl::ScriptAction& join = f.script().back();
        QVERIFY(join.kind == Kind::Join);
        QCOMPARE(join.block, 2);
        QCOMPARE(join.corner, k);
        QCOMPARE(join.otherBlock, 1);
        QCOMPARE(join.otherCorner, k);
        QCOMPARE(join.at, f.t);
        QVERIFY(f.goTo(40));
        QVERIFY(f.sim->status()->frame->hinges[1].mode != jl::HingeMode::Cut);  // the hinge again
        QVERIFY(f.replaysFromFile(40));
    }

    // The same join in the side view.
    void aCornerDraggedInTheSideViewJoinsThem() {
        Hand f(cutLadder(), 10);
        QVERIFY(f.t > 0);
        const int k = f.sim->status()->frame->hinges[1].corner;
        const QPoint from = f.inSide(f.corner(2, k)), onto = f.inSide(f.corner(1, k));
        QTest::mousePress(f.side(), Qt::LeftButton, {}, from);
        for (int s = 1; s <= 8; ++s) QTest::mouseMove(f.side(), from + (onto + QPoint(-4, 5) - from) * s / 8);
        QTest::mouseRelease(f.side(), Qt::LeftButton, {}, onto + QPoint(-4, 5));
        QCOMPARE(f.script().size(), f.scene.script.size() + 1);
        QVERIFY(f.script().back().kind == Kind::Join && f.script().back().block == 2 &&
                f.script().back().otherBlock == 1 && f.script().back().at == f.t);
        f.window.document()->undoStack()->undo();
        QCOMPARE(f.script(), f.scene.script);
    }
};

QTEST_MAIN(RestructureByHandTest)
#include "test_restructure_by_hand.moc"
