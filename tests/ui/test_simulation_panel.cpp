// labels: ui
// The Simulation dock's choices: each one a box that edits the scene as one
// undoable step, and shows the scene's value again after undo. Block contact
// (docs/model.md section 17) and the table top (17.8) are chosen here, not
// only in the scene file.
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "ui/edit/document.h"
#include "ui/edit/simulation_panel.h"
#include "ui_test_support.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QLineEdit>
#include <QSpinBox>
#include <QThreadPool>
#include <QUndoStack>
#include <QtTest>

using namespace jl::ui;

namespace {

// The classic cascade with this many blocks.
jl::Scene classicWith(int blocks) {
    jl::Scene scene = *jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml").scene;
    scene.ladder->blocks = blocks;
    return scene;
}

}  // namespace

class SimulationPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void blockContactIsTurnedOffFromTheKeyboardAndUndone() {
        Document doc;
        const jl::SceneLoad load = jl::loadScene(JL_SOURCE_DIR "/examples/wrong-way.yaml");
        QVERIFY(load.scene);
        doc.reset(*load.scene, QString());
        SimulationPanel panel(&doc);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto* box = panel.findChild<QComboBox*>("block_contact");
        QVERIFY(box);
        // Solid blocks are the default.
        QCOMPARE(doc.scene().solver.blockContact, jl::BlockContact::On);
        QCOMPARE(box->currentData().toInt(), int(jl::BlockContact::On));
        // The user picks "off" (the paper's model): the item below "on".
        box->setFocus();
        QTest::keyClick(box, Qt::Key_Down);
        QCOMPARE(doc.scene().solver.blockContact, jl::BlockContact::Off);
        QCOMPARE(doc.undoStack()->undoText(), QString("Change block contact"));
        // Written to the file as the scene format says.
        QVERIFY(jl::sceneToYaml(doc.scene()).find("block_contact: off") != std::string::npos);
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().solver.blockContact, jl::BlockContact::On);
        panel.refresh();  // as the main window does on every change of the scene
        QCOMPARE(box->currentData().toInt(), int(jl::BlockContact::On));
    }

    // A click puts a table top just under the ladder as it starts; its
    // height is then typed; each is one step of undo.
    void aTableTopIsPutUnderTheLadderTypedAndUndone() {
        Document doc;
        const jl::SceneLoad load = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
        QVERIFY(load.scene && !load.scene->floor);
        doc.reset(*load.scene, QString());
        SimulationPanel panel(&doc);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto* table = panel.findChild<QCheckBox*>("floor");
        auto* height = panel.findChild<QDoubleSpinBox*>("floor.height");
        QVERIFY(table && height);
        QVERIFY(!table->isChecked() && table->isEnabled() && !height->isEnabled());
        QCOMPARE(height->text(), QString("none"));
        // The ladder's lowest corner as it starts.
        const auto built = jl::Simulation::build(doc.scene());
        QVERIFY(built.simulation);
        const jl::Ladder& ladder = *built.simulation->ladder();
        double lowest = 1e300;
        for (int i = 0; i < ladder.blockCount(); ++i)
            for (int k = 0; k < 4; ++k)
                lowest = std::min(lowest, ladder.cornerWorld(built.simulation->world(), i, k).y());

        QTest::mouseClick(table, Qt::LeftButton, {}, QPoint(4, table->height() / 2));
        QTRY_VERIFY(doc.scene().floor);
        const double under = lowest - doc.scene().floor->height;
        qInfo("lowest corner %.6f m, table top %.6f m", lowest, doc.scene().floor->height);
        QVERIFY(under >= 0.01 && under < 0.011);
        QCOMPARE(doc.undoStack()->undoText(), QString("Add table top"));
        panel.refresh();
        QVERIFY(table->isChecked() && height->isEnabled());
        QCOMPARE(height->value(), doc.scene().floor->height * 1000);
        // The scene builds with it, and it is written to the file.
        QVERIFY(jl::Simulation::build(doc.scene()).simulation);
        QVERIFY(jl::sceneToYaml(doc.scene()).find("floor:") != std::string::npos);

        // Typed: -250 mm.
        height->setFocus();
        height->findChild<QLineEdit*>()->selectAll();
        QTest::keyClicks(height, "-250");
        QTest::keyClick(height, Qt::Key_Return);
        QVERIFY(doc.scene().floor);
        QCOMPARE(doc.scene().floor->height, -0.25);
        QCOMPARE(doc.undoStack()->undoText(), QString("Change table top"));

        doc.undoStack()->undo();
        QVERIFY(std::abs(lowest - doc.scene().floor->height - under) < 1e-15);
        doc.undoStack()->undo();
        QVERIFY(!doc.scene().floor);
        panel.refresh();
        QVERIFY(!table->isChecked() && !height->isEnabled());
        QCOMPARE(height->text(), QString("none"));
    }

    // Finding where the table goes builds the ladder: 0.8 s at 100,000
    // blocks, never on the UI thread. The click returns at once with the
    // box checked and out of reach; the table comes as one edit after.
    void aTableTopUnderALongLadderIsFoundOffTheUiThread() {
        Document doc;
        const jl::Scene longLadder = classicWith(100000);
        doc.reset(longLadder, QString());
        SimulationPanel panel(&doc);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto* table = panel.findChild<QCheckBox*>("floor");
        QVERIFY(table);
        QElapsedTimer click;
        click.start();
        QTest::mouseClick(table, Qt::LeftButton, {}, QPoint(4, table->height() / 2));
        const qint64 took = click.elapsed();
        QVERIFY(!doc.scene().floor);
        QVERIFY(table->isChecked() && !table->isEnabled());
        // The scene changed meanwhile (another integrator): the place is
        // found again for it, and the box stays as it is on a refresh.
        auto* integrator = panel.findChild<QComboBox*>("integrator");
        QVERIFY(integrator);
        QVERIFY(integrator->currentIndex() + 1 < integrator->count());
        integrator->setFocus();
        QTest::keyClick(integrator, Qt::Key_Down);
        QCOMPARE(doc.undoStack()->count(), 1);
        panel.refresh();
        QVERIFY(table->isChecked() && !table->isEnabled());
        QElapsedTimer placed;
        placed.start();
        QTRY_VERIFY_WITH_TIMEOUT(doc.scene().floor, 30000);
        qInfo("the click took %lld ms; the table top came %lld ms later, at %.3f m", took, placed.elapsed(),
              doc.scene().floor->height);
        // 100,000 blocks of 60 mm hang about 6 km: the table is under the last.
        QVERIFY(doc.scene().floor->height < -100000 * 0.06 * 0.9);
        QCOMPARE(doc.undoStack()->count(), 2);
        QCOMPARE(doc.undoStack()->undoText(), QString("Add table top"));
        panel.refresh();
        QVERIFY(table->isChecked() && table->isEnabled());

        // Another scene opened meanwhile: the click is dropped, not put
        // under the new scene's ladder.
        doc.reset(longLadder, QString());
        panel.refresh();
        QVERIFY(!table->isChecked() && table->isEnabled());
        QTest::mouseClick(table, Qt::LeftButton, {}, QPoint(4, table->height() / 2));
        QVERIFY(table->isChecked() && !table->isEnabled());
        doc.reset(classicWith(6), QString());
        QVERIFY(!table->isChecked() && table->isEnabled());
        QVERIFY(QThreadPool::globalInstance()->waitForDone(30000));
        QCoreApplication::processEvents();
        QVERIFY(!doc.scene().floor && doc.undoStack()->count() == 0);
        QVERIFY(!table->isChecked() && table->isEnabled());
    }

    // Checked from the keyboard, the box keeps the keyboard: while the place
    // is found no other field takes it (the next one, History memory, would
    // change with the arrow keys), and the box has it again afterwards.
    void aTableTopCheckedFromTheKeyboardKeepsTheFocus() {
        Document doc;
        doc.reset(classicWith(100000), QString());
        SimulationPanel panel(&doc);
        panel.show();
        panel.activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(&panel));
        auto* table = panel.findChild<QCheckBox*>("floor");
        auto* history = panel.findChild<QSpinBox*>("historyMegabytes");
        QVERIFY(table && history);
        table->setFocus();
        QTRY_VERIFY(table->hasFocus());
        const int megabytes = history->value();
        QTest::keyClick(table, Qt::Key_Space);
        QVERIFY(table->isChecked() && !table->isEnabled() && !doc.scene().floor);
        QVERIFY(!history->hasFocus());
        QTest::keyClick(&panel, Qt::Key_Up);
        QCOMPARE(history->value(), megabytes);
        QTRY_VERIFY_WITH_TIMEOUT(doc.scene().floor, 30000);
        QVERIFY(table->isEnabled());
        QVERIFY(table->hasFocus());
    }
};

QTEST_MAIN(SimulationPanelTest)
#include "test_simulation_panel.moc"
