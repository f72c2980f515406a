// labels: ui
// The Simulation dock's choices: each one a box that edits the scene as one
// undoable step, and shows the scene's value again after undo. Block contact
// (docs/model.md section 17) is chosen here, not only in the scene file.
#include "jl/scene/scene_io.h"
#include "ui/edit/document.h"
#include "ui/edit/simulation_panel.h"
#include "ui_test_support.h"

#include <QComboBox>
#include <QUndoStack>
#include <QtTest>

using namespace jl::ui;

class SimulationPanelTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void blockContactIsTurnedOnFromTheKeyboardAndUndone() {
        Document doc;
        const jl::SceneLoad load = jl::loadScene(JL_SOURCE_DIR "/examples/wrong-way.yaml");
        QVERIFY(load.scene);
        doc.reset(*load.scene, QString());
        SimulationPanel panel(&doc);
        panel.show();
        QVERIFY(QTest::qWaitForWindowExposed(&panel));
        auto* box = panel.findChild<QComboBox*>("block_contact");
        QVERIFY(box);
        QCOMPARE(doc.scene().solver.blockContact, jl::BlockContact::Off);
        QCOMPARE(box->currentData().toInt(), int(jl::BlockContact::Off));
        // The user picks "on": the item above "off" in the box.
        box->setFocus();
        QTest::keyClick(box, Qt::Key_Up);
        QCOMPARE(doc.scene().solver.blockContact, jl::BlockContact::On);
        QCOMPARE(doc.undoStack()->undoText(), QString("Change block contact"));
        // Written to the file as the scene format says.
        QVERIFY(jl::sceneToYaml(doc.scene()).find("block_contact: on") != std::string::npos);
        doc.undoStack()->undo();
        QCOMPARE(doc.scene().solver.blockContact, jl::BlockContact::Off);
        panel.refresh();  // as the main window does on every change of the scene
        QCOMPARE(box->currentData().toInt(), int(jl::BlockContact::Off));
    }
};

QTEST_MAIN(SimulationPanelTest)
#include "test_simulation_panel.moc"
