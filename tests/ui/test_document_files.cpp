// labels: ui
// Files around the document: the recovery copy written while there are
// unsaved edits and removed once saved, and a scene dropped on the window.
#include "jl/scene/scene_io.h"
#include "jl/scene/yaml_comments.h"
#include "jl/sim/simulation.h"
#include "ui_test_support.h"

#include <QAction>
#include <QFile>
#include <QFileDialog>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QTimer>
#include <QtTest>

using namespace jl::ui;

namespace {
const QString kClassic = QStringLiteral(JL_SOURCE_DIR "/examples/classic.yaml");

// Answers the next message box with `button`.
void answerNextBox(QMessageBox::StandardButton button, QString* text = nullptr) {
    jl::test::answerNextModal([=](QWidget* modal) {
        auto* box = qobject_cast<QMessageBox*>(modal);
        if (!box) return false;
        if (text) *text = box->text();
        box->button(button)->click();
        return true;
    });
}

// The same for a box whose buttons are the program's own words; another box
// may come first (the unsaved-changes prompt): it waits for ours.
void clickInNextBox(const QString& buttonText, QString* text = nullptr) {
    jl::test::answerNextModal([=](QWidget* modal) {
        auto* box = qobject_cast<QMessageBox*>(modal);
        if (!box) return false;
        for (QAbstractButton* b : box->buttons())
            if (b->text() == buttonText) {
                if (text) *text = box->text();
                b->click();
                return true;
            }
        return false;
    });
}

// Reads the file the next file dialog proposes, then cancels it.
void cancelNextFileDialog(QString* proposed) {
    jl::test::answerNextModal([=](QWidget* modal) {
        auto* dialog = qobject_cast<QFileDialog*>(modal);
        if (!dialog) return false;
        *proposed = dialog->selectedFiles().value(0);
        dialog->reject();
        return true;
    });
}

QAction* action(QWidget& w, const QString& text) {
    for (QAction* a : w.findChildren<QAction*>())
        if (a->text() == text) return a;
    qFatal("no action %s", qPrintable(text));
}

QByteArray contents(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) qFatal("cannot read %s", qPrintable(path));
    return f.readAll();
}

// A scene of our own to edit, so the examples on disk are never touched.
QString copyOfClassic(const QTemporaryDir& dir) {
    const QString path = dir.filePath("mine.yaml");
    QFile::copy(kClassic, path);
    return path;
}
}  // namespace

class DocumentFilesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }
    void init() { Document::removeRecovery(); }
    void cleanup() { qunsetenv("JL_EXAMPLES"); }

    // A new scene plays the classic trick: its turn sends a ripple down (it
    // turned the other way, which only throws the ladder about).
    void aNewSceneRipplesWhenPlayed() {
        auto sim = jl::Simulation::build(Document::newScene()).simulation;
        QVERIFY(sim);
        std::vector<int> flips;
        while (sim->time() < 1.0 && sim->stepOnce())
            for (const jl::Event& e : sim->takeEvents())
                if (e.kind == jl::EventKind::FlipFlop && (flips.empty() || flips.back() < e.hinge))
                    flips.push_back(e.hinge);
        QVERIFY(sim->failure().empty());
        QVERIFY2(flips.size() >= 3 && flips[0] == 1 && flips[1] == 2 && flips[2] == 3,
                 qPrintable(QString::number(flips.size())));
    }

    void theRecoveryCopyHoldsTheUnsavedSceneAndGoesAwayOnSave() {
        QTemporaryDir dir;
        MainWindow w(jl::test::quietWindow());
        QVERIFY(w.openFile(kClassic));
        w.findChild<QSpinBox*>("blocks")->setValue(11);
        QVERIFY(w.document()->isModified());
        w.document()->writeRecovery();  // what the 30 s autosave timer does
        QFile file(Document::recoveryPath());
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        file.close();
        QVERIFY(text.startsWith("# recovered-from: " + QFileInfo(kClassic).absoluteFilePath().toUtf8() + "\n"));
        const jl::SceneLoad back = jl::parseScene(text.toStdString(), "recovery.yaml");
        QVERIFY(back.scene.has_value());
        QVERIFY(*back.scene == w.document()->scene());

        QVERIFY(w.saveTo(dir.filePath("saved.yaml")));
        QVERIFY(!QFile::exists(Document::recoveryPath()));
    }

    void aRecoveredSceneOpensAsUnsavedWorkWithItsOriginalPath() {
        {
            MainWindow crashed(jl::test::quietWindow());
            QVERIFY(crashed.openFile(kClassic));
            crashed.findChild<QSpinBox*>("blocks")->setValue(12);
            crashed.document()->writeRecovery();
        }  // gone without a close: like a crash, the recovery copy stays
        QVERIFY(QFile::exists(Document::recoveryPath()));
        MainWindow next({true, false});
        answerNextBox(QMessageBox::Yes);
        next.offerRecovery();
        QCOMPARE(next.document()->scene().ladder->blocks, 12);
        QVERIFY(next.document()->isModified());
        QCOMPARE(next.document()->path(), QFileInfo(kClassic).absoluteFilePath());
    }

    // Revert asks first; No keeps the edits, Yes reads the file again.
    void revertAsksThenReadsTheFileAgain() {
        QTemporaryDir dir;
        const QString path = copyOfClassic(dir);
        const QByteArray onDisk = contents(path);
        MainWindow w(jl::test::quietWindow());
        QVERIFY(w.openFile(path));
        const int blocks = w.document()->scene().ladder->blocks;
        QAction* revert = action(w, "&Revert");
        QVERIFY(!revert->isEnabled());  // nothing to throw away yet
        w.findChild<QSpinBox*>("blocks")->setValue(blocks + 3);
        QVERIFY(revert->isEnabled());

        QString asked;
        answerNextBox(QMessageBox::No, &asked);
        revert->trigger();
        QVERIFY2(asked.contains("mine.yaml"), qPrintable(asked));
        QCOMPARE(w.document()->scene().ladder->blocks, blocks + 3);
        QVERIFY(w.document()->isModified());

        answerNextBox(QMessageBox::Yes);
        revert->trigger();
        QCOMPARE(w.document()->scene().ladder->blocks, blocks);
        QVERIFY(!w.document()->isModified());
        QVERIFY(!revert->isEnabled());
        QCOMPARE(contents(path), onDisk);
    }

    // Closing with unsaved edits: Cancel keeps the window and the edits,
    // Save writes them, Discard leaves the file as it was.
    void closingWithUnsavedChangesAsks() {
        QTemporaryDir dir;
        const QString path = copyOfClassic(dir);
        const QByteArray onDisk = contents(path);
        {
            MainWindow w({false, true});
            QVERIFY(w.openFile(path));
            w.show();
            QVERIFY(QTest::qWaitForWindowExposed(&w));
            const int blocks = w.document()->scene().ladder->blocks;
            w.findChild<QSpinBox*>("blocks")->setValue(blocks + 2);

            QString asked;
            answerNextBox(QMessageBox::Cancel, &asked);
            QVERIFY(!w.close());
            QVERIFY2(asked.contains("not saved"), qPrintable(asked));
            QVERIFY(w.isVisible());
            QVERIFY(w.document()->isModified());
            QCOMPARE(contents(path), onDisk);

            answerNextBox(QMessageBox::Discard);
            QVERIFY(w.close());
            QCOMPARE(contents(path), onDisk);
        }
        {
            MainWindow w({false, true});
            QVERIFY(w.openFile(path));
            const int blocks = w.document()->scene().ladder->blocks;
            w.findChild<QSpinBox*>("blocks")->setValue(blocks + 2);
            answerNextBox(QMessageBox::Save);
            clickInNextBox("Save Over It");  // classic.yaml has comments: a second box says they will go
            QVERIFY(w.close());
            const jl::SceneLoad saved = jl::parseScene(contents(path).toStdString(), "mine.yaml");
            QVERIFY(saved.scene.has_value());
            QCOMPARE(saved.scene->ladder->blocks, blocks + 2);
        }
        {
            // New, with the prompt cancelled, keeps the scene as it is.
            MainWindow w({false, true});
            QVERIFY(w.openFile(path));
            w.findChild<QSpinBox*>("blocks")->setValue(5);
            answerNextBox(QMessageBox::Cancel);
            action(w, "&New")->trigger();
            QCOMPARE(w.document()->path(), QFileInfo(path).absoluteFilePath());
            QCOMPARE(w.document()->scene().ladder->blocks, 5);
            answerNextBox(QMessageBox::Discard);
            QVERIFY(w.close());
        }
    }

    // The writer writes the scene, not the text: saving over a file with
    // comments says they will go; Cancel leaves the file as it was, Save
    // Over It writes the scene without them.
    void savingOverAFileWithCommentsAsksFirst() {
        QTemporaryDir dir;
        const QString path = copyOfClassic(dir);
        const QByteArray onDisk = contents(path);
        QVERIFY(onDisk.contains("\n#") || onDisk.startsWith("#"));
        MainWindow w({false, true});
        QVERIFY(w.openFile(path));
        w.findChild<QSpinBox*>("blocks")->setValue(9);
        QString asked;
        answerNextBox(QMessageBox::Cancel, &asked);
        action(w, "&Save")->trigger();
        QVERIFY2(asked.contains("comments"), qPrintable(asked));
        QCOMPARE(contents(path), onDisk);
        QVERIFY(w.document()->isModified());

        clickInNextBox("Save Over It");
        action(w, "&Save")->trigger();
        QVERIFY(!w.document()->isModified());
        const QByteArray saved = contents(path);
        QVERIFY(!saved.contains("#  ") && !jl::hasComments(saved.toStdString()));
        QCOMPARE(jl::parseScene(saved.toStdString(), "mine.yaml").scene->ladder->blocks, 9);
        // Now without comments: a second save asks nothing.
        w.findChild<QSpinBox*>("blocks")->setValue(10);
        action(w, "&Save")->trigger();
        QVERIFY(!w.document()->isModified());
        QVERIFY(w.close());
    }

    // A lesson is read-only: Save As proposes the user's documents folder
    // (home on an account without one) under the lesson's name, Save asks where, and saving over it is refused.
    void lessonsAreNeverSavedOver() {
        QTemporaryDir lessons;
        const QString lesson = lessons.filePath("classic.yaml");
        QVERIFY(QFile::copy(kClassic, lesson));
        const QByteArray onDisk = contents(lesson);
        qputenv("JL_EXAMPLES", lessons.path().toUtf8());
        MainWindow w(jl::test::quietWindow());
        QVERIFY(w.openFile(lesson));
        w.findChild<QSpinBox*>("blocks")->setValue(9);
        const QDir documents(QStandardPaths::writableLocation(QStandardPaths::DocumentsLocation));
        const QString mine = (documents.exists() ? documents : QDir::home()).filePath("classic.yaml");
        QString proposed;
        cancelNextFileDialog(&proposed);
        action(w, "Save &As...")->trigger();
        QCOMPARE(proposed, mine);
        proposed.clear();
        cancelNextFileDialog(&proposed);
        action(w, "&Save")->trigger();
        QCOMPARE(proposed, mine);
        QString refusal;
        answerNextBox(QMessageBox::Ok, &refusal);
        QVERIFY(!w.saveTo(lesson));
        QVERIFY2(refusal.contains("lesson"), qPrintable(refusal));
        QCOMPARE(contents(lesson), onDisk);
        QVERIFY(w.document()->isModified());
    }

    void droppingASceneFileOnTheWindowOpensIt() {
        MainWindow w(jl::test::quietWindow());
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(kClassic)});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(&w, &drop);
        QCOMPARE(w.document()->path(), QFileInfo(kClassic).absoluteFilePath());
        QCOMPARE(w.document()->scene().title, std::string("The classic cascade"));

        QMimeData text;
        text.setUrls({QUrl::fromLocalFile(JL_SOURCE_DIR "/CMakeLists.txt")});
        QDragEnterEvent refused(QPoint(10, 10), Qt::CopyAction, &text, Qt::LeftButton, Qt::NoModifier);
        refused.setAccepted(false);
        QApplication::sendEvent(&w, &refused);
        QVERIFY(!refused.isAccepted());
    }
};

QTEST_MAIN(DocumentFilesTest)
#include "test_document_files.moc"
