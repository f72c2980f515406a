// labels: ui
// The side view: each block drawn where the engine says it is, zoom, pan and
// follow, the engine's corner numbers (at every size the view has), a
// general scene's springs, and a legend that stays whole in a narrow view.
#include "example_runs.h"
#include "ui/teaching/side_view.h"
#include "ui/view3d/round_length.h"
#include "ui_test_support.h"

#include <QApplication>
#include <QMouseEvent>
#include <QWheelEvent>
#include <QtTest>

#include <cmath>

using namespace jl::ui;

namespace {

bool near(const QColor& a, const QColor& b, int tolerance = 4) {
    return std::abs(a.red() - b.red()) <= tolerance && std::abs(a.green() - b.green()) <= tolerance &&
           std::abs(a.blue() - b.blue()) <= tolerance;
}

QString colorText(const QColor& c) { return QString("(%1, %2, %3)").arg(c.red()).arg(c.green()).arg(c.blue()); }

// The classic ladder hanging at rest, in a side view of its own.
struct ClassicAtRest {
    jl::Scene scene = loadExample("classic.yaml");
    Run run = runHeadless(scene, 0.0);
    SideView view;
    ClassicAtRest() {
        view.setScene(scene);
        view.showFrame(run.frames.front());
    }
};

}  // namespace

class SideViewTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void theSideViewDrawsEachBlockWhereTheEngineSaysItIs() {
        const jl::Scene scene = loadExample("classic.yaml");
        const Run run = runHeadless(scene, 0.7);
        const jl::Frame& f = run.frames.back();
        // The ladder has moved from where it hung: the check is not of a still picture.
        QVERIFY((f.poses[3].position - run.frames.front().poses[3].position).norm() > 0.01);
        SideView view;
        SideViewOptions look;
        look.blockNumbers = false;  // the number would sit on the centre pixel
        view.setOptions(look);
        view.setScene(scene);
        view.showFrame(f);
        const QSize size(600, 800);
        const QImage image = view.render(size);
        QCOMPARE(image.size(), size);
        const QColor wood(200, 162, 107);  // "#c8a26b" in classic.yaml
        const QRectF target(QPointF(0, 0), QSizeF(size));
        for (size_t i = 0; i < f.poses.size(); ++i) {
            const QPoint at = view.pixelOf(f.poses[i].position, target).toPoint();
            QVERIFY(image.rect().contains(at));
            const QColor c = image.pixelColor(at);
            QVERIFY2(near(c, wood),
                     qPrintable(QString("block %1 at %2,%3 is %4").arg(i).arg(at.x()).arg(at.y()).arg(colorText(c))));
        }
        // Well outside the ladder: the background (or a grid line), never wood.
        // The middle of the framing's left or right edge, whichever is further from every block.
        const QRectF shown = view.framing();
        auto clearance = [&f](const jl::Vec2& p) {
            double d = 1e9;
            for (const jl::Pose& b : f.poses) d = std::min(d, (b.position - p).norm());
            return d;
        };
        const jl::Vec2 left(shown.left() + 0.05 * shown.width(), shown.center().y());
        const jl::Vec2 right(shown.right() - 0.05 * shown.width(), shown.center().y());
        const jl::Vec2 away = clearance(left) > clearance(right) ? left : right;
        QVERIFY2(clearance(away) > 0.05, qPrintable(QString::number(clearance(away))));
        const QPoint awayPixel = view.pixelOf(away, target).toPoint();
        QVERIFY(image.rect().contains(awayPixel));
        const QColor c = image.pixelColor(awayPixel);
        QVERIFY2(near(c, QColor(252, 252, 249)) || near(c, QColor(232, 232, 226)), qPrintable(colorText(c)));
        // Hinges are drawn in the colour of their mode.
        int checked = 0;
        for (const jl::HingeFrame& h : f.hinges) {
            bool alone = true;
            for (const jl::HingeFrame& o : f.hinges)
                if (&o != &h && (o.position - h.position).norm() < 0.006) alone = false;
            if (!alone) continue;
            const QColor hc = image.pixelColor(view.pixelOf(h.position, target).toPoint());
            QVERIFY2(near(hc, hingeColor(h.mode), 6),
                     qPrintable(QString("%1 hinge is %2").arg(jl::toString(h.mode)).arg(colorText(hc))));
            ++checked;
        }
        QVERIFY(checked >= 3);
    }

    // A general scene's springs reach from end to end: the frame carries
    // each spring's ends where the engine has them (the fixed point, the
    // particles), and the side view draws the straight lead at each end.
    void aScenesSpringsAreDrawnBetweenTheirEnds() {
        const jl::Scene scene = loadExample("particles-and-springs.yaml");
        const Run run = runHeadless(scene, 0.5);
        const jl::Frame& f = run.frames.back();
        QCOMPARE(f.springs.size(), scene.springs.size());
        // Poses: the box, then the particles p1, p2, p3.
        QCOMPARE(f.springs[0].first, jl::Vec2(0, 0));
        QCOMPARE(f.springs[0].second, f.poses[1].position);
        QCOMPARE(f.springs[1].first, f.poses[1].position);
        QCOMPARE(f.springs[2].second, f.poses[3].position);
        QVERIFY((f.poses[2].position - run.frames.front().poses[2].position).norm() > 1e-3);  // it moved
        SideView view;
        view.setScene(scene);
        view.showFrame(f);
        // The fixed end, where the chain hangs from, is in the picture.
        QVERIFY2(view.framing().contains(QPointF(0, 0)), qPrintable(QString("framing %1, %2 to %3, %4")
                                                                        .arg(view.framing().left())
                                                                        .arg(view.framing().top())
                                                                        .arg(view.framing().right())
                                                                        .arg(view.framing().bottom())));
        const QSize size(600, 800);
        const QImage image = view.render(size);
        const QRectF target(QPointF(0, 0), QSizeF(size));
        for (size_t k = 1; k < 3; ++k) {  // between particles: nothing else drawn there
            const auto& [a, b] = f.springs[k];
            // The darkest pixel around the point: the line is a pixel or two wide.
            const QPoint at = view.pixelOf(a + 0.1 * (b - a), target).toPoint();
            QColor c = Qt::white;
            for (int dx = -1; dx <= 1; ++dx)
                for (int dy = -1; dy <= 1; ++dy)
                    if (const QColor here = image.pixelColor(at + QPoint(dx, dy)); here.lightness() < c.lightness())
                        c = here;
            QVERIFY2(c.lightness() < 150, qPrintable(QString("spring %1 at its lead is %2").arg(k).arg(colorText(c))));
        }
    }

    // The wheel zooms about the pointer, a drag pans, and the view then stays
    // where the user put it; a double click follows the whole ladder again.
    // The clock and the legend keep clear of the drawing.
    void theSideViewZoomsPansAndFollowsAgain() {
        const jl::Scene scene = loadExample("classic.yaml");
        const Run run = runHeadless(scene, 0.7);
        SideView view;
        view.resize(400, 500);
        view.setScene(scene);
        view.showFrame(run.frames.front());
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        const QRectF whole = view.framing();
        QVERIFY(view.following());
        // Nothing drawn under the clock's band or the legend's row.
        const QRectF target(QPointF(0, 0), QSizeF(view.size()));
        for (const jl::Pose& b : run.frames.front().poses) {
            const QPointF at = view.pixelOf(b.position, target);
            QVERIFY2(at.y() > 30 && at.y() < view.height() - 50, qPrintable(QString::number(at.y())));
        }
        // Zoom in about block 3: it stays under the pointer, the framing shrinks.
        const jl::Vec2 block3 = run.frames.front().poses[3].position;
        const QPointF pointer = view.pixelOf(block3, target);
        QWheelEvent wheel(pointer, view.mapToGlobal(pointer), QPoint(), QPoint(0, 120), Qt::NoButton, Qt::NoModifier,
                          Qt::NoScrollPhase, false);
        QApplication::sendEvent(&view, &wheel);
        QVERIFY(view.framing().width() < 0.9 * whole.width());
        QVERIFY(!view.following());
        QVERIFY((view.pixelOf(block3, target) - pointer).manhattanLength() < 1.0);
        // Later frames do not move a view the user has zoomed.
        const QRectF zoomed = view.framing();
        view.showFrame(run.frames.back());
        QCOMPARE(view.framing(), zoomed);
        // A drag of 40 px to the right, begun beside the ladder (a press at
        // a block's free corner would begin a join), moves the picture with the mouse.
        QTest::mousePress(&view, Qt::LeftButton, {}, QPoint(60, 250));
        QMouseEvent move(QEvent::MouseMove, QPointF(100, 250), view.mapToGlobal(QPointF(100, 250)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&view, &move);
        QTest::mouseRelease(&view, Qt::LeftButton, {}, QPoint(100, 250));
        QVERIFY(std::abs(view.pixelOf(block3, target).x() - pointer.x() - 40) < 1.0);
        // A double click: the whole ladder in view again, following.
        QTest::mouseDClick(&view, Qt::LeftButton, {}, QPoint(200, 250));
        QVERIFY(view.following());
        QVERIFY(view.framing().contains(view.extentOf(run.frames.back())));
    }

    void theSideViewUsesTheEnginesCornerNumbers() {
        // Hinge j sits at corner 0 (j odd) or 3 (j even) of both blocks: the
        // view's corner k of block j must be where the engine puts hinge j.
        ClassicAtRest c;
        const Run& run = c.run;
        SideView& view = c.view;
        const QRectF target(0, 0, 600, 800);
        for (size_t j = 1; j <= run.frames.front().hinges.size(); ++j) {
            const jl::HingeFrame& h = run.frames.front().hinges[j - 1];
            QCOMPARE(h.corner, j % 2 == 1 ? 0 : 3);
        }
        // Drawn with corner numbers and arrows, the picture still renders (and differs).
        const QImage plain = view.render(target.size().toSize());
        SideViewOptions all;
        all.cornerNumbers = all.orientation = true;
        view.setOptions(all);
        QVERIFY(view.render(target.size().toSize()) != plain);
    }

    // At an event's instant (N in presentation mode, where there is no
    // status bar) the view says what happened there, under the clock; a
    // frame whose events came before it says nothing more.
    void anEventsInstantIsSaidUnderTheClock() {
        ClassicAtRest c;
        const QSize size(400, 600);
        jl::Frame f = c.run.frames.front();
        f.time = 0.5125;
        c.view.showFrame(f);
        const QImage plain = c.view.render(size);
        const jl::Event earlier{0.5100, jl::EventKind::Lock, 4, 0, "blocks 3 and 4 lock end to end"};
        const jl::Event fold{0.5125, jl::EventKind::Fold, 1, 0, "blocks 0 and 1 fold face to face"};
        f.events = {earlier};
        c.view.showFrame(f);
        QCOMPARE(c.view.render(size), plain);
        f.events = {earlier, fold};
        c.view.showFrame(f);
        const QImage said = c.view.render(size);
        int changed = 0, lowest = 0;
        for (int y = 0; y < size.height(); ++y)
            for (int x = 0; x < size.width(); ++x)
                if (said.pixel(x, y) != plain.pixel(x, y)) ++changed, lowest = y;
        // Words in the band under the clock, nothing else moved.
        QVERIFY2(changed > 200, qPrintable(QString::number(changed)));
        QVERIFY2(lowest < size.height() / 3, qPrintable(QString::number(lowest)));
    }

    // In a view of the default dock's size the whole ladder is small, too
    // thin for a number at every corner: each hinge then shows its corner
    // number beside its dot, in the corner numbers' colour.
    void theSideViewShowsCornerNumbersAtItsDefaultSize() {
        ClassicAtRest c;
        const Run& run = c.run;
        SideView& view = c.view;
        const QSize size(360, 280);
        SideViewOptions numbered;
        numbered.cornerNumbers = true;
        view.setOptions(numbered);
        const QImage image = view.render(size);
        const QRectF target(QPointF(0, 0), QSizeF(size));
        auto purpleNear = [&](const QPointF& at) {
            int found = 0;
            for (int y = int(at.y()) - 8; y <= int(at.y()) + 8; ++y)
                for (int x = int(at.x()); x <= int(at.x()) + 22; ++x) {
                    if (!image.rect().contains(x, y)) continue;
                    const QColor c = image.pixelColor(x, y);
                    // Purple: blue well above green, red between (the ink is 90, 40, 120).
                    if (c.blue() > c.green() + 30 && c.red() > c.green() + 15 && c.blue() < 200) ++found;
                }
            return found;
        };
        for (const jl::HingeFrame& h : run.frames.front().hinges)
            QVERIFY2(purpleNear(view.pixelOf(h.position, target)) >= 3, qPrintable(QString::number(h.corner)));
    }

    // The legend row (free, locked open, folded) in presentation type in a
    // narrow view: smaller type, but all three entries whole inside the view.
    // The grid keeps its cells some 80 px apart at any length of ladder (it
    // stopped at 50 m cells, and a 10,000-block ladder, 600 m, was a grey
    // band of lines), and the scale bar says kilometres where it should.
    void theGridStaysReadableOnAnyLengthOfLadder() {
        QCOMPARE(gridCell(1000.0, 80), 0.1);  // 1 px per mm: 10 cm cells
        QCOMPARE(gridCell(1.0, 80), 100.0);
        QCOMPARE(gridCell(0.05, 80), 2000.0);  // 6 km in 300 px
        QCOMPARE(lengthText(0.05), QString("5 cm"));
        QCOMPARE(lengthText(20.0), QString("20 m"));
        QCOMPARE(lengthText(2000.0), QString("2 km"));

        jl::Scene scene;
        scene.ladder = jl::LadderSpec{};
        scene.ladder->blocks = 10000;
        SideView view;
        view.setScene(scene);
        view.showFrame(runHeadless(scene, 0.0).frames.front());
        const QImage image = view.render(QSize(400, 500));
        // Grid lines crossing a row above the ladder's top, clear of the clock:
        // runs of pixels that are not the background.
        const QColor background = image.pixelColor(2, 60);
        int lines = 0;
        for (int x = 1; x < image.width(); ++x)
            lines += !near(image.pixelColor(x, 60), background, 3) && near(image.pixelColor(x - 1, 60), background, 3);
        QVERIFY2(lines >= 1 && lines <= 6, qPrintable(QString("%1 grid lines across 400 px").arg(lines)));
    }

    // A ladder of any length seen whole is a thread from its top block to
    // its last: at 100,000 blocks a block is a few thousandths of a pixel,
    // and drawn one by one the ladder left no mark at all.
    void aLadderOfAnyLengthIsSeenWholeAsAThread() {
        for (int blocks : {1000, 10000, 100000}) {
            jl::Scene scene;
            scene.ladder = jl::LadderSpec{};
            scene.ladder->blocks = blocks;
            SideView view;
            view.setScene(scene);
            const jl::Frame frame = runHeadless(scene, 0.0).frames.front();
            view.showFrame(frame);
            const QSize size(400, 500);
            const QImage image = view.render(size);
            const QRectF target(QPointF(0, 0), QSizeF(size));
            const QPointF top = view.pixelOf(frame.poses.front().position, target);
            const QPointF bottom = view.pixelOf(frame.poses[size_t(blocks - 1)].position, target);
            QVERIFY(bottom.y() - top.y() > 200);  // seen whole, and long on screen
            // The thread (the blocks' colour, darkened, over a near-white
            // background and light grid) near every point of the line between them.
            const QColor background = image.pixelColor(2, size.height() / 2);
            const auto dark = [&](const QColor& c) {
                return c.red() + c.green() + c.blue() < background.red() + background.green() + background.blue() - 90;
            };
            int missing = 0, samples = 0;
            for (double y = top.y() + 2; y < bottom.y() - 2; y += 4, ++samples) {
                const double x = top.x() + (bottom.x() - top.x()) * (y - top.y()) / (bottom.y() - top.y());
                bool found = false;
                for (int dx = -3; dx <= 3 && !found; ++dx)
                    found = dark(image.pixelColor(int(std::lround(x)) + dx, int(y)));
                missing += !found;
            }
            QVERIFY2(
                missing == 0,
                qPrintable(QString("%1 blocks: no thread at %2 of %3 heights").arg(blocks).arg(missing).arg(samples)));
        }
    }

    // A corner resting on another block's face is marked there: the
    // turned-the-wrong-way lesson with contact between blocks on, where
    // block 3's corner rests on block 0's side from 0.851 s.
    void aCornerRestingOnAFaceIsMarked() {
        jl::Scene scene = loadExample("wrong-way.yaml");
        scene.solver.blockContact = jl::BlockContact::On;
        const Run run = runHeadless(scene, 0.88);
        const jl::Frame& f = run.frames.back();
        QVERIFY(!f.blockContacts.empty());
        const jl::BlockContactFrame& c = f.blockContacts.front();
        QVERIFY2(c.block == 3 && c.other == 0, qPrintable(QString("block %1 on block %2").arg(c.block).arg(c.other)));
        SideView view;
        view.setScene(scene);
        view.showFrame(f);
        const QSize size(600, 800);
        const QRectF target(QPointF(0, 0), QSizeF(size));
        const QImage marked = view.render(size);
        jl::Frame bare = f;
        bare.blockContacts.clear();
        view.showFrame(bare);
        const QImage plain = view.render(size);
        // Pixels of the mark's colour within 12 px of the corner, with the
        // mark and without.
        const QPointF at = view.pixelOf(c.point, target);
        const auto count = [&](const QImage& image) {
            int n = 0;
            for (int y = int(at.y()) - 12; y <= int(at.y()) + 12; ++y)
                for (int x = int(at.x()) - 12; x <= int(at.x()) + 12; ++x)
                    if (image.rect().contains(x, y) && near(image.pixelColor(x, y), QColor(170, 20, 150), 30)) ++n;
            return n;
        };
        qInfo("mark pixels near the corner: %d with the contact, %d without", count(marked), count(plain));
        QVERIFY(count(marked) >= 10);
        QCOMPARE(count(plain), 0);
    }

    void theSideViewLegendFitsANarrowView() {
        ClassicAtRest c;
        SideView& view = c.view;
        SideViewOptions large;
        large.scale = 2.0;
        view.setOptions(large);
        const QImage image = view.render(QSize(260, 420));
        auto columnsOf = [&](const QColor& want) {
            std::pair<int, int> range{image.width(), -1};
            for (int y = image.height() - 60; y < image.height(); ++y)
                for (int x = 0; x < image.width(); ++x) {
                    const QColor c = image.pixelColor(x, y);
                    if (std::abs(c.red() - want.red()) + std::abs(c.green() - want.green()) +
                            std::abs(c.blue() - want.blue()) <
                        30)
                        range = {std::min(range.first, x), std::max(range.second, x)};
                }
            return range;
        };
        const auto free = columnsOf(hingeColor(jl::HingeMode::Free));
        const auto folded = columnsOf(hingeColor(jl::HingeMode::Folded));
        QVERIFY2(free.second >= 0 && free.first >= 2, qPrintable(QString("free dot from x = %1").arg(free.first)));
        QVERIFY2(folded.second >= 0 && folded.second < image.width() - 2,
                 qPrintable(QString("folded dot to x = %1").arg(folded.second)));
        QVERIFY(free.second < folded.first);
    }
};

QTEST_MAIN(SideViewTest)
#include "test_side_view.moc"
