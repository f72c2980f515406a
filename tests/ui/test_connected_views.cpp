// labels: ui
// The teaching views tell one story: the hinge of the event on screen is
// pointed at in the 3-D view and ringed in the side view, the Events list
// follows a scrub, a loop is marked on the timeline, the status bar says a
// replay is a replay, the lesson says when its scene was edited, and the
// plots choose hinges and blocks over the whole ladder.
#include "example_runs.h"
#include "playback_fixture.h"
#include "ui/play/timeline.h"
#include "ui/teaching/lessons.h"
#include "ui/teaching/run_plots.h"
#include "ui/teaching/side_view.h"

#include <QApplication>
#include <QDialog>
#include <QDockWidget>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QListWidget>
#include <QSpinBox>
#include <QTextBrowser>
#include <QTimer>
#include <QtTest>

#include <cmath>

using namespace jl::test;

namespace {

// The classic cascade, recorded up to `t` (paused there).
bool recordClassicTo(Fixture& f, double t) {
    f.sim->seek(t);
    return waitForStatus(f.sim, [t](const SimStatus& s) {
        return s.seekingTo < 0 && s.frame && std::abs(s.frame->time - t) < s.interval && !s.playing;
    });
}

// Clicks the Events list's row, as a user does.
void clickRow(QListWidget* list, int row) {
    QListWidgetItem* item = list->item(row);
    list->scrollToItem(item);
    QTest::mouseClick(list->viewport(), Qt::LeftButton, {}, list->visualItemRect(item).center());
}

// How many pixels of `color` (within a few levels) lie within `radius` of `at`.
int pixelsNear(const QImage& image, QPointF at, double radius, QColor color) {
    int n = 0;
    for (int y = int(at.y() - radius); y <= int(at.y() + radius); ++y)
        for (int x = int(at.x() - radius); x <= int(at.x() + radius); ++x) {
            if (!image.rect().contains(x, y) || std::hypot(x - at.x(), y - at.y()) > radius) continue;
            const QColor c = image.pixelColor(x, y);
            if (std::abs(c.red() - color.red()) + std::abs(c.green() - color.green()) +
                    std::abs(c.blue() - color.blue()) <
                24)
                ++n;
        }
    return n;
}

}  // namespace

class ConnectedViewsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { isolateSettings(); }

    void theChosenEventsHingeIsPointedAtInBothViews() {
        Fixture f(loadExample("classic.yaml"));
        QVERIFY(recordClassicTo(f, 1.0));
        auto* list = f.window.findChild<QListWidget*>("events");
        QVERIFY(list);
        QTRY_VERIFY(list->count() >= 3);  // once the window has the run's events
        // A flip in the cascade: the first event of a hinge below the top one.
        const auto events = f.sim->status()->events;
        int row = -1, hinge = 0;
        double time = 0;
        for (int i = 0; i < list->count() && row < 0; ++i) {
            time = list->item(i)->data(Qt::UserRole).toDouble();
            for (const jl::Event& e : *events)
                if (e.time == time && e.hinge >= 2) {
                    row = i, hinge = e.hinge;
                    break;
                }
        }
        QVERIFY(row >= 0);
        clickRow(list, row);
        QVERIFY(waitForStatus(f.sim, [time](const SimStatus& s) { return s.frame && s.frame->time == time; }));
        // The 3-D view highlights the two blocks the hinge joins.
        LadderView* view = f.window.ladderView();
        QTRY_VERIFY(std::find(view->pointedAt().begin(), view->pointedAt().end(), hinge) != view->pointedAt().end());
        QVERIFY(std::find(view->pointedAt().begin(), view->pointedAt().end(), hinge - 1) != view->pointedAt().end());
        // The side view draws a ring round it, in a colour of its own.
        auto* side = f.window.findChild<SideView*>("sideView");
        QVERIFY(side);
        QTRY_COMPARE(side->frame().time, time);
        const QImage picture = side->render(side->size());
        const QPointF at = side->pixelOf(side->frame().hinges[size_t(hinge - 1)].position, QRectF(side->rect()));
        QVERIFY2(pixelsNear(picture, at, 30, QColor(200, 30, 30)) > 10, "no ring round the event's hinge");
        if (const QByteArray dir = qgetenv("JL_SHOT_DIR"); !dir.isEmpty()) {
            picture.save(QString("%1/event-side-view.png").arg(dir));
            jl::test::captureView(view).save(QString("%1/event-3d-view.png").arg(dir));
        }
        // A frame later nothing is pointed at.
        QTest::keyClick(view, Qt::Key_Right);
        QVERIFY(waitForStatus(f.sim, [time](const SimStatus& s) { return s.frame && s.frame->time > time; }));
        QTRY_VERIFY(view->pointedAt().empty());
    }

    // Scrubbing selects the latest event at or before the time on screen.
    void theEventsListFollowsTheScrub() {
        Fixture f(loadExample("classic.yaml"));
        QVERIFY(recordClassicTo(f, 1.0));
        auto* list = f.window.findChild<QListWidget*>("events");
        auto* timeline = f.window.findChild<Timeline*>();
        QVERIFY(list && timeline);
        QTRY_VERIFY(list->count() >= 3);
        const int y = timeline->height() / 3;
        // Between two rows some pixels apart, off any mark: the earlier one is chosen.
        int checked = 0;
        for (int row = 0; row + 1 < list->count(); ++row) {
            const double a = list->item(row)->data(Qt::UserRole).toDouble();
            const double b = list->item(row + 1)->data(Qt::UserRole).toDouble();
            const int x = int(std::lround((timeline->xOf(a) + timeline->xOf(b)) / 2));
            if (timeline->xOf(b) - timeline->xOf(a) < 12 || timeline->eventNear(x)) continue;
            QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(x, y));
            QVERIFY(waitForStatus(f.sim, [&](const SimStatus& s) {
                return s.seekingTo < 0 && s.frame && s.frame->time > a && s.frame->time < b;
            }));
            QTRY_COMPARE(list->currentRow(), row);
            QVERIFY(list->currentItem()->isSelected());
            ++checked;
        }
        QVERIFY(checked >= 2);
        // Before the first event, none is.
        QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(int(timeline->xOf(0)) + 1, y));
        QVERIFY(waitForStatus(f.sim, [](const SimStatus& s) { return s.frame && s.frame->time < 0.05; }));
        QTRY_COMPARE(list->selectedItems().size(), 0);
    }

    // L where the loop starts, L where it ends: the stretch is marked.
    void aLoopIsMarkedOnTheTimeline() {
        Fixture f(loadExample("classic.yaml"));
        QVERIFY(recordClassicTo(f, 1.0));
        auto* timeline = f.window.findChild<Timeline*>();
        QVERIFY(recordClassicTo(f, 0.3));
        QTest::keyClick(f.window.ladderView(), Qt::Key_L);
        QVERIFY(recordClassicTo(f, 0.7));
        QTest::keyClick(f.window.ladderView(), Qt::Key_L);
        QVERIFY(waitForStatus(f.sim, [](const SimStatus& s) { return s.playing; }));
        QTest::keyClick(f.window.ladderView(), Qt::Key_Space);
        QVERIFY(waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        QTest::qWait(50);
        const QImage strip = timeline->grab().toImage();
        const int y = 8;  // just inside the track's top edge, where the loop's bar lies
        const auto marked = [&](double t) {
            return pixelsNear(strip, QPointF(timeline->xOf(t), y), 1, Timeline::kLoopColor) > 0;
        };
        QVERIFY(marked(0.4) || marked(0.6));  // (one may be under the cursor)
        QVERIFY(!marked(0.2) && !marked(0.9));
        QTest::keyClick(f.window.ladderView(), Qt::Key_L);  // looping stops: the mark goes
        QTest::qWait(50);
        const QImage after = timeline->grab().toImage();
        QCOMPARE(pixelsNear(after, QPointF(timeline->xOf(0.4), y), 1, Timeline::kLoopColor) +
                     pixelsNear(after, QPointF(timeline->xOf(0.6), y), 1, Timeline::kLoopColor),
                 0);
    }

    // Playing frames recorded earlier measures no rate: it said "0.00x real
    // time, 0 steps/s", which reads as a stall.
    void aReplaySaysItIsAReplay() {
        jl::Scene scene = swingingLadder();
        scene.duration = 0.5;
        Fixture f(scene);
        f.window.setSpeed(0.5);
        f.sim->seek(0.5);
        QVERIFY(waitForStatus(f.sim, [](const SimStatus& s) { return s.seekingTo < 0 && s.frameIndex >= 29; }));
        QTest::keyClick(f.window.ladderView(), Qt::Key_R, Qt::ControlModifier);
        QVERIFY(waitForStatus(f.sim, [](const SimStatus& s) { return s.frameIndex == 0; }));
        QTest::keyClick(f.window.ladderView(), Qt::Key_Space);
        QVERIFY(waitForStatus(f.sim, [](const SimStatus& s) { return s.playing && s.frameIndex > 3; }));
        auto* rate = f.window.findChild<QLabel*>("rate");
        QVERIFY(rate);
        QTRY_VERIFY2(rate->text().contains("replaying recorded frames"), qPrintable(rate->text()));
        QVERIFY(!rate->text().contains("0.00"));
    }

    // After an edit, the lesson says its words were written for another
    // scene, and its link opens the title and description.
    void anEditedLessonSaysSo() {
        Fixture f(loadExample("classic.yaml"));
        auto* lesson = f.window.findChild<QTextBrowser*>("lessonText");
        QVERIFY(lesson);
        QVERIFY(!lesson->toPlainText().contains("Edited"));
        auto* blocks = f.window.findChild<QSpinBox*>("blocks");
        blocks->setFocus();
        blocks->selectAll();
        QTest::keyClicks(blocks, "10");
        QTest::keyClick(blocks, Qt::Key_Return);
        QTRY_VERIFY(lesson->toPlainText().contains("Edited"));
        // The link, clicked: the title and description dialog opens.
        f.window.findChild<QDockWidget*>("lessonDock")->raise();
        QTRY_VERIFY(lesson->isVisible());
        QTextCursor link = lesson->document()->find("Edit the title");
        QVERIFY(!link.isNull());
        QTextCursor middle(lesson->document());
        middle.setPosition((link.selectionStart() + link.selectionEnd()) / 2);
        const QPoint at = lesson->cursorRect(middle).center();
        bool opened = false;
        QTimer::singleShot(300, [&] {
            for (QWidget* w : QApplication::topLevelWidgets())
                if (auto* d = qobject_cast<QDialog*>(w); d && d->isVisible() && d->objectName() == "sceneTextDialog") {
                    opened = true;
                    d->reject();
                }
        });
        QTest::mouseClick(lesson->viewport(), Qt::LeftButton, {}, at);
        QTRY_VERIFY(opened);
        // Undone (the toolbar's button), the scene is the lesson's again.
        QVERIFY(clickToolButton(f.window, "&Undo"));
        QCOMPARE(f.window.document()->scene().ladder->blocks, 6);
        QTRY_VERIFY(!lesson->toPlainText().contains("Edited"));
    }

    // Ten blocks: the fold angles of hinges over the whole ladder, not 1-5.
    void thePlotsFollowTheLaddersSize() {
        Fixture f(loadExample("classic.yaml"));
        auto* plots = f.window.findChild<RunPlots*>();
        auto* hinges = f.window.findChild<QLineEdit*>("plotHinges");
        auto* blocksPlotted = f.window.findChild<QLineEdit*>("plotBlocks");
        QVERIFY(plots && hinges && blocksPlotted);
        // Every energy curve is shown from the start.
        for (int t = 0; t < int(jl::ui::EnergyTrace::Count); ++t)
            QVERIFY2(plots->energyCurve(jl::ui::EnergyTrace(t))->isVisible(), qPrintable(QString::number(t)));
        QTRY_COMPARE(hinges->text(), QString("1-5"));
        const auto before = loadsSoFar(f.sim);
        auto* blocks = f.window.findChild<QSpinBox*>("blocks");
        blocks->setFocus();
        blocks->selectAll();
        QTest::keyClicks(blocks, "10");
        QTest::keyClick(blocks, Qt::Key_Return);
        QVERIFY(loadedAfter(f.sim, before));
        QTRY_COMPARE(hinges->text(), QString("1, 3, 5, 7, 9"));
        QCOMPARE(blocksPlotted->text(), QString("0, 5, 9"));
    }
};

QTEST_MAIN(ConnectedViewsTest)
#include "test_connected_views.moc"
