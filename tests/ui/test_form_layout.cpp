// labels: ui
// The editing panels as a user meets them, run by CTest under a window
// manager at 1280 x 720 (a common projector) and 1440 x 900: the Ladder
// form stays put while the ripple estimate's words change (it moved every
// field below by a line, and clicks landed in the wrong field), the estimate
// is never cut mid-line, a bad file's problems wrap under the file named
// once, and the hinge damping reads in significant digits.
#include "jl/scene/scene_io.h"
#include "ui/design/reach_estimate.h"
#include "ui/edit/ladder_panel.h"
#include "ui/window/file_errors_dialog.h"
#include "ui/window/main_window.h"
#include "ui_test_support.h"

#include <QAbstractScrollArea>
#include <QDir>
#include <QDockWidget>
#include <QDoubleSpinBox>
#include <QLineEdit>
#include <QPushButton>
#include <QScreen>
#include <QScrollBar>
#include <QSignalSpy>
#include <QSpinBox>
#include <QtTest>

using namespace jl::ui;

namespace {
const QString kClassic = QStringLiteral(JL_SOURCE_DIR "/examples/classic.yaml");

// Where every editor of the Ladder panel lies, top to bottom.
QList<QPoint> fieldPlaces(LadderPanel* panel) {
    QList<QPoint> places;
    for (QWidget* w : panel->findChildren<QWidget*>())
        if ((qobject_cast<QAbstractSpinBox*>(w) || qobject_cast<QLineEdit*>(w) || qobject_cast<QPushButton*>(w)) &&
            w->isVisible())
            places << w->mapTo(panel, QPoint(0, 0));
    return places;
}

// The words drawn fit the estimate's height: none is cut.
bool wholeLines(ReachEstimate* e) {
    const QRect box = e->contentsRect();
    return e->fontMetrics()
               .boundingRect(QRect(0, 0, box.width(), 1 << 20), Qt::TextWordWrap, e->shownText())
               .height() <= box.height();
}

// Types a block count into the field, as a user does, and presses Enter.
void typeBlocks(MainWindow& w, int blocks) {
    auto* field = w.findChild<QSpinBox*>("blocks");
    field->setFocus();
    field->selectAll();
    QTest::keyClicks(field, QString::number(blocks));
    QTest::keyClick(field, Qt::Key_Return);
}
}  // namespace

class FormLayoutTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void theLadderFormStaysPutWhileTheEstimateChanges() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openFile(kClassic));
        auto* panel = w.findChild<LadderPanel*>();
        auto* estimate = w.findChild<ReachEstimate*>("reachEstimate");
        QVERIFY(panel && estimate);
        w.findChild<QDockWidget*>("ladderDock")->raise();
        QTRY_VERIFY(estimate->isVisible() && !estimate->computing());
        QTest::qWait(100);
        const QList<QPoint> places = fieldPlaces(panel);
        QVERIFY(places.size() > 10);
        const auto samePlaces = [&] { return fieldPlaces(panel) == places; };

        QSignalSpy shown(estimate, &ReachEstimate::estimated);
        typeBlocks(w, 13);  // a design no other test runs: computed
        QVERIFY(estimate->computing());
        QTest::qWait(50);
        QVERIFY2(samePlaces(), qPrintable(estimate->text()));
        QVERIFY(wholeLines(estimate));
        QVERIFY(shown.wait(60000));
        QTest::qWait(50);
        QVERIFY2(estimate->text().contains("of 12"), qPrintable(estimate->text()));
        QVERIFY2(samePlaces(), qPrintable(estimate->text()));
        QVERIFY(wholeLines(estimate));
        // The longest thing it says: not estimated, too long a ladder.
        typeBlocks(w, 20000);
        QTRY_VERIFY(estimate->text().contains("not estimated"));
        QTest::qWait(50);
        QVERIFY2(samePlaces(), qPrintable(estimate->text()));
        QVERIFY(wholeLines(estimate));
        QVERIFY(estimate->toolTip().contains(estimate->text()));  // the whole of it, where cut
        if (const QByteArray dir = qgetenv("JL_SHOT_DIR"); !dir.isEmpty()) {
            QDir().mkpath(dir);
            const QSize screen = w.screen()->size();
            panel->grab().save(QString("%1/ladder-panel-%2x%3.png").arg(dir).arg(screen.width()).arg(screen.height()));
        }
    }

    void aBadFilesProblemsWrapUnderTheFileNamedOnce() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        const QString bad = QStringLiteral(JL_SOURCE_DIR "/tests/fixtures/bad/many-problems.yaml");
        const auto expected = jl::loadScene(bad.toStdString()).errors;
        QCOMPARE(expected.size(), size_t(5));
        QVERIFY(!w.openFile(bad));
        auto* dialog = w.findChild<FileErrorsDialog*>();
        QVERIFY(dialog);
        QTRY_VERIFY(dialog->isVisible());
        QTest::qWait(100);
        const QStringList rows = dialog->lines();
        QCOMPARE(rows.size(), int(expected.size()));
        for (size_t i = 0; i < expected.size(); ++i) {
            const jl::Diagnostic& d = expected[i];
            QCOMPARE(rows[int(i)], QString("%1:%2: %3").arg(d.line).arg(d.column).arg(d.message.c_str()));
        }
        // Nothing runs past the dialog's right edge: the rows wrap.
        auto* area = dialog->findChild<QAbstractScrollArea*>();
        QVERIFY(area);
        QCOMPARE(area->horizontalScrollBar()->maximum(), 0);
        QVERIFY(dialog->frameGeometry().width() <= dialog->screen()->availableGeometry().width());
        dialog->close();
    }

    void theHingeDampingReadsInSignificantDigits() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QVERIFY(w.openFile(kClassic));
        w.findChild<QDockWidget*>("ladderDock")->raise();
        auto* field = w.findChild<QDoubleSpinBox*>("damping");
        QVERIFY(field);
        QCOMPARE(w.document()->scene().ladder->hinges.damping, 0.0);
        QCOMPARE(field->text(), QString("0 N·m·s"));
        field->setFocus();
        field->selectAll();
        QTest::keyClicks(field, "2e-5");
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(w.document()->scene().ladder->hinges.damping, 2e-5);
        QCOMPARE(field->text(), QString("2e-05 N·m·s"));
        field->selectAll();
        QTest::keyClicks(field, "0.00031");
        QTest::keyClick(field, Qt::Key_Return);
        QCOMPARE(w.document()->scene().ladder->hinges.damping, 0.00031);
        QCOMPARE(field->text(), QString("0.00031 N·m·s"));
    }
};

QTEST_MAIN(FormLayoutTest)
#include "test_form_layout.moc"
