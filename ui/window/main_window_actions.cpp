// The main window's actions (each with its keys, icon and tip) and its
// menus: what the menus, the toolbar and the keys all trigger.
#include "ui/edit/scene_text_dialog.h"
#include "ui/play/sim_controller.h"
#include "ui/view3d/ladder_view.h"
#include "ui/window/controls_sheet.h"
#include "ui/window/help_pages.h"
#include "ui/window/main_window.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QStyle>
#include <QUndoStack>

namespace jl::ui {

namespace {

// An action of the window: its keys, the style's icon (none for
// SP_CustomBase), and a tip that names its first key.
QAction* makeAction(QWidget* window, const QString& text, const QList<QKeySequence>& keys, QStyle::StandardPixmap icon,
                    const QString& tip) {
    auto* a = new QAction(text, window);
    a->setShortcuts(keys);
    if (icon != QStyle::SP_CustomBase) a->setIcon(window->style()->standardIcon(icon));
    a->setToolTip(tip +
                  (keys.isEmpty() ? QString() : QString(" (%1)").arg(keys.first().toString(QKeySequence::NativeText))));
    a->setStatusTip(tip);
    return a;
}

}  // namespace

void MainWindow::createActions() {
    createFileActions();
    createUndoActions();
    createPlayActions();
    createViewActions();
    connectActions();
}

void MainWindow::createFileActions() {
    newAct_ = makeAction(this, tr("&New"), QKeySequence::keyBindings(QKeySequence::New), QStyle::SP_FileIcon,
                         tr("A new ladder of six blocks"));
    openAct_ = makeAction(this, tr("&Open..."), QKeySequence::keyBindings(QKeySequence::Open),
                          QStyle::SP_DialogOpenButton, tr("Open a scene file"));
    saveAct_ = makeAction(this, tr("&Save"), QKeySequence::keyBindings(QKeySequence::Save), QStyle::SP_DialogSaveButton,
                          tr("Save the scene"));
    saveAsAct_ = makeAction(this, tr("Save &As..."), QKeySequence::keyBindings(QKeySequence::SaveAs),
                            QStyle::SP_CustomBase, tr("Save the scene under a new name"));
    revertAct_ = makeAction(this, tr("&Revert"), {}, QStyle::SP_BrowserReload,
                            tr("Throw away unsaved changes and read the file again"));
    quitAct_ = makeAction(this, tr("&Quit"), QKeySequence::keyBindings(QKeySequence::Quit), QStyle::SP_CustomBase,
                          tr("Quit the program"));
}

void MainWindow::createUndoActions() {
    undoAct_ = doc_->undoStack()->createUndoAction(this, tr("&Undo"));
    undoAct_->setShortcuts(QKeySequence::Undo);
    redoAct_ = doc_->undoStack()->createRedoAction(this, tr("&Redo"));
    // The platform's own keys (Ctrl+Shift+Z here), and Ctrl+Y everywhere, as the Help says.
    const QKeySequence ctrlY(Qt::CTRL | Qt::Key_Y);
    redoAct_->setShortcuts(QKeySequence::keyBindings(QKeySequence::Redo) << ctrlY);
    // Icons on the toolbar: its buttons would otherwise carry the changing
    // text ("Undo Change blocks") and every button after them would shift.
    undoAct_->setIcon(QIcon::fromTheme("edit-undo", style()->standardIcon(QStyle::SP_ArrowBack)));
    redoAct_->setIcon(QIcon::fromTheme("edit-redo", style()->standardIcon(QStyle::SP_ArrowForward)));
}

void MainWindow::createPlayActions() {
    playAct_ = makeAction(this, tr("&Play"), {Qt::Key_Space}, QStyle::SP_MediaPlay, tr("Play or pause the simulation"));
    stepAct_ = makeAction(this, tr("Step &forward"), {Qt::Key_Right, Qt::Key_Period}, QStyle::SP_MediaSeekForward,
                          tr("One frame forward"));
    backAct_ = makeAction(this, tr("Step &back"), {Qt::Key_Left, Qt::Key_Comma}, QStyle::SP_MediaSeekBackward,
                          tr("One frame back"));
    restartAct_ = makeAction(this, tr("&Restart"), {QKeySequence(Qt::CTRL | Qt::Key_R)}, QStyle::SP_MediaSkipBackward,
                             tr("Back to the start"));
}

void MainWindow::createViewActions() {
    resetViewAct_ = makeAction(this, tr("Reset &view"), {Qt::Key_Home}, QStyle::SP_CustomBase,
                               tr("Look at the whole ladder again"));
    frameAct_ = makeAction(this, tr("&Frame the ladder"), {Qt::Key_F}, QStyle::SP_CustomBase,
                           tr("Fit the whole ladder in the view, seen from where you are"));
    frameMotionAct_ = makeAction(
        this, tr("Frame the &moving blocks"), {Qt::Key_M}, QStyle::SP_CustomBase,
        tr("Fit the blocks that moved most in the last frame in the view: on a long ladder, where the action is"));
    frameMotionAct_->setObjectName("frameMotionAction");
    walkAct_ = makeAction(this, tr("&Walk mode"), {Qt::Key_V}, QStyle::SP_CustomBase,
                          tr("Walk around the room: W A S D to move, Q E down and up, drag to look, Esc to stop"));
    walkAct_->setCheckable(true);
    followAct_ = makeAction(this, tr("F&ollow the ladder"), {}, QStyle::SP_CustomBase,
                            tr("Move the camera with the ladder, so a ladder that swings away stays in view"));
    followAct_->setCheckable(true);
    followAct_->setObjectName("followAction");
    connect(followAct_, &QAction::toggled, this, [this](bool on) {
        view_->setFollow(on);
        QSettings().setValue("view/follow", on);
    });
    followAct_->setChecked(QSettings().value("view/follow", false).toBool());
}

void MainWindow::connectActions() {
    connect(newAct_, &QAction::triggered, this, &MainWindow::newFile);
    connect(openAct_, &QAction::triggered, this, &MainWindow::openDialog);
    connect(saveAct_, &QAction::triggered, this, &MainWindow::save);
    connect(saveAsAct_, &QAction::triggered, this, &MainWindow::saveAsDialog);
    connect(revertAct_, &QAction::triggered, this, &MainWindow::revert);
    connect(quitAct_, &QAction::triggered, this, &QWidget::close);
    connect(playAct_, &QAction::triggered, sim_, &SimController::togglePlay);
    connect(stepAct_, &QAction::triggered, sim_, &SimController::stepForward);
    connect(backAct_, &QAction::triggered, sim_, &SimController::stepBack);
    connect(restartAct_, &QAction::triggered, sim_, &SimController::restart);
    connect(resetViewAct_, &QAction::triggered, this, [this] { view_->resetView(); });
    connect(frameAct_, &QAction::triggered, this, [this] { view_->frameLadder(); });
    connect(frameMotionAct_, &QAction::triggered, this, [this] {
        if (!view_->frameMotion())
            statusBar()->showMessage(tr("Nothing moved between the last two frames: the whole ladder is framed."),
                                     4000);
    });
    connect(walkAct_, &QAction::toggled, this, [this](bool on) { view_->setWalkMode(on); });
    connect(view_, &LadderView::walkModeChanged, walkAct_, &QAction::setChecked);
}

void MainWindow::createMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addActions({newAct_, openAct_});
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addSeparator();
    file->addActions({saveAct_, saveAsAct_, revertAct_});
    file->addSeparator();
    file->addAction(quitAct_);
    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addActions({undoAct_, redoAct_});
    edit->addSeparator();
    QAction* text =
        edit->addAction(tr("&Title and Description..."), this, [this] { SceneTextDialog(doc_, this).exec(); });
    text->setObjectName("sceneTextAction");
    text->setStatusTip(tr("Edit the scene's title and description: the lesson the Lesson panel shows"));
    QMenu* sim = menuBar()->addMenu(tr("&Simulation"));
    sim->addActions({playAct_, stepAct_, backAct_, restartAct_});
    sim->addSeparator();
    sim->addAction(tr("&Design map..."), this, [this] { showDesignMap(); })->setObjectName("designMapAction");
    viewMenu_ = menuBar()->addMenu(tr("&View"));
    viewMenu_->addActions({resetViewAct_, frameAct_, frameMotionAct_, followAct_, walkAct_});
    viewMenu_->addSeparator();
    for (QDockWidget* d : findChildren<QDockWidget*>()) viewMenu_->addAction(d->toggleViewAction());
    helpMenu_ = menuBar()->addMenu(tr("&Help"));
    QMenu* help = helpMenu_;
    addHelpPages(help, this);
    QAction* controls = help->addAction(tr("&Controls"), this, [this] { showControlsSheet(this); });
    controls->setShortcut(QKeySequence::HelpContents);
    help->addAction(tr("&About"), this, [this] {
        QMessageBox::about(
            this, tr("About Jacob's Ladder Studio"),
            tr("<b>Jacob's Ladder Studio</b> %1<p>Build, simulate and teach with a virtual Jacob's ladder.</p>")
                .arg(QApplication::applicationVersion()));
    });
    updateRecentMenu();
}

}  // namespace jl::ui
