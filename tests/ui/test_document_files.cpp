// labels: ui
// Files around the document: the recovery copy written while there are
// unsaved edits and removed once saved, and a scene dropped on the window.
#include "ui_test_support.h"

#include "core/scene_io.h"

#include <QFile>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QTimer>
#include <QSpinBox>
#include <QTemporaryDir>
#include <QtTest>

using namespace jlui;

namespace {
const QString kClassic = QStringLiteral(JL_SOURCE_DIR "/examples/classic.yaml");
}

class DocumentFilesTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jltest::isolateSettings(); }
    void init() { Document::removeRecovery(); }

    void theRecoveryCopyHoldsTheUnsavedSceneAndGoesAwayOnSave() {
        QTemporaryDir dir;
        MainWindow w(jltest::quietWindow());
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
            MainWindow crashed(jltest::quietWindow());
            QVERIFY(crashed.openFile(kClassic));
            crashed.findChild<QSpinBox*>("blocks")->setValue(12);
            crashed.document()->writeRecovery();
        }  // gone without a close: like a crash, the recovery copy stays
        QVERIFY(QFile::exists(Document::recoveryPath()));
        MainWindow next({true, false});
        // Answer the question the window asks.
        QTimer::singleShot(300, [] {
            if (auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget())) box->button(QMessageBox::Yes)->click();
        });
        next.offerRecovery();
        QCOMPARE(next.document()->scene().ladder->blocks, 12);
        QVERIFY(next.document()->isModified());
        QCOMPARE(next.document()->path(), QFileInfo(kClassic).absoluteFilePath());
    }

    void droppingASceneFileOnTheWindowOpensIt() {
        MainWindow w(jltest::quietWindow());
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
