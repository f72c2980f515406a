// The main window's file handling: new, open (menu, command line, drop),
// save, recent files, revert, the unsaved-changes prompt and crash recovery.
#include "jl/scene/scene_io.h"
#include "jl/scene/yaml_comments.h"
#include "ui/play/sim_controller.h"
#include "ui/teaching/lessons.h"
#include "ui/window/file_errors_dialog.h"
#include "ui/window/main_window.h"

#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenu>
#include <QMessageBox>
#include <QMimeData>
#include <QPushButton>
#include <QSettings>
#include <QStatusBar>

namespace jl::ui {

namespace {
constexpr int kMaxRecent = 8;
const char* kSceneFilter = QT_TRANSLATE_NOOP("MainWindow", "Scene files (*.yaml *.yml);;All files (*)");

QString droppedScene(const QMimeData* mime) {
    if (!mime || !mime->hasUrls()) return {};
    for (const QUrl& url : mime->urls()) {
        const QString path = url.toLocalFile();
        if (path.endsWith(".yaml", Qt::CaseInsensitive) || path.endsWith(".yml", Qt::CaseInsensitive)) return path;
    }
    return {};
}
}  // namespace

bool MainWindow::openFile(const QString& path) {
    const std::vector<jl::Diagnostic> errors = doc_->open(path);
    if (!errors.empty()) {
        auto* dialog = new FileErrorsDialog(path, errors, this);
        dialog->open();
        return false;
    }
    addRecent(doc_->path());
    return true;
}

bool MainWindow::saveTo(const QString& path) {
    // Lessons stay as they were written: the next class opens the same one.
    if (isLesson(path)) {
        QMessageBox::warning(this, tr("Not saved"),
                             tr("%1 is a lesson, and lessons stay as they are. Save your version under "
                                "another name or in another folder, such as %2.")
                                 .arg(QFileInfo(path).fileName(), QFileInfo(saveAsProposal(path)).absolutePath()));
        return false;
    }
    if (const auto error = doc_->saveAs(path)) {
        QMessageBox::warning(this, tr("Not saved"), tr("The scene was not saved:\n%1").arg(*error));
        return false;
    }
    addRecent(doc_->path());
    statusBar()->showMessage(tr("Saved %1").arg(doc_->path()), 4000);
    return true;
}

void MainWindow::newFile() {
    if (!maybeSave()) return;
    doc_->reset(Document::newScene(), QString());
}

void MainWindow::openDialog() {
    if (!maybeSave()) return;
    const QString dir = doc_->path().isEmpty() ? QString() : QFileInfo(doc_->path()).absolutePath();
    const QString path = QFileDialog::getOpenFileName(this, tr("Open scene"), dir, tr(kSceneFilter));
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::save() {
    if (doc_->path().isEmpty() || isLesson(doc_->path())) return saveAsDialog();
    switch (askAboutComments(doc_->path())) {
        case CommentsChoice::SaveOver:
            return saveTo(doc_->path());
        case CommentsChoice::SaveAs:
            return saveAsDialog();
        case CommentsChoice::Cancel:
            return false;
    }
    return false;
}

// The writer writes the scene, not the text: the comments of a hand-written
// file would go. Before saving over such a file, say so, and offer a new
// file instead.
MainWindow::CommentsChoice MainWindow::askAboutComments(const QString& path) {
    if (!options_.askToSave) return CommentsChoice::SaveOver;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return CommentsChoice::SaveOver;  // nothing there to lose
    const QByteArray text = file.read(64 << 20);
    if (!jl::hasComments(std::string_view(text.constData(), size_t(text.size())))) return CommentsChoice::SaveOver;
    QMessageBox box(QMessageBox::Warning, tr("Comments will be lost"),
                    tr("%1 has comments (lines with #). Scene files are written from the scene itself, so saving "
                       "over it drops them. Save as a new file to keep the original as it is?")
                        .arg(QFileInfo(path).fileName()),
                    QMessageBox::NoButton, this);
    box.setObjectName("commentsWarning");
    QPushButton* saveAs = box.addButton(tr("Save As..."), QMessageBox::AcceptRole);
    QPushButton* over = box.addButton(tr("Save Over It"), QMessageBox::DestructiveRole);
    box.addButton(QMessageBox::Cancel);
    box.setDefaultButton(saveAs);
    box.exec();
    if (box.clickedButton() == over) return CommentsChoice::SaveOver;
    if (box.clickedButton() == saveAs) return CommentsChoice::SaveAs;
    return CommentsChoice::Cancel;
}

bool MainWindow::saveAsDialog() {
    QString path =
        QFileDialog::getSaveFileName(this, tr("Save scene as"), saveAsProposal(doc_->path()), tr(kSceneFilter));
    if (path.isEmpty()) return false;
    if (QFileInfo(path).suffix().isEmpty()) path += ".yaml";
    return saveTo(path);
}

void MainWindow::revert() {
    if (doc_->path().isEmpty() || !doc_->isModified()) return;
    const auto answer = QMessageBox::question(
        this, tr("Revert"), tr("Throw away the changes made since %1 was saved?").arg(doc_->displayName()));
    if (answer == QMessageBox::Yes) openFile(doc_->path());
}

bool MainWindow::maybeSave() {
    if (!doc_->isModified() || !options_.askToSave) return true;
    const auto answer = QMessageBox::warning(
        this, tr("Unsaved changes"), tr("%1 has changes that are not saved. Save them?").arg(doc_->displayName()),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Save) return save();
    return answer == QMessageBox::Discard;
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (!maybeSave()) {
        e->ignore();
        return;
    }
    writeSettings();
    // Closed on purpose: no crash to recover from.
    Document::removeRecovery();
    e->accept();
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    if (!droppedScene(e->mimeData()).isEmpty()) e->acceptProposedAction();
}

void MainWindow::dropEvent(QDropEvent* e) {
    const QString path = droppedScene(e->mimeData());
    if (path.isEmpty() || !maybeSave()) return;
    e->acceptProposedAction();
    openFile(path);
}

void MainWindow::addRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value("files/recent").toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent) recent.removeLast();
    settings.setValue("files/recent", recent);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
    if (!recentMenu_) return;
    recentMenu_->clear();
    const QStringList recent = QSettings().value("files/recent").toStringList();
    for (const QString& path : recent) {
        QAction* a = recentMenu_->addAction(QFileInfo(path).fileName(), this, [this, path] {
            if (maybeSave()) openFile(path);
        });
        a->setStatusTip(path);
    }
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::updateTitle() {
    setWindowTitle(QString("%1[*] — Jacob's Ladder Studio").arg(doc_->displayName()));
    setWindowModified(doc_->isModified());
    revertAct_->setEnabled(doc_->isModified() && !doc_->path().isEmpty());
}

// A recovery file exists only if the program stopped with unsaved edits.
void MainWindow::offerRecovery() {
    QFile file(Document::recoveryPath());
    if (!options_.askToRecover || !file.open(QIODevice::ReadOnly)) return;
    const QByteArray text = file.readAll();
    file.close();
    QString from;
    if (text.startsWith("# recovered-from: "))
        from = QString::fromUtf8(text.mid(18, text.indexOf('\n') - 18)).trimmed();
    const auto answer =
        QMessageBox::question(this, tr("Recover unsaved work"),
                              tr("The program stopped last time with unsaved changes to %1. Open the recovered copy?")
                                  .arg(from.isEmpty() ? tr("an untitled scene") : from));
    if (answer != QMessageBox::Yes) {
        Document::removeRecovery();
        return;
    }
    jl::SceneLoad load = jl::parseScene(text.toStdString(), Document::recoveryPath().toStdString());
    if (!load.scene) {
        new FileErrorsDialog(Document::recoveryPath(), load.errors, this);
        return;
    }
    doc_->reset(*load.scene, from, true);
}

}  // namespace jl::ui
