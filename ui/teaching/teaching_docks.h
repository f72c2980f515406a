// The teaching tools in one place: the side view, plots and lesson docks, the
// Lessons and Teach menus and the exports, fed from the open document and the
// simulation's status. They know the document and the controller, never the
// window: the window places the docks and menus they make.
#pragma once

#include "ui/edit/scene_change.h"
#include "ui/play/sim_status.h"

#include <QObject>

#include <memory>
#include <optional>

class QAction;
class QDockWidget;
class QMenu;
class QWidget;

namespace jl::ui {

class Document;
class LadderView;
class LessonPanel;
class Pacing;
class RunPlots;
class SideView;
class SimController;

class TeachingDocks : public QObject {
    Q_OBJECT
public:
    // `parent` owns the docks and menus and is the parent of the dialogs;
    // `view`, the 3-D view, is pictured by the exports.
    TeachingDocks(Document* doc, SimController* sim, LadderView* view, QWidget* parent);

    QDockWidget* sideViewDock() const { return sideViewDock_; }
    QDockWidget* plotsDock() const { return plotsDock_; }
    QDockWidget* lessonDock() const { return lessonDock_; }
    QMenu* lessonsMenu() const { return lessonsMenu_; }
    QMenu* teachMenu() const { return teachMenu_; }
    // Checkable; the window connects it to its presentation mode.
    QAction* presentationAction() const { return presentationAction_; }

    SideView* sideView() const { return sideView_; }
    RunPlots* plots() const { return plots_; }
    LessonPanel* lessonPanel() const { return lessonPanel_; }
    Pacing* pacing() const { return pacing_; }

    // Large type and lines, for a projector.
    void setLarge(bool on);

signals:
    // A lesson was chosen: the window asks about unsaved changes, then opens it.
    void lessonRequested(const QString& path);
    // A short message for the status bar.
    void message(const QString& text);
    // The Lesson panel's link under an edited scene's note.
    void editTextRequested();

private:
    QDockWidget* dock(const QString& title, const QString& name, QWidget* w);
    void createMenus();
    void onStatus(std::shared_ptr<const jl::ui::SimStatus> s);
    void onSceneChanged(SceneChange change = SceneChange::Whole);
    void setLook();
    void markLoop();
    void sideViewPicture();
    void viewPicture();
    // `threeD`: pictures of the 3-D view, else of the side view.
    void exportSequence(bool video, bool threeD);
    void exportEvents();
    void exportTables();
    void say(const QString& text);
    std::shared_ptr<const SimStatus> latest() const;

    Document* doc_;
    SimController* sim_;
    LadderView* view_;
    QWidget* parent_;
    SideView* sideView_;
    RunPlots* plots_;
    LessonPanel* lessonPanel_;
    Pacing* pacing_;
    QDockWidget* sideViewDock_ = nullptr;
    QDockWidget* plotsDock_ = nullptr;
    QDockWidget* lessonDock_ = nullptr;
    QMenu* lessonsMenu_ = nullptr;
    QMenu* teachMenu_ = nullptr;
    QAction* presentationAction_ = nullptr;
    bool large_ = false;
    QAction* blockNumbers_ = nullptr;
    QAction* cornerNumbers_ = nullptr;
    QAction* arrows_ = nullptr;
    std::optional<double> loopStart_;  // L pressed once: the loop starts here
    bool edited_ = false;              // the design changed since its title and description were written
};

}  // namespace jl::ui
