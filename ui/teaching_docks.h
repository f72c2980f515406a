// What the teaching tools add to the main window, in one place: the side
// view, plots and lesson docks, the Lessons and Teach menus and the exports,
// fed from the simulation's status and the open document.
#pragma once

#include "ui/sim_status.h"

#include <QObject>

#include <memory>
#include <optional>

class QAction;
class QDockWidget;

namespace jl::ui {

class LessonPanel;
class MainWindow;
class Pacing;
class PresentationMode;
class RunPlots;
class SideView;

class TeachingDocks : public QObject {
    Q_OBJECT
public:
    // Call once the window has its docks and menus, before it restores its
    // saved layout (so the new docks are restored too).
    explicit TeachingDocks(MainWindow* window);

    SideView* sideView() const { return sideView_; }
    RunPlots* plots() const { return plots_; }
    LessonPanel* lessonPanel() const { return lessonPanel_; }
    Pacing* pacing() const { return pacing_; }
    PresentationMode* presentation() const { return presentation_; }

signals:
    // A lesson was chosen: the window asks about unsaved changes, then opens it.
    void lessonRequested(const QString& path);

private:
    QDockWidget* dock(const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area);
    void createMenus();
    void onStatus(std::shared_ptr<const jl::ui::SimStatus> s);
    void onSceneChanged();
    void setLook();
    void markLoop();
    void sideViewPicture();
    void exportSequence(bool video);
    void exportEvents();
    void exportTables();
    void say(const QString& text);
    std::shared_ptr<const SimStatus> latest() const;

    MainWindow* window_;
    SideView* sideView_;
    RunPlots* plots_;
    LessonPanel* lessonPanel_;
    Pacing* pacing_;
    PresentationMode* presentation_;
    QDockWidget* lessonDock_ = nullptr;
    QAction* blockNumbers_ = nullptr;
    QAction* cornerNumbers_ = nullptr;
    QAction* arrows_ = nullptr;
    std::optional<double> loopStart_;  // L pressed once: the loop starts here
};

}  // namespace jl::ui
