// labels: ui
// The desktop window: it opens a scene and draws it, edits undo exactly,
// saves and opens, refuses a bad file without touching the open scene, and
// stays within the screen (restored, and after presentation mode).
#include "jl/scene/scene_io.h"
#include "ui/view3d/ladder_view.h"
#include "ui/window/file_errors_dialog.h"
#include "ui_test_support.h"

#include <QCheckBox>
#include <QDoubleSpinBox>
#include <QMessageBox>
#include <QPushButton>
#include <QRegularExpression>
#include <QScreen>
#include <QSettings>
#include <QSpinBox>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QToolBar>
#include <Qt3DRender/QRenderCapture>
#include <QtTest>

using namespace jl::ui;

namespace {
const QString kClassic = QStringLiteral(JL_SOURCE_DIR "/examples/classic.yaml");

// The blocks' centres show their wood seen edge-on (yaw 0): from the default
// three-quarter view the centre of a block is on a shaded face or a ribbon.
void turnEdgeOn(MainWindow& w) { w.ladderView()->orbit(-w.ladderView()->viewCamera().yaw(), 0); }

}  // namespace

class MainWindowTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void opensClassicAndTheCaptureShowsTheBlocks() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(jl::test::showScene(w, kClassic));
        QCOMPARE(w.document()->scene().title, std::string("The classic cascade"));
        const auto status = w.controller()->status();
        QCOMPARE(int(status->frame->poses.size()), 6);
        turnEdgeOn(w);
        QTest::qWait(300);  // a few rendered frames with the poses in place

        const QImage image = jl::test::captureView(w.ladderView());
        QVERIFY2(!image.isNull(), "no capture from the 3-D view");
        const double scale = double(image.width()) / w.ladderView()->width();
        const QColor wood(200, 162, 107);  // #c8a26b, the file's block colour
        for (int i = 0; i < 6; ++i) {
            const jl::Vec2 c = status->frame->poses[size_t(i)].position;
            const QPointF p = w.ladderView()->pixelOf(c) * scale;
            const QColor got = image.pixelColor(p.toPoint());
            QVERIFY2(jl::test::woodColoured(got, wood),
                     qPrintable(QString("block %1 at %2,%3 is %4").arg(i).arg(p.x()).arg(p.y()).arg(got.name())));
            // 15 cm beside the ladder there is no wood, so the test can fail.
            const QPointF beside = w.ladderView()->pixelOf(c + jl::Vec2(0.15, 0)) * scale;
            QVERIFY2(!jl::test::woodColoured(image.pixelColor(beside.toPoint()), wood),
                     "wood colour where no block is");
        }
    }

    void ribbonsAreDrawnOverTheFacesAndHideWhenAsked() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(jl::test::showScene(w, kClassic));
        turnEdgeOn(w);
        w.ladderView()->orbit(35, 0);  // from the front the ribbons are edge on
        QTest::qWait(300);
        const QColor ribbon(40, 60, 140);  // the default ribbon colour
        auto ribbonPixels = [&] {
            const QImage image = jl::test::captureView(w.ladderView());
            int n = 0;
            for (int y = 0; y < image.height(); y += 2)
                for (int x = 0; x < image.width(); x += 2) {
                    const QColor c = image.pixelColor(x, y);
                    n += std::abs(c.hsvHueF() * 360 - ribbon.hsvHueF() * 360) < 12 && c.hsvSaturationF() > 0.45f;
                }
            return n;
        };
        const int shown = ribbonPixels();
        QVERIFY2(shown > 100, qPrintable(QString("%1 ribbon pixels").arg(shown)));
        auto* visible = w.findChild<QCheckBox*>("ribbonsVisible");
        QVERIFY(visible && visible->isChecked());
        visible->setChecked(false);
        QVERIFY(!w.document()->scene().ladder->ribbons.visible);
        QVERIFY(jl::test::waitForStatus(w.controller(), [](const SimStatus& s) {
            return s.recorded && !s.recorded->ladder->ribbons.visible && s.frame;
        }));
        QTest::qWait(300);
        QCOMPARE(ribbonPixels(), 0);
    }

    void blockCountEditsMergeAndUndoRestoresTheSceneExactly() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(w.openFile(kClassic));
        const jl::Scene original = w.document()->scene();
        auto* blocks = w.findChild<QSpinBox*>("blocks");
        QVERIFY(blocks);
        QCOMPARE(blocks->value(), 6);
        // The toolbar stays put while the Undo text changes.
        auto* bar = w.findChild<QToolBar*>("mainToolBar");
        QVERIFY(bar);
        QWidget* play = bar->widgetForAction(bar->actions().at(bar->actions().size() - 1));
        const int before = play->mapTo(&w, QPoint()).x();
        // Arrow clicks on the spin box: three changes, one undo step.
        blocks->stepUp();
        blocks->stepUp();
        blocks->stepUp();
        QCOMPARE(w.document()->scene().ladder->blocks, 9);
        QCOMPARE(w.document()->undoStack()->count(), 1);
        QVERIFY(w.document()->isModified());
        QApplication::processEvents();
        QCOMPARE(play->mapTo(&w, QPoint()).x(), before);
        const jl::Scene nine = w.document()->scene();
        QVERIFY(jl::test::waitForStatus(w.controller(),
                                        [](const SimStatus& s) { return s.frame && s.frame->poses.size() == 9; }));

        w.document()->undoStack()->undo();
        QVERIFY(w.document()->scene() == original);
        QVERIFY(!w.document()->isModified());
        QCOMPARE(blocks->value(), 6);
        QVERIFY(jl::test::waitForStatus(w.controller(),
                                        [](const SimStatus& s) { return s.frame && s.frame->poses.size() == 6; }));
        w.document()->undoStack()->redo();
        QVERIFY(w.document()->scene() == nine);

        // Going back to where it started is no change at all: the command drops itself.
        w.document()->undoStack()->undo();
        auto* thickness = w.findChild<QDoubleSpinBox*>("thickness");
        QVERIFY(thickness);
        const double t0 = thickness->value();
        thickness->setValue(t0 + 1);
        thickness->setValue(t0);
        QCOMPARE(w.document()->undoStack()->count(), 0);
        QVERIFY(w.document()->scene() == original);

        // Two edits of the same field a moment apart are two steps: undo
        // goes back to the middle value (6 -> 12, later 12 -> 200 used to
        // merge, and one undo went back to 6).
        blocks->setValue(12);
        QTest::qWait(1000);
        blocks->setValue(200);
        QCOMPARE(w.document()->undoStack()->count(), 2);
        // Ctrl+Z with the field still focused undoes the document, not the field's text.
        w.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        blocks->setFocus();
        QTRY_VERIFY(blocks->hasFocus());
        QTest::keyClick(blocks, Qt::Key_Z, Qt::ControlModifier);
        QCOMPARE(w.document()->scene().ladder->blocks, 12);
        QCOMPARE(blocks->value(), 12);
    }

    // Help > Controls lists the mouse and every key, read from the actions.
    void helpControlsListsTheMouseAndTheKeys() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QAction* controls = nullptr;
        for (QAction* a : w.findChildren<QAction*>())
            if (a->text() == "&Controls") controls = a;
        QVERIFY(controls);
        controls->trigger();
        auto* box = w.findChild<QMessageBox*>("controlsHelp");
        QVERIFY(box && box->isVisible() && !box->isModal());
        for (const char* words : {"right-drag", "Left-drag off the blocks", "Wheel", "Frame the ladder",
                                  "Presentation mode", "Play", "Undo"})
            QVERIFY2(box->text().contains(words), words);
    }

    void aBlockOverrideChangesThatBlockAloneAndUndoes() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(jl::test::showScene(w, kClassic));
        const jl::Scene original = w.document()->scene();
        auto* table = w.findChild<QTableWidget*>("blockOverrides");
        QVERIFY(table);
        QPushButton* add = nullptr;
        for (auto* b : w.findChildren<QPushButton*>())
            if (b->text() == "Override a block") add = b;
        QVERIFY(add);
        add->click();
        QCOMPARE(table->rowCount(), 1);
        table->item(0, 0)->setText("2");  // which block
        table->item(0, 1)->setText("6");  // thickness, mm
        const auto& o = w.document()->scene().ladder->overrides;
        QCOMPARE(int(o.size()), 1);
        QCOMPARE(o[0].index, 2);
        QCOMPARE(*o[0].thickness, 0.006);
        QVERIFY(o[0].color.has_value());

        // Drawn: block 2 in its own colour, block 3 still in the ladder's.
        QVERIFY(jl::test::waitForStatus(w.controller(), [](const SimStatus& s) {
            return s.recorded && s.recorded->ladder->overrides.size() == 1 &&
                   s.recorded->ladder->overrides[0].thickness && s.frame;
        }));
        turnEdgeOn(w);
        QTest::qWait(300);
        const QImage image = jl::test::captureView(w.ladderView());
        const double scale = double(image.width()) / w.ladderView()->width();
        const auto frame = w.controller()->status()->frame;
        auto colourAt = [&](int block) {
            return image.pixelColor((w.ladderView()->pixelOf(frame->poses[size_t(block)].position) * scale).toPoint());
        };
        const jl::Color oc = *o[0].color;
        QVERIFY(jl::test::woodColoured(colourAt(2), QColor(oc.r, oc.g, oc.b)));
        QVERIFY(!jl::test::woodColoured(colourAt(2), QColor(200, 162, 107)));
        QVERIFY(jl::test::woodColoured(colourAt(3), QColor(200, 162, 107)));

        while (w.document()->undoStack()->canUndo()) w.document()->undoStack()->undo();
        QVERIFY(w.document()->scene() == original);
        QCOMPARE(table->rowCount(), 0);
    }

    void saveThenOpenGivesAnEqualScene() {
        QTemporaryDir dir;
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(w.openFile(kClassic));
        w.findChild<QSpinBox*>("blocks")->setValue(8);
        w.findChild<QDoubleSpinBox*>("thickness")->setValue(7.5);
        const jl::Scene edited = w.document()->scene();
        QVERIFY(edited != jl::loadScene(kClassic.toStdString()).scene.value());
        const QString path = dir.filePath("edited.yaml");
        QVERIFY(w.saveTo(path));
        QVERIFY(!w.document()->isModified());

        QVERIFY(w.openFile(QStringLiteral(JL_SOURCE_DIR "/examples/pendulum.yaml")));
        QVERIFY(w.document()->scene() != edited);
        QVERIFY(w.openFile(path));
        QVERIFY(w.document()->scene() == edited);
        QCOMPARE(w.document()->path(), QFileInfo(path).absoluteFilePath());
    }

    void aBadFileShowsEveryErrorAndLeavesTheOpenSceneUntouched() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(w.openFile(kClassic));
        w.findChild<QSpinBox*>("blocks")->setValue(7);  // unsaved work that must survive
        const jl::Scene before = w.document()->scene();
        const QString bad = QStringLiteral(JL_SOURCE_DIR "/tests/fixtures/bad/negative-length.yaml");
        const auto expected = jl::loadScene(bad.toStdString()).errors;
        QVERIFY(!expected.empty());

        QVERIFY(!w.openFile(bad));
        QVERIFY(w.document()->scene() == before);
        QCOMPARE(w.document()->path(), QFileInfo(kClassic).absoluteFilePath());
        QVERIFY(w.document()->isModified());
        auto* dialog = w.findChild<FileErrorsDialog*>();
        QVERIFY(dialog);
        QVERIFY(dialog->isVisible());
        QCOMPARE(dialog->errorCount(), int(expected.size()));
        QVERIFY(dialog->windowTitle().contains("negative-length.yaml"));
        const QRegularExpression located("^\\d+:\\d+: \\S");  // the file is named once, above
        for (const QString& line : dialog->lines()) QVERIFY2(located.match(line).hasMatch(), qPrintable(line));
    }

    // Filling a 1440 x 900 screen, the window came back from presentation
    // mode taller than the screen, the plots and the status bar off it.
    void leavingPresentationModeKeepsTheWindowOnTheScreen() {
        MainWindow w(jl::test::quietWindow());
        QVERIFY(jl::test::showScene(w, kClassic));
        const QRect screen = w.screen()->availableGeometry();
        w.setGeometry(screen);
        w.activateWindow();
        QTest::qWait(200);
        const QRect before = w.geometry();
        const QSize smallest = w.minimumSizeHint();
        QVERIFY(QTest::qWaitForWindowActive(&w));
        QTest::keyClick(&w, Qt::Key_F5);
        QTRY_VERIFY(w.isFullScreen());
        QTest::qWait(300);  // laid out in large type
        QTest::keyClick(&w, Qt::Key_Escape);
        QTRY_VERIFY(!w.isFullScreen());
        QTest::qWait(500);
        const QRect g = w.frameGeometry();
        QVERIFY2(screen.contains(g), qPrintable(QString("the window %1x%2 at %3,%4 is not within the screen's %5x%6")
                                                    .arg(g.width())
                                                    .arg(g.height())
                                                    .arg(g.x())
                                                    .arg(g.y())
                                                    .arg(screen.width())
                                                    .arg(screen.height())));
        // On a taller screen too the window comes back as it was, and the
        // large type's minimum sizes do not outlast presentation mode.
        QCOMPARE(w.geometry(), before);
        QCOMPARE(w.minimumSizeHint(), smallest);
    }

    // A geometry saved on a larger screen (or before presentation mode was
    // fixed) is fitted to the screen the window opens on.
    void aRestoredWindowTallerThanTheScreenIsFittedToIt() {
        const QRect screen = QGuiApplication::primaryScreen()->availableGeometry();
        {
            MainWindow big(jl::test::quietWindow());
            big.setGeometry(screen.x() + 40, screen.y() + 30, screen.width() + 200, screen.height() + 400);
            QSettings().setValue("window/geometry", big.saveGeometry());
        }
        MainWindow w(jl::test::quietWindow());
        QSettings().remove("window/geometry");
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QTest::qWait(300);
        const QRect g = w.frameGeometry();
        QVERIFY2(screen.contains(g), qPrintable(QString("the window %1x%2 at %3,%4 is not within the screen's %5x%6")
                                                    .arg(g.width())
                                                    .arg(g.height())
                                                    .arg(g.x())
                                                    .arg(g.y())
                                                    .arg(screen.width())
                                                    .arg(screen.height())));
    }
};

QTEST_MAIN(MainWindowTest)
#include "test_main_window.moc"
