// labels: ui
// The teaching tools in the main window (MainWindow makes its TeachingDocks): the side view and plots follow the
// running simulation, a click in a plot moves the timeline, the Lessons and
// Teach menus sit before Help, presentation mode hides the chrome and comes back.
#include "ui/edit/scene_text_dialog.h"
#include "ui/play/pacing.h"
#include "ui/play/timeline.h"
#include "ui/teaching/lessons.h"
#include "ui/teaching/run_plots.h"
#include "ui/teaching/side_view.h"
#include "ui/teaching/teaching_docks.h"
#include "ui/teaching/time_chart.h"
#include "ui/window/presentation_mode.h"
#include "ui_test_support.h"

#include <QApplication>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QGraphicsScene>
#include <QGraphicsTextItem>
#include <QLabel>
#include <QLegend>
#include <QLineEdit>
#include <QMenuBar>
#include <QPlainTextEdit>
#include <QSettings>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTimer>
#include <QToolBar>
#include <QValueAxis>
#include <QtTest>

using namespace jl::ui;

namespace {

jl::Scene classic() {
    const jl::SceneLoad load = jl::loadScene(std::string(JL_SOURCE_DIR) + "/examples/classic.yaml");
    if (!load.scene) qFatal("classic.yaml does not load");
    return *load.scene;
}

// Axis labels and titles a chart had to cut short ("..." in place of text).

struct Fixture {
    MainWindow window{jl::test::quietWindow()};
    TeachingDocks& teaching = *window.teaching();
    SimController* sim = window.controller();
    Fixture() {
        window.resize(1400, 950);
        window.show();
        const auto before = jl::test::loadsSoFar(sim);
        window.document()->reset(classic(), QString());
        if (!jl::test::loadedAfter(sim, before)) qFatal("the scene was not loaded");
    }
    bool showsTime(double t) {
        const int index = int(std::floor(t / sim->status()->interval + 1e-6));
        return jl::test::waitForStatus(sim,
                                       [index](const SimStatus& s) { return s.frameIndex == index && !s.playing; });
    }
};

}  // namespace

class TeachingWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void theSideViewAndThePlotsFollowTheRunAndAPlotClickSeeks() {
        Fixture f;
        f.sim->seek(0.7);
        QVERIFY(f.showsTime(0.7));
        QTest::qWait(100);  // the controller's poll hands the status to the docks
        const auto s = f.sim->status();
        QCOMPARE(f.teaching.sideView()->frame().time, s->frame->time);
        QCOMPARE(f.teaching.sideView()->frame().poses[3].position, s->frame->poses[3].position);
        QCOMPARE(f.teaching.plots()->traces().endTime(), s->frame->time);
        // Each new frame shown past the last one becomes a sample of the plots.
        const int samples = f.teaching.plots()->traces().count();
        f.sim->stepForward();
        QVERIFY(
            jl::test::waitForStatus(f.sim, [&](const SimStatus& st) { return st.frameIndex == s->frameIndex + 1; }));
        QTest::qWait(100);
        QCOMPARE(f.teaching.plots()->traces().count(), samples + 1);
        QCOMPARE(f.teaching.plots()->traces().endTime(), f.sim->status()->frame->time);
        QCOMPARE(f.teaching.plots()->traces().energy(EnergyTrace::Total).back(),
                 f.sim->status()->frame->energy.total());

        f.teaching.plots()->refresh();
        QTest::qWait(50);
        TimeChart* chart = f.teaching.plots()->energyChart();
        const QPoint at =
            chart->viewPointOf(0.3, (chart->valueAxis()->min() + chart->valueAxis()->max()) / 2).toPoint();
        QTest::mouseClick(chart->viewport(), Qt::LeftButton, {}, at);
        const double pixel = (chart->timeAxis()->max() - chart->timeAxis()->min()) / chart->chart()->plotArea().width();
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus& st) { return std::abs(st.frame->time - 0.3) < 1.5 * pixel + st.interval; }));
    }

    // The plots hold a sample of every frame of the run from t = 0, at the
    // frames' own times: after a seek far ahead, after an edit (which makes
    // the run again up to the moment on screen) and after "next event",
    // though the window saw only a few of those frames on screen.
    void thePlotsHoldEveryFrameOfTheRunFromTheStart() {
        Fixture f;
        auto dense = [&](const char* when) {
            QTest::qWait(100);  // the controller's poll hands the frames to the plots
            const auto s = f.sim->status();
            const RunTraces& traces = f.teaching.plots()->traces();
            if (traces.count() != s->frameCount) {
                qWarning("%s: %d samples for %d frames", when, traces.count(), s->frameCount);
                return false;
            }
            // Frame i is the state at the end of the step that reaches i * interval.
            for (int i = 0; i < traces.count(); ++i)
                if (const double t = traces.time()[size_t(i)];
                    t < i * s->interval - 1e-9 || t >= (i + 1) * s->interval) {
                    qWarning("%s: sample %d at %.6f s", when, i, traces.time()[size_t(i)]);
                    return false;
                }
            return true;
        };
        f.sim->seek(2.0);
        QVERIFY(f.showsTime(2.0));
        QVERIFY(dense("seek"));

        const auto before = jl::test::loadsSoFar(f.sim);
        f.window.findChild<QDoubleSpinBox*>("thickness")->setValue(10.0);  // mm
        QCOMPARE(f.window.document()->scene().ladder->block.thickness, 0.010);
        const int index = f.sim->status()->frameIndex;
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus& s) { return s.loadSerial > before && s.frameIndex == index && !s.playing; }));
        QVERIFY(dense("edit"));

        const int head = f.sim->status()->frameCount;
        f.teaching.pacing()->runToNextEvent();
        QVERIFY(
            jl::test::waitForStatus(f.sim, [&](const SimStatus& s) { return s.frameCount > head + 1 && !s.playing; }));
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus&) { return !f.teaching.pacing()->seekingEvent(); }));
        QVERIFY(dense("next event"));
    }

    // At the default window size every curve's name shows in full in its
    // chart's legend (eight in the energy chart, five in the fold angles),
    // and every number of the status bar in full in its place.
    void everyNameAndNumberShowsWholeAtTheDefaultSize() {
        QSettings().clear();                         // a first start: no arrangement saved by an earlier window
        MainWindow window(jl::test::quietWindow());  // at its first size, 1440 x 900
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        const auto before = jl::test::loadsSoFar(window.controller());
        window.openFile(QString(JL_SOURCE_DIR) + "/examples/classic.yaml");
        QVERIFY(jl::test::loadedAfter(window.controller(), before));
        QTest::qWait(200);
        QCOMPARE(window.size(), QSize(1440, 900));
        RunPlots* plots = window.teaching()->plots();
        for (TimeChart* chart : {plots->energyChart(), plots->foldChart()}) {
            QLegend* legend = chart->chart()->legend();
            const QRectF box = legend->sceneBoundingRect();
            QStringList shown, cut;
            for (QGraphicsItem* item : chart->scene()->items())
                if (auto* text = dynamic_cast<QGraphicsTextItem*>(item); text && legend->isAncestorOf(text)) {
                    shown << text->toPlainText();
                    if (!box.contains(text->sceneBoundingRect()) || text->toPlainText().contains(QChar(0x2026)))
                        cut << text->toPlainText();
                }
            QCOMPARE(shown.size(), int(chart->chart()->series().size()));
            QVERIFY2(cut.isEmpty(), qPrintable(chart->chart()->title() + ": " + cut.join(", ")));
        }
        // The status bar's numbers, in the middle of the run, each whole in its place.
        window.controller()->seek(2.0);
        QVERIFY(
            jl::test::waitForStatus(window.controller(), [](const SimStatus& st) { return st.frame->time >= 2.0; }));
        QTest::qWait(100);
        int labels = 0;
        for (QLabel* label : window.statusBar()->findChildren<QLabel*>()) {
            if (!label->isVisible() || label->text().isEmpty()) continue;
            ++labels;
            const int needed = label->fontMetrics().horizontalAdvance(label->text());
            QVERIFY2(
                needed <= label->contentsRect().width(),
                qPrintable(label->text() + QString(": %1 px in %2").arg(needed).arg(label->contentsRect().width())));
        }
        QVERIFY(labels >= 3);
    }

    void lessonsAndTeachMenusSitBeforeHelp() {
        Fixture f;
        QStringList titles;
        for (QAction* a : f.window.menuBar()->actions())
            if (a->menu()) titles << a->menu()->title().remove('&');
        QVERIFY2(titles.size() >= 3, qPrintable(titles.join(",")));
        QCOMPARE(titles.mid(titles.size() - 3), QStringList({"Lessons", "Teach", "Help"}));
        auto* lessons = f.window.findChild<LessonsMenu*>("lessonsMenu");
        QVERIFY(lessons);
        QSignalSpy asked(&f.teaching, &TeachingDocks::lessonRequested);
        lessons->actions().at(1)->trigger();
        QCOMPARE(asked.size(), 1);
        QVERIFY(asked.first().at(0).toString().endsWith("wrong-way.yaml"));
    }

    // Edit > Title and Description: typed into the dialog, shown in the lesson
    // panel, one undo step, control characters kept out of the file, and the
    // run on screen left alone (words change no physics).
    void titleAndDescriptionAreEditedAndUndone() {
        Fixture f;
        f.sim->seek(0.5);
        QVERIFY(f.showsTime(0.5));
        const auto shownBefore = f.sim->status()->frameIndex;
        QAction* action = f.window.findChild<QAction*>("sceneTextAction");
        QVERIFY(action);
        QTimer::singleShot(0, [] {
            auto* dialog = qobject_cast<SceneTextDialog*>(QApplication::activeModalWidget());
            if (!dialog) return;
            dialog->titleField()->clear();
            QTest::keyClicks(dialog->titleField(), "Ripples for Year 9");
            dialog->titleField()->insert(QString(QChar(1)));  // pasted: a control character
            dialog->descriptionField()->setPlainText("First line.\n\nSecond paragraph.");
            dialog->accept();
        });
        action->trigger();
        QCOMPARE(f.window.document()->scene().title, std::string("Ripples for Year 9"));
        QCOMPARE(f.window.document()->scene().description, std::string("First line.\n\nSecond paragraph."));
        QVERIFY(f.teaching.lessonPanel()->text().contains("Ripples for Year 9"));
        QVERIFY(f.teaching.lessonPanel()->text().contains("Second paragraph."));
        QTest::qWait(100);
        QCOMPARE(f.sim->status()->frameIndex, shownBefore);  // not run again from the start
        f.window.document()->undoStack()->undo();
        QCOMPARE(f.window.document()->scene().title, std::string("The classic cascade"));
        QVERIFY(f.teaching.lessonPanel()->text().contains("The classic cascade"));
        QCOMPARE(SceneTextDialog::cleanTitle("a\nb\tc"), QString("a b c"));
    }

    void presentationModeHidesTheChromeAndComesBack() {
        Fixture f;
        PresentationMode* p = f.window.presentation();
        auto* ladderDock = f.window.findChild<QDockWidget*>("ladderDock");
        auto* sideDock = f.window.findChild<QDockWidget*>("sideViewDock");
        QVERIFY(f.window.menuBar()->isVisible());
        const QFont before = f.window.font();
        p->setActive(true);
        QVERIFY(!f.window.menuBar()->isVisible());
        for (QToolBar* t : f.window.findChildren<QToolBar*>()) QVERIFY(!t->isVisible());
        QVERIFY(ladderDock->isHidden() || !ladderDock->isVisible());
        QVERIFY(sideDock->isVisible());
        QVERIFY(f.window.font().pointSizeF() > before.pointSizeF() * 1.5);
        QCOMPARE(f.teaching.sideView()->options().scale, 2.0 * presentationSize(f.teaching.sideView()));
        // The plots get room for their large type: no tick label cut to "...".
        QTRY_VERIFY(f.window.findChild<QDockWidget*>("plotsDock")->height() >= f.window.height() / 3 - 2);
        // The timeline's labels, in large type, stay whole inside it and apart.
        auto* timeline = f.window.findChild<Timeline*>();
        QVERIFY(timeline);
        QTest::qWait(50);
        const std::vector<Timeline::Label> labels = timeline->labels();
        QVERIFY(labels.size() >= 3);
        for (size_t i = 0; i < labels.size(); ++i) {
            QVERIFY2(QRectF(timeline->rect()).contains(labels[i].box),
                     qPrintable(labels[i].text + QString(" at %1..%2 of %3 x %4")
                                                     .arg(labels[i].box.left())
                                                     .arg(labels[i].box.right())
                                                     .arg(timeline->width())
                                                     .arg(timeline->height())));
            if (i > 0) QVERIFY(labels[i].box.left() >= labels[i - 1].box.right());
        }
        QTest::qWait(200);
        for (TimeChart* c :
             {f.teaching.plots()->energyChart(), f.teaching.plots()->foldChart(), f.teaching.plots()->speedChart()})
            QCOMPARE(jl::test::cutLabels(c), 0);
        // The keyboard still drives: Space plays, though the toolbar is hidden.
        f.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&f.window));
        QTest::keyClick(&f.window, Qt::Key_Space);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.playing; }));
        QTest::keyClick(&f.window, Qt::Key_Space);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        // Esc leaves and everything comes back as it was.
        QTest::keyClick(&f.window, Qt::Key_Escape);
        QVERIFY(!p->active());
        QVERIFY(f.window.menuBar()->isVisible());
        QCOMPARE(f.window.font(), before);
        QCOMPARE(f.teaching.sideView()->options().scale, 1.0);
    }

    // In front of a class Space plays and pauses wherever the keyboard is:
    // typed into a field, then F5, then Space plays (it used to land in the
    // Plots dock's Hinges field, erasing it); a click into that field while
    // presenting does not take Space either.
    void spaceAlwaysPlaysWhilePresenting() {
        Fixture f;
        f.window.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&f.window));
        auto* thickness = f.window.findChild<QDoubleSpinBox*>("thickness");
        auto* hinges = f.window.findChild<QLineEdit*>("plotHinges");
        QVERIFY(thickness && hinges);
        const QString hingesBefore = hinges->text();
        thickness->setFocus();
        QTest::keyClick(thickness, Qt::Key_End);
        QTest::keyClick(QApplication::focusWidget(), Qt::Key_F5);
        QVERIFY(f.window.presentation()->active());
        QWidget* focus = QApplication::focusWidget() ? QApplication::focusWidget() : &f.window;
        QTest::keyClick(focus, Qt::Key_Space);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return s.playing; }));
        QCOMPARE(hinges->text(), hingesBefore);
        QTest::mouseClick(hinges, Qt::LeftButton);
        QTest::keyClick(QApplication::focusWidget() ? QApplication::focusWidget() : hinges, Qt::Key_Space);
        QVERIFY(jl::test::waitForStatus(f.sim, [](const SimStatus& s) { return !s.playing; }));
        QCOMPARE(hinges->text(), hingesBefore);
        QTest::keyClick(hinges, Qt::Key_Escape);
        QVERIFY(!f.window.presentation()->active());
        // Out of presentation mode a field takes its space again.
        hinges->setFocus();
        QTest::keyClick(hinges, Qt::Key_End);
        QTest::keyClick(hinges, Qt::Key_Space);
        QCOMPARE(hinges->text(), hingesBefore + " ");
    }

    // A press on an event's mark in the timeline shows that event's instant
    // (the mark is the way a class finds "the moment block 3 locks"); a press
    // away from every mark shows the frame there, as before.
    void aPressOnAnEventsMarkShowsItsInstant() {
        Fixture f;
        f.sim->seek(1.0);
        QVERIFY(f.showsTime(1.0));
        auto* timeline = f.window.findChild<Timeline*>();
        QTRY_VERIFY(timeline->eventNear(timeline->xOf(0.2)));  // the hand's turn, at a frame's time
        const auto events = f.sim->status()->events;
        const jl::FrameGrid grid{0, f.sim->status()->interval};
        // An event alone at its mark's pixel, between two frames.
        const jl::Event* chosen = nullptr;
        for (const jl::Event& e : *events)
            if (!grid.on(e.time) && timeline->eventNear(timeline->xOf(e.time)) == &e) {
                chosen = &e;
                break;
            }
        QVERIFY(chosen);
        const int y = timeline->height() / 3;
        QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(int(std::lround(timeline->xOf(chosen->time))), y));
        QVERIFY(jl::test::waitForStatus(f.sim, [&](const SimStatus& s) { return s.frame->time == chosen->time; }));
        QCOMPARE(f.sim->status()->frameIndex, int(std::floor(chosen->time / grid.every)));
        // Far from every mark: the frame under the pointer.
        double quiet = -1;
        for (int x = timeline->width() / 2; x < timeline->width() && quiet < 0; ++x)
            if (!timeline->eventNear(x)) quiet = x;
        QVERIFY(quiet > 0);
        QTest::mouseClick(timeline, Qt::LeftButton, {}, QPoint(int(quiet), y));
        QVERIFY(jl::test::waitForStatus(
            f.sim, [&](const SimStatus& s) { return s.frame->time != chosen->time && grid.on(s.frame->time); }));
    }
};

QTEST_MAIN(TeachingWindowTest)
#include "test_teaching_window.moc"
