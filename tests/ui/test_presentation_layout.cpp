// labels: ui
// Presentation mode reads well on the screens a class meets: run by CTest
// under a window manager at 1280 x 720 (a common projector), 1440 x 900 and
// 1920 x 1080, full screen, the classic cascade at its end. Nothing is cut:
// the lesson text needs no scroll bar, no chart label ends in "...", the
// side view's scale label lies inside it; the 3-D view keeps a useful share
// of the screen; the plots get more height, and their own back afterwards.
// A picture of each screen is left in JL_SHOT_DIR.
#include "ui/play/sim_controller.h"
#include "ui/teaching/lessons.h"
#include "ui/teaching/run_plots.h"
#include "ui/teaching/side_view.h"
#include "ui/teaching/teaching_docks.h"
#include "ui/teaching/time_chart.h"
#include "ui/window/main_window.h"
#include "ui/window/presentation_mode.h"
#include "ui_test_support.h"

#include <QDir>
#include <QDockWidget>
#include <QGraphicsTextItem>
#include <QScreen>
#include <QScrollBar>
#include <QTextBrowser>
#include <QTextDocument>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace jl::ui;

class PresentationLayoutTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void theCascadeReadsWellFullScreen() {
        MainWindow window{jl::test::quietWindow()};
        window.show();
        QVERIFY(QTest::qWaitForWindowExposed(&window));
        SimController* sim = window.controller();
        const auto before = jl::test::loadsSoFar(sim);
        QVERIFY(window.openFile(JL_SOURCE_DIR "/examples/classic.yaml"));
        QVERIFY(jl::test::loadedAfter(sim, before));
        QDockWidget* plotsDock = window.teaching()->plotsDock();
        QTest::qWait(200);
        const int plotsHeight = plotsDock->height();
        window.presentation()->setActive(true);
        sim->seek(2.5);
        QVERIFY(jl::test::waitForStatus(sim, [](const SimStatus& s) { return s.frame && s.frame->time >= 2.49; }));
        const QRect screen = window.screen()->geometry();
        QTRY_COMPARE_WITH_TIMEOUT(window.frameGeometry().size(), screen.size(), 5000);
        QTest::qWait(500);  // the charts settle their margins after the last resize
        TeachingDocks& teaching = *window.teaching();
        RunPlots* plots = teaching.plots();

        const QString size = QString("%1x%2").arg(screen.width()).arg(screen.height());
        if (const QByteArray dir = qgetenv("JL_SHOT_DIR"); !dir.isEmpty()) {
            QDir().mkpath(dir);
            window.screen()->grabWindow(0).save(QString("%1/presentation-%2.png").arg(QString(dir), size));
        }
        auto* lesson = teaching.lessonPanel()->findChild<QTextBrowser*>();
        QVERIFY(lesson);
        lesson->document()->setTextWidth(lesson->viewport()->width());
        QVERIFY2(lesson->document()->size().height() <= lesson->viewport()->height(),
                 qPrintable(QString("%1: the lesson text needs %2 px, it has %3")
                                .arg(size)
                                .arg(lesson->document()->size().height())
                                .arg(lesson->viewport()->height())));
        for (TimeChart* c : {plots->energyChart(), plots->foldChart(), plots->speedChart()})
            QVERIFY2(jl::test::cutLabels(c) == 0,
                     qPrintable(size + ": a label of '" + c->chart()->title() + "' is cut"));
        const QWidget* view = window.findChild<QWidget*>("ladderView");
        QVERIFY(view);
        const double share = double(view->width() * view->height()) / (screen.width() * screen.height());
        qInfo("%s: the 3-D view is %d x %d (%.0f %% of the screen)", qPrintable(size), view->width(), view->height(),
              100 * share);
        QVERIFY2(share >= 0.2, qPrintable(size + ": the 3-D view is too small"));
        SideView* side = teaching.sideView();
        QVERIFY(side->scaleLabelRect().isValid());
        QVERIFY2(QRectF(side->rect()).contains(side->scaleLabelRect()),
                 qPrintable(size + ": the side view's scale label is cut"));
        // The plots get more room (a third of the window's height as it was
        // asked for, at least a quarter of the screen), and their own back afterwards.
        QVERIFY2(
            plotsDock->height() >= std::max(plotsHeight, screen.height() / 4),
            qPrintable(
                QString("%1: the plots are %2 px high, were %3").arg(size).arg(plotsDock->height()).arg(plotsHeight)));
        window.presentation()->setActive(false);
        QTRY_VERIFY2(
            std::abs(plotsDock->height() - plotsHeight) <= 2,
            qPrintable(
                QString("%1: the plots are %2 px high, were %3").arg(size).arg(plotsDock->height()).arg(plotsHeight)));
    }
};

QTEST_MAIN(PresentationLayoutTest)
#include "test_presentation_layout.moc"
