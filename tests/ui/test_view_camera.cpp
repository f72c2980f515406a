// labels: ui
// The viewer's camera: framing a long ladder, orbiting about the target,
// walking (eye and target together) and looking around from the eye; in the
// window, a three-quarter view that frames the whole ladder on load, after
// an edit that makes it longer and on F; the room's table below all that a
// chain pinned to the world reaches.
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "ui/view3d/block_shapes.h"
#include "ui/view3d/scale_mark.h"
#include "ui/view3d/view_camera.h"
#include "ui_test_support.h"

#include <QMouseEvent>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTemporaryDir>
#include <Qt3DRender/QCamera>
#include <QtTest>

#include <cmath>
#include <numbers>

using namespace jl::ui;

namespace {
const QString kClassic = QStringLiteral(JL_SOURCE_DIR "/examples/classic.yaml");

// A scene file of `blocks` blocks with no view of its own.
QString ladderFile(const QTemporaryDir& dir, int blocks) {
    const QString path = dir.filePath(QString("ladder-%1.yaml").arg(blocks));
    QFile f(path);
    if (!f.open(QIODevice::WriteOnly)) return {};
    f.write(QString("format: jacobs-ladder/1\ntitle: framed\nladder:\n  blocks: %1\n  held: [0]\nduration: 1\n")
                .arg(blocks)
                .toUtf8());
    return path;
}

bool showScene(MainWindow& w, const QString& path) {
    if (!jl::test::showScene(w, path)) return false;
    QTest::qWait(200);  // the first frame reaches the view
    return true;
}

// Empty when every corner of every block shown projects inside the 3-D
// view, and (`fill`) the ladder fills a fair part of it (framing is not just
// far away).
QString framingProblem(MainWindow& w, bool fill = true) {
    LadderView* view = w.ladderView();
    const auto status = w.controller()->status();
    if (!status->frame) return "no frame";
    const std::vector<BlockShape> shapes = blockShapes(w.document()->scene());
    const QMatrix4x4 viewProjection = view->camera()->projectionMatrix() * view->camera()->viewMatrix();
    float lo[2] = {1e9f, 1e9f}, hi[2] = {-1e9f, -1e9f};
    for (size_t i = 0; i < status->frame->poses.size(); ++i) {
        const jl::Pose& p = status->frame->poses[i];
        const BlockShape& s = shapes[i];
        const float c = float(std::cos(p.angle)), sn = float(std::sin(p.angle));
        for (const float u : {-s.across / 2, s.across / 2})
            for (const float v : {-s.along / 2, s.along / 2})
                for (const float z : {-s.out / 2, s.out / 2}) {
                    const QVector4D clip = viewProjection * QVector4D(float(p.position.x()) + c * u - sn * v,
                                                                      float(p.position.y()) + sn * u + c * v, z, 1);
                    if (clip.w() <= 0) return QString("block %1 is behind the eye").arg(i);
                    const float x = clip.x() / clip.w(), y = clip.y() / clip.w();
                    if (std::abs(x) > 1 || std::abs(y) > 1)
                        return QString("a corner of block %1 is out of view at %2, %3").arg(i).arg(x).arg(y);
                    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
                    lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
                }
    }
    // Normalised coordinates span 2 each way: the ladder spans half the view at least one way.
    if (fill && std::max(hi[0] - lo[0], hi[1] - lo[1]) < 1.0f)
        return QString("the ladder is small in the view: %1 by %2").arg(hi[0] - lo[0]).arg(hi[1] - lo[1]);
    return {};
}
}  // namespace

class ViewCameraTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void aSceneThatLeavesTheYawIsSeenFromThreeQuarters() {
        ViewCamera c;
        c.reset(jl::ViewSpec{}, 0.36);
        QVERIFY(c.yaw() != 0);
        // Both the faces (x) and the edges (z) of the blocks face the eye.
        QVERIFY(c.eye().x() > 0.3f && c.eye().z() > 0.3f);
    }

    void aShortLadderKeepsTheScenesView() {
        ViewCamera c;
        jl::ViewSpec v;  // target (0, -0.15), distance 0.8, pitch 10
        v.yaw = 0;       // edge-on, as the file asks
        c.reset(v, 0.36);
        QCOMPARE(c.distance(), 0.8f);
        const QVector3D eye = c.eye();
        QVERIFY(qAbs(eye.x()) < 1e-6f);
        QVERIFY(qFuzzyCompare(eye.y(), float(-0.15 + 0.8 * std::sin(10 * std::numbers::pi / 180))));
    }

    // The room's table stands below anything the scene can reach
    // (Room::fitTo puts its top under ladderExtent): the falling chain,
    // laid out level from its pin, swings down through where a table under
    // its start would stand.
    void aChainPinnedToTheWorldSwingsAboveTheTable() {
        for (const char* name : {"falling-chain.yaml", "folding-chain.yaml"}) {
            const jl::SceneLoad load = jl::loadScene(std::string(JL_SOURCE_DIR "/examples/") + name);
            QVERIFY(load.scene);
            const double extent = ladderExtent(*load.scene);
            auto sim = std::move(jl::Simulation::build(*load.scene).simulation);
            QVERIFY(sim);
            const std::vector<BlockShape> shapes = blockShapes(*load.scene);
            double lowest = 0;
            for (double t = 0.01; t <= load.scene->duration + 1e-9; t += 0.01) {
                QVERIFY(sim->advanceTo(t));
                const jl::Frame f = sim->frame();
                for (size_t i = 0; i < f.poses.size(); ++i)
                    for (const float u : {-shapes[i].across / 2, shapes[i].across / 2})
                        for (const float v : {-shapes[i].along / 2, shapes[i].along / 2})
                            lowest = std::min(lowest, f.poses[i].apply(jl::Vec2(u, v)).y());
            }
            QVERIFY2(lowest > -extent,
                     qPrintable(QString("%1: down to %2 m, the table at %3 m").arg(name).arg(lowest).arg(-extent)));
        }
    }

    void aLongLadderIsFramedWhole() {
        ViewCamera c;
        c.reset(jl::ViewSpec{}, 60.0);  // 1000 blocks of 60 mm
        // 40 degrees of view must span the 60 m with a margin.
        const float visible = 2 * c.distance() * std::tan(float(20 * std::numbers::pi / 180));
        QVERIFY(visible > 60.0f && visible < 75.0f);
    }

    // The scale bar: a round length, 90 pixels or more on screen, and as
    // long against the ladder as it says (a 6-block ladder and one of
    // 10,000 blocks, 600 m, each framed whole). Of a long ladder only the
    // blocks a pixel apart are drawn; of a short one, all.
    void aScaleBarSaysHowLongTheLadderIs_data() {
        QTest::addColumn<int>("blocks");
        QTest::newRow("6 blocks") << 6;
        QTest::newRow("10,000 blocks") << 10000;
    }
    void aScaleBarSaysHowLongTheLadderIs() {
        QFETCH(int, blocks);
        QTemporaryDir dir;
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, ladderFile(dir, blocks)));
        LadderView* view = w.ladderView();
        const ScaleMark* mark = view->scaleMark();
        const double length = mark->length();
        const double decade = std::pow(10.0, std::floor(std::log10(length) + 1e-9));
        const double mantissa = length / decade;
        QVERIFY2(std::abs(mantissa - 1) < 1e-9 || std::abs(mantissa - 2) < 1e-9 || std::abs(mantissa - 5) < 1e-9,
                 qPrintable(QString::number(length)));
        const QRect viewport(0, 0, view->width(), view->height());
        const QMatrix4x4 v = view->camera()->viewMatrix(), p = view->camera()->projectionMatrix();
        const double barPixels =
            (mark->top().project(v, p, viewport) - mark->bottom().project(v, p, viewport)).toVector2D().length();
        QVERIFY2(barPixels >= 90 && barPixels < 2.5 * 90, qPrintable(QString::number(barPixels)));
        // The ladder hangs straight from the hand: its top and bottom blocks' centres.
        const auto frame = w.controller()->status()->frame;
        const QPointF top = view->pixelOf(frame->poses.front().position);
        const QPointF bottom = view->pixelOf(frame->poses.back().position);
        const double ladder = (frame->poses.front().position - frame->poses.back().position).norm();
        const double ladderPixels = QLineF(top, bottom).length();
        const double perPixelBar = length / barPixels, perPixelLadder = ladder / ladderPixels;
        QVERIFY2(std::abs(perPixelBar / perPixelLadder - 1) < 0.15,
                 qPrintable(QString("bar %1 m/px, ladder %2 m/px").arg(perPixelBar).arg(perPixelLadder)));
        qInfo("%d blocks, %d drawn; scale bar %g m over %.0f px", blocks, view->blocksDrawn(), length, barPixels);
        if (blocks < 100)
            QCOMPARE(view->blocksDrawn(), blocks);
        else
            QVERIFY2(view->blocksDrawn() > 100 && view->blocksDrawn() < blocks / 5,
                     qPrintable(QString::number(view->blocksDrawn())));
    }

    // A scene that says where to look is looked at there, however long its
    // ladder: the long-ladder example opens on its top blocks (a 12 m
    // ladder framed whole is a line one block thick), also after another
    // scene whose whole ladder was still to be framed on its first frame.
    void aSceneThatSaysWhereToLookIsLookedAtThereHoweverLong() {
        ViewCamera c;
        jl::ViewSpec top;
        top.target = {0, -0.15};
        top.distance = 0.6;
        c.reset(top, 12.0);
        QCOMPARE(c.distance(), 0.6f);
        QCOMPARE(c.target(), QVector3D(0, -0.15f, 0));

        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        QVERIFY(showScene(w, QStringLiteral(JL_SOURCE_DIR "/examples/long-ladder.yaml")));
        QCOMPARE(w.document()->scene().view.distance, 0.6);
        QCOMPARE(w.ladderView()->viewCamera().distance(), 0.6f);
        // Blocks 0 and 1 are in view, and the ladder runs out of it.
        QVERIFY(framingProblem(w).contains("out of view"));
        const auto poses = w.controller()->status()->frame->poses;
        for (const size_t b : {size_t(0), size_t(1)}) {
            const QPointF p = w.ladderView()->pixelOf(poses[b].position);
            QVERIFY2(p.x() > 0 && p.x() < w.ladderView()->width() && p.y() > 0 && p.y() < w.ladderView()->height(),
                     qPrintable(QString("block %1 at %2, %3").arg(b).arg(p.x()).arg(p.y())));
        }
        // A scene with the default view, then at once (before any frame of
        // it) one that says where to look: the first frame does not frame
        // the whole ladder as the first scene asked.
        jl::Scene unsaid = w.document()->scene();
        unsaid.view = {};
        w.ladderView()->setScene(unsaid, true);
        w.ladderView()->setScene(w.document()->scene(), true);
        w.ladderView()->showFrame(*w.controller()->status()->frame);
        QCOMPARE(w.ladderView()->viewCamera().distance(), 0.6f);
        // F still frames the whole of it.
        QTest::keyClick(w.ladderView(), Qt::Key_F);
        const QString problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // M frames the stretch of blocks that moved between the last two frames
    // shown (and two neighbours each side): on a 200-block ladder where only
    // blocks 100 to 103 moved, those fill the view and the ends are out of it.
    // With nothing moving it frames the whole ladder and says so.
    void mFramesTheMovingBlocks() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, QStringLiteral(JL_SOURCE_DIR "/examples/long-ladder.yaml")));
        LadderView* view = w.ladderView();
        const jl::Frame still = *w.controller()->status()->frame;
        jl::Frame moved = still;
        moved.time = still.time + 1.0 / 60;
        for (size_t i = 100; i <= 103; ++i) moved.poses[i].position.x() += 0.01;
        view->showFrame(still);
        view->showFrame(moved);
        QTest::keyClick(view, Qt::Key_M);
        auto inView = [&](size_t i) {
            const QPointF p = view->pixelOf(moved.poses[i].position);
            return p.x() > 0 && p.x() < view->width() && p.y() > 0 && p.y() < view->height();
        };
        for (size_t i = 98; i <= 105; ++i) QVERIFY2(inView(i), qPrintable(QString("block %1").arg(i)));
        for (const size_t i : {size_t(0), size_t(90), size_t(112), size_t(199)})
            QVERIFY2(!inView(i), qPrintable(QString("block %1").arg(i)));
        // Those eight blocks fill a fair part of the view's height.
        const double span =
            std::abs(view->pixelOf(moved.poses[105].position).y() - view->pixelOf(moved.poses[98].position).y());
        QVERIFY2(span > view->height() * 0.4, qPrintable(QString::number(span)));

        // Moving at both ends (the top swinging, the bottom knocking): the
        // end that moved most, not the whole ladder between them.
        jl::Frame both = moved;
        both.time += 1.0 / 60;
        for (size_t i = 1; i <= 2; ++i) both.poses[i].position.x() += 0.02;
        for (size_t i = 195; i <= 199; ++i) both.poses[i].position.x() += 0.01;
        view->showFrame(both);
        QVERIFY(view->frameMotion());
        for (size_t i = 0; i <= 4; ++i) QVERIFY2(inView(i), qPrintable(QString("block %1").arg(i)));
        for (const size_t i : {size_t(20), size_t(195)}) QVERIFY2(!inView(i), qPrintable(QString("block %1").arg(i)));

        jl::Frame later = both;
        later.time += 1.0 / 60;
        view->showFrame(later);
        QVERIFY(!view->frameMotion());
        for (const size_t i : {size_t(0), size_t(199)}) QVERIFY2(inView(i), qPrintable(QString("block %1").arg(i)));
    }

    void orbitingKeepsTheDistanceToTheTarget() {
        ViewCamera c;
        c.reset(jl::ViewSpec{}, 0.36);
        const QVector3D target(0, -0.15f, 0);
        c.orbit(90, 20);
        QVERIFY(qFuzzyCompare((c.eye() - target).length(), 0.8f));
        QVERIFY(c.eye().x() > 0.5f);  // a quarter turn: now looking from +x
        c.orbit(0, 500);              // pitch stops short of straight down (85 degrees)
        const float height = c.eye().y() - target.y();
        QVERIFY2(height > 0.79f && height < 0.8f * std::sin(86.0f * 3.14159265f / 180),
                 qPrintable(QString::number(height)));
        QVERIFY(std::abs(c.eye().x() - target.x()) + std::abs(c.eye().z() - target.z()) > 0.05f);
    }

    // The wheel zooms toward the point under the pointer: that point stays
    // on the same pixel while the eye comes closer to it (in a long ladder,
    // the top stays in view as one zooms in on it).
    void theWheelZoomsTowardThePointUnderThePointer() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        LadderView* view = w.ladderView();
        const jl::Vec2 top = w.controller()->status()->frame->poses[0].position;
        const QPointF at = view->pixelOf(top);
        const QVector3D point(float(top.x()), float(top.y()), 0);
        const float before = (view->viewCamera().eye() - point).length();
        QWheelEvent wheel(at, view->mapToGlobal(at), {}, QPoint(0, 120 * 5), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(view, &wheel);
        const float after = (view->viewCamera().eye() - point).length();
        QVERIFY2(std::abs(after / before - std::pow(0.88f, 5.0f)) < 1e-4f, qPrintable(QString::number(after / before)));
        const QPointF still = view->pixelOf(top);
        QVERIFY2((still - at).manhattanLength() < 0.5,
                 qPrintable(
                     QString("moved from (%1, %2) to (%3, %4)").arg(at.x()).arg(at.y()).arg(still.x()).arg(still.y())));
        const auto p = view->planePoint(at);
        QVERIFY(p && (*p - top).norm() < 1e-4);
    }

    void walkingMovesTheEyeLevelAndLookingAroundKeepsIt() {
        ViewCamera c;
        jl::ViewSpec v;
        v.yaw = 0;  // looking along -z
        c.reset(v, 0.36);
        const QVector3D before = c.eye();
        c.walk(1.0f, 0, 0);  // a metre forward, toward the ladder (-z), level
        const QVector3D after = c.eye();
        QVERIFY(qFuzzyCompare(after.z(), before.z() - 1.0f));
        QVERIFY(qFuzzyCompare(after.y(), before.y()));
        c.lookAround(45, 0);
        QVERIFY((c.eye() - after).length() < 1e-5f);
    }

    void theWholeLadderIsFramedOnLoadAndOnF_data() {
        QTest::addColumn<int>("blocks");
        QTest::newRow("6 blocks") << 6;
        QTest::newRow("200 blocks") << 200;
    }

    void theWholeLadderIsFramedOnLoadAndOnF() {
        QFETCH(int, blocks);
        QTemporaryDir dir;
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, ladderFile(dir, blocks)));
        QVERIFY(w.ladderView()->viewCamera().yaw() != 0);
        QString problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable("after load: " + problem));

        // Turned, moved off and zoomed right in: F brings the whole ladder back, seen from there.
        w.ladderView()->orbit(70, 25);
        // (the wheel zooms toward the point under the pointer: a block's centre)
        const QPointF middle =
            w.ladderView()->pixelOf(w.controller()->status()->frame->poses[size_t(blocks / 2)].position);
        QWheelEvent wheel(middle, w.ladderView()->mapToGlobal(middle), {}, QPoint(0, 120 * 12), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(w.ladderView(), &wheel);
        QVERIFY(!framingProblem(w).isEmpty());
        const float yaw = w.ladderView()->viewCamera().yaw();
        QTest::keyClick(w.ladderView(), Qt::Key_F);
        QCOMPARE(w.ladderView()->viewCamera().yaw(), yaw);
        problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable("after F: " + problem));
    }

    // The framing on load takes in where the blocks can hang from the hand,
    // not from the origin: one-hinge.yaml holds the lower block, and the
    // upper one flips over to hang below it (by 0.56 s), in view without a
    // second framing.
    void blocksHangingBelowAHeldLowerBlockStayInView() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, QStringLiteral(JL_SOURCE_DIR "/examples/one-hinge.yaml")));
        SimController* sim = w.controller();
        sim->seek(1.0);
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return s.frame && s.frame->time >= 0.99; }));
        QTest::qWait(100);
        const jl::Frame& f = *sim->status()->frame;
        QVERIFY(f.poses[0].position.y() < f.poses[1].position.y() - 0.05);  // block 0 hangs below the held block 1
        // (Framed for where they can go, the two blocks fill less of the view.)
        const QString problem = framingProblem(w, false);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    void theClassicExampleIsSeenFromThreeQuartersAndWhole() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        QVERIFY(w.ladderView()->viewCamera().yaw() != 0);
        const QString problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // A left drag that starts off every block orbits the camera (as in most
    // 3-D programs) and pushes nothing; one that starts on a block pushes it.
    void aLeftDragOffTheBlocksOrbitsAndOnABlockPushes() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        LadderView* view = w.ladderView();
        QSignalSpy pushes(view, &LadderView::dragBegun);
        auto send = [view](QEvent::Type type, QPointF at, Qt::MouseButton button, Qt::MouseButtons buttons) {
            QMouseEvent e(type, at, view->mapToGlobal(at), button, buttons, Qt::NoModifier);
            QCoreApplication::sendEvent(view, &e);
        };
        const jl::Vec2 beside = jl::Vec2(0.2, -0.15);
        QVERIFY(!view->blockAt(beside));
        const QPointF from = view->pixelOf(beside);
        const float yaw = view->viewCamera().yaw();
        send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
        send(QEvent::MouseMove, from + QPointF(60, 0), Qt::NoButton, Qt::LeftButton);
        send(QEvent::MouseButtonRelease, from + QPointF(60, 0), Qt::LeftButton, Qt::NoButton);
        QVERIFY(std::abs(view->viewCamera().yaw() - yaw) > 5);
        QCOMPARE(pushes.count(), 0);
        QVERIFY(w.document()->scene().drags.empty());

        const jl::Vec2 block3 = w.controller()->status()->frame->poses[3].position;
        QVERIFY(view->blockAt(block3));
        const QPointF on = view->pixelOf(block3);
        const float turned = view->viewCamera().yaw();
        send(QEvent::MouseButtonPress, on, Qt::LeftButton, Qt::LeftButton);
        send(QEvent::MouseMove, on + QPointF(30, 0), Qt::NoButton, Qt::LeftButton);
        send(QEvent::MouseButtonRelease, on + QPointF(30, 0), Qt::LeftButton, Qt::NoButton);
        QCOMPARE(pushes.count(), 1);
        QCOMPARE(view->viewCamera().yaw(), turned);  // a push does not turn the view
    }

    // View > Follow the ladder: the camera moves with the blocks' centre;
    // switched off, a ladder that moves leaves the camera where it is.
    void followingMovesTheCameraWithTheLadder() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        LadderView* view = w.ladderView();
        QAction* follow = w.findChild<QAction*>("followAction");
        QVERIFY(follow && follow->isCheckable() && !follow->isChecked());
        jl::Frame f = *w.controller()->status()->frame;
        auto moved = [](jl::Frame g, const jl::Vec2& d) {
            for (jl::Pose& p : g.poses) p.position += d;
            return g;
        };
        view->showFrame(f);
        const QVector3D still = view->viewCamera().target();
        view->showFrame(moved(f, {0.1, -0.05}));
        QCOMPARE(view->viewCamera().target(), still);
        follow->setChecked(true);
        view->showFrame(f);
        const QVector3D before = view->viewCamera().target();
        view->showFrame(moved(f, {0.1, -0.05}));
        const QVector3D d = view->viewCamera().target() - before;
        QVERIFY(std::abs(d.x() - 0.1f) < 1e-6f && std::abs(d.y() + 0.05f) < 1e-6f && std::abs(d.z()) < 1e-6f);
        follow->setChecked(false);
    }

    void aLongerLadderIsFramedAgain() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        auto* blocks = w.findChild<QSpinBox*>("blocks");
        QVERIFY(blocks);
        const auto before = jl::test::loadsSoFar(w.controller());
        blocks->setValue(60);
        QVERIFY(jl::test::loadedAfter(w.controller(), before));
        QTest::qWait(200);
        QCOMPARE(int(w.controller()->status()->frame->poses.size()), 60);
        const QString problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // A view of part of the ladder stays as it is when blocks are added:
    // they hang below, and the top (where the ripple starts) does not move.
    // Once the whole ladder is in view again (F), a longer one is framed.
    void aViewOfTheTopStaysWhenTheLadderGrows() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, QStringLiteral(JL_SOURCE_DIR "/examples/long-ladder.yaml")));
        QCOMPARE(w.ladderView()->viewCamera().distance(), 0.6f);
        auto* blocks = w.findChild<QSpinBox*>("blocks");
        auto grow = [&](int n) {
            const auto before = jl::test::loadsSoFar(w.controller());
            blocks->setValue(n);
            return jl::test::loadedAfter(w.controller(), before) &&
                   QTest::qWaitFor([&] { return int(w.controller()->status()->frame->poses.size()) == n; }) &&
                   (QTest::qWait(200), true);
        };
        QVERIFY(grow(300));
        QCOMPARE(w.ladderView()->viewCamera().distance(), 0.6f);
        QCOMPARE(w.ladderView()->viewCamera().target(), QVector3D(0, -0.15f, 0));
        QTest::keyClick(w.ladderView(), Qt::Key_F);
        QVERIFY(framingProblem(w).isEmpty());
        QVERIFY(grow(400));
        const QString problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }

    // Zoomed in on the bottom of a long ladder, an undo back to six blocks
    // left a view of empty room until F: a view that shows none of the
    // ladder after a change of its size frames it.
    void anUndoFromAZoomedViewStillShowsTheLadder() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(showScene(w, kClassic));
        auto* blocks = w.findChild<QSpinBox*>("blocks");
        const auto before = jl::test::loadsSoFar(w.controller());
        blocks->setFocus();
        blocks->selectAll();
        QTest::keyClicks(blocks, "200");
        QTest::keyClick(blocks, Qt::Key_Return);
        QVERIFY(jl::test::loadedAfter(w.controller(), before));
        QVERIFY(QTest::qWaitFor([&] { return w.controller()->status()->frame->poses.size() == 200; }));
        QTest::qWait(200);
        const QPointF bottom = w.ladderView()->pixelOf(w.controller()->status()->frame->poses[190].position);
        QWheelEvent wheel(bottom, w.ladderView()->mapToGlobal(bottom), {}, QPoint(0, 120 * 12), Qt::NoButton,
                          Qt::NoModifier, Qt::NoScrollPhase, false);
        QCoreApplication::sendEvent(w.ladderView(), &wheel);
        QVERIFY(!framingProblem(w).isEmpty());
        const auto edited = jl::test::loadsSoFar(w.controller());
        QVERIFY(jl::test::clickToolButton(w, "&Undo"));
        QCOMPARE(w.document()->scene().ladder->blocks, 6);
        QVERIFY(jl::test::loadedAfter(w.controller(), edited));
        QVERIFY(QTest::qWaitFor([&] { return w.controller()->status()->frame->poses.size() == 6; }));
        QTest::qWait(200);
        const QString problem = framingProblem(w);
        QVERIFY2(problem.isEmpty(), qPrintable(problem));
    }
};

QTEST_MAIN(ViewCameraTest)
#include "test_view_camera.moc"
