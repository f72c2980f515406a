// The desktop program's window: the 3-D view and timeline in the middle, the
// Ladder, Simulation, Script and Events docks, transport controls, files.
#pragma once

#include "ui/edit/document.h"
#include "ui/play/sim_status.h"

#include <QMainWindow>

#include <chrono>
#include <memory>

class QAction;
class QDockWidget;
class QLabel;
class QMenu;
class QSlider;

namespace jl::ui {

class DesignMap;
class EventsPanel;
class LadderPanel;
class LadderView;
class PresentationMode;
class ScriptPanel;
class SimController;
class SimulationPanel;
class TeachingDocks;
class Timeline;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    struct Options {
        bool askToRecover = true;  // offer a recovery file left by a crash
        bool askToSave = true;     // prompt on closing with unsaved changes
    };
    explicit MainWindow(Options options);
    explicit MainWindow() : MainWindow(Options{}) {}
    ~MainWindow() override;

    // Opens a scene file; on errors shows them all and keeps the open scene.
    bool openFile(const QString& path);
    bool saveTo(const QString& path);
    void offerRecovery();

    Document* document() const { return doc_; }
    SimController* controller() const { return sim_; }
    LadderView* ladderView() const { return view_; }
    QWidget* viewContainer() const { return viewContainer_; }
    TeachingDocks* teaching() const { return teaching_; }
    PresentationMode* presentation() const { return presentation_; }
    // Shows the window's design map, made on first use (kept, with its cache).
    void showDesignMap();
    DesignMap* designMap() const { return designMap_; }
    void setSpeed(double factor);

protected:
    void closeEvent(QCloseEvent* e) override;
    void showEvent(QShowEvent* e) override;
    void moveEvent(QMoveEvent* e) override;
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;

private:
    void createActions();  // main_window_actions.cpp, with the menus
    void createFileActions();
    void createUndoActions();
    void createPlayActions();
    void createViewActions();
    void connectActions();
    void createMenus();
    void createToolBar();
    void createDocks();
    void createTeaching();
    void createStatusBar();
    void connectView();
    void showFailure(const QString& failure);
    void readSettings();
    void arrangeDocks();
    QSize framedBy_;              // what the window manager's frame adds, when the window was last fitted to its screen
    bool arrangeOnShow_ = false;  // no saved arrangement: the first show makes the default one
    void writeSettings() const;

    void newFile();
    void openDialog();
    bool save();
    enum class CommentsChoice { SaveOver, SaveAs, Cancel };
    CommentsChoice askAboutComments(const QString& path);
    bool saveAsDialog();
    void revert();
    bool maybeSave();
    void addRecent(const QString& path);
    void updateRecentMenu();
    void updateTitle();

    void onSceneChanged(SceneChange change);
    void onStatus(std::shared_ptr<const SimStatus> s);
    void showRunRate(const SimStatus& s);
    void showFrameNumbers(const jl::Frame& f);
    void showStopOrNote(const SimStatus& s);
    void syncRecordedDrags(const SimStatus& s);
    void simulateEdit(SceneChange change);

    Options options_;
    Document* doc_;
    SimController* sim_;
    LadderView* view_;
    QWidget* viewContainer_;
    Timeline* timeline_;
    LadderPanel* ladderPanel_;
    SimulationPanel* simulationPanel_;
    ScriptPanel* scriptPanel_;
    EventsPanel* eventsPanel_;
    QDockWidget* ladderDock_ = nullptr;
    QDockWidget* scriptDock_ = nullptr;
    QDockWidget* eventsDock_ = nullptr;
    TeachingDocks* teaching_ = nullptr;
    PresentationMode* presentation_ = nullptr;
    QMenu* helpMenu_ = nullptr;
    DesignMap* designMap_ = nullptr;
    QMenu* recentMenu_ = nullptr;
    QMenu* viewMenu_ = nullptr;
    QSlider* speedSlider_ = nullptr;
    QLabel* speedLabel_ = nullptr;
    QLabel* timeLabel_;
    QLabel* rateLabel_;
    QLabel* energyLabel_;
    QLabel* residualLabel_;
    QLabel* stepLabel_;
    QLabel* stillLabel_;
    QString shownFailure_;  // the failure last shown in full
    QLabel* warningLabel_;
    std::uint64_t loadsPosted_ = 0;
    std::uint64_t shownLoad_ = 0;
    bool playing_ = false;
    // The run up to the moment of an edit under way: where it goes, and how
    // far along it was and when it was first seen, to say how long is left.
    struct Seeking {
        double to = -1, fromProgress = 0;
        std::chrono::steady_clock::time_point since;
    } seeking_;
    double speed_ = 1.0;

    QAction* newAct_;
    QAction* openAct_;
    QAction* saveAct_;
    QAction* saveAsAct_;
    QAction* revertAct_;
    QAction* quitAct_;
    QAction* undoAct_;
    QAction* redoAct_;
    QAction* playAct_;
    QAction* stepAct_;
    QAction* backAct_;
    QAction* restartAct_;
    QAction* resetViewAct_;
    QAction* frameAct_;
    QAction* frameMotionAct_;
    QAction* walkAct_;
    QAction* followAct_;
};

}  // namespace jl::ui
