#include "ui/window/main_window.h"

#include "ui/design/design_map.h"
#include "ui/edit/change_value.h"
#include "ui/edit/ladder_panel.h"
#include "ui/edit/scene_text_dialog.h"
#include "ui/edit/script_panel.h"
#include "ui/edit/simulation_panel.h"
#include "ui/play/pacing.h"
#include "ui/play/sim_controller.h"
#include "ui/play/timeline.h"
#include "ui/teaching/events_panel.h"
#include "ui/teaching/side_view.h"
#include "ui/teaching/teaching_docks.h"
#include "ui/view3d/ladder_view.h"
#include "ui/view3d/shader_material.h"
#include "ui/window/help_pages.h"
#include "ui/window/presentation_mode.h"
#include "ui/window/screen_fit.h"

#include <QAction>
#include <QDockWidget>
#include <QLabel>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMoveEvent>
#include <QScrollArea>
#include <QScrollBar>
#include <QSettings>
#include <QShowEvent>
#include <QSignalBlocker>
#include <QSlider>
#include <QStatusBar>
#include <QStyle>
#include <QTimer>
#include <QToolBar>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace jl::ui {

namespace {
// The speed slider is logarithmic: 0.01x at the left, 4x at the right.
constexpr double kMinSpeed = 0.01, kMaxSpeed = 4.0;
constexpr int kSpeedTicks = 200;
// A run's rate is read over this many seconds before it says how long is left.
constexpr double kSecondsBeforeTimeLeft = 2.0;
int speedToTick(double s) {
    return int(std::lround(kSpeedTicks * std::log(s / kMinSpeed) / std::log(kMaxSpeed / kMinSpeed)));
}
double tickToSpeed(int t) { return kMinSpeed * std::pow(kMaxSpeed / kMinSpeed, double(t) / kSpeedTicks); }

// Paused on an event's instant, which lies between two recorded frames.
bool atInstant(const SimStatus& s) {
    return !s.playing && s.frame && std::abs(s.frame->time - s.frameIndex * s.interval) > 1e-9 * s.interval;
}

// "about 40 s", "about 8 min", "about 2.5 h": how long a run still needs.
QString durationText(double seconds) {
    if (seconds < 90) return QObject::tr("about %1 s").arg(std::max(1.0, std::round(seconds)));
    if (seconds < 5400) return QObject::tr("about %1 min").arg(std::round(seconds / 60));
    return QObject::tr("about %1 h").arg(std::round(seconds / 360) / 10);
}

QString energyText(double joules) {
    if (std::abs(joules) < 1) return QString("%1 mJ").arg(joules * 1000, 0, 'f', 3);
    return QString("%1 J").arg(joules, 0, 'f', 4);
}
}  // namespace

MainWindow::MainWindow(Options options) : options_(options) {
    ensureResources();
    setObjectName("mainWindow");
    setWindowIcon(QIcon(":/icons/jacobsladder.svg"));
    setAcceptDrops(true);
    setDockOptions(AnimatedDocks | AllowTabbedDocks);
    doc_ = new Document(this);
    sim_ = new SimController(this);

    view_ = new LadderView;
    viewContainer_ = QWidget::createWindowContainer(view_, this);
    viewContainer_->setObjectName("ladderView");
    viewContainer_->setFocusPolicy(Qt::StrongFocus);
    viewContainer_->setMinimumSize(320, 240);
    viewContainer_->setToolTip(
        tr("Left-drag a block to push it; left-drag elsewhere (or right-drag) to orbit; wheel to zoom toward the "
           "pointer; middle-drag to pan; Home resets the view; F frames the ladder, M the blocks that are moving."));
    timeline_ = new Timeline(this);
    auto* centre = new QWidget(this);
    auto* box = new QVBoxLayout(centre);
    box->setContentsMargins(0, 0, 0, 0);
    box->setSpacing(2);
    box->addWidget(viewContainer_, 1);
    box->addWidget(timeline_);
    setCentralWidget(centre);

    createActions();
    createDocks();
    createMenus();
    createToolBar();
    createStatusBar();
    connectView();

    connect(doc_, &Document::changed, this, &MainWindow::onSceneChanged);
    connect(doc_, &Document::modifiedChanged, this, &MainWindow::updateTitle);
    connect(doc_, &Document::pathChanged, this, &MainWindow::updateTitle);
    connect(sim_, &SimController::statusChanged, this, &MainWindow::onStatus);
    connect(timeline_, &Timeline::seekRequested, sim_, &SimController::seek);
    connect(timeline_, &Timeline::instantRequested, sim_, &SimController::showInstant);
    connect(eventsPanel_, &EventsPanel::instantRequested, sim_, &SimController::showInstant);
    connect(simulationPanel_, &SimulationPanel::historyMegabytesChanged, this, [this](int mb) {
        sim_->setMemoryBudget(std::size_t(mb) << 20);
        QSettings().setValue("simulation/historyMegabytes", mb);
    });

    // Side view, plots, lessons, pacing and exports (docs/teaching.md); before
    // readSettings so their docks are restored with the others.
    createTeaching();
    readSettings();
    onSceneChanged(SceneChange::Whole);
    updateTitle();
}

MainWindow::~MainWindow() = default;

void MainWindow::createToolBar() {
    QToolBar* bar = addToolBar(tr("Main"));
    bar->setObjectName("mainToolBar");
    bar->setMovable(false);
    bar->addActions({newAct_, openAct_, saveAct_});
    bar->addSeparator();
    bar->addActions({undoAct_, redoAct_});
    bar->addSeparator();
    bar->addActions({restartAct_, backAct_, playAct_, stepAct_});
    bar->addSeparator();
    auto* speedTitle = new QLabel(tr(" Speed "), bar);
    speedSlider_ = new QSlider(Qt::Horizontal, bar);
    speedSlider_->setObjectName("speed");
    speedSlider_->setRange(0, kSpeedTicks);
    speedSlider_->setFixedWidth(160);
    speedSlider_->setToolTip(tr("Simulated seconds per real second, from 0.01x (slow motion) to 4x."));
    speedLabel_ = new QLabel(bar);
    speedLabel_->setMinimumWidth(52);
    bar->addWidget(speedTitle);
    bar->addWidget(speedSlider_);
    bar->addWidget(speedLabel_);
    connect(speedSlider_, &QSlider::valueChanged, this, [this](int t) { setSpeed(tickToSpeed(t)); });
    bar->addSeparator();
    bar->addActions({resetViewAct_, walkAct_});
}

void MainWindow::setSpeed(double factor) {
    speed_ = std::clamp(factor, kMinSpeed, kMaxSpeed);
    sim_->setSpeed(speed_);
    speedLabel_->setText(QString("%1×").arg(speed_, 0, 'f', speed_ < 0.1 ? 2 : (speed_ < 1 ? 2 : 1)));
    const QSignalBlocker block(speedSlider_);
    speedSlider_->setValue(speedToTick(speed_));
}

void MainWindow::createDocks() {
    auto dock = [this](const QString& title, const QString& name, QWidget* w, Qt::DockWidgetArea area) {
        auto* d = new QDockWidget(title, this);
        d->setObjectName(name);
        d->setWidget(w);
        addDockWidget(area, d);
        return d;
    };
    ladderPanel_ = new LadderPanel(doc_, this);
    connect(ladderPanel_, &LadderPanel::designMapRequested, this, [this] { showDesignMap(); });
    simulationPanel_ = new SimulationPanel(doc_, this);
    scriptPanel_ = new ScriptPanel(doc_, this);
    eventsPanel_ = new EventsPanel(this);
    // The long forms scroll rather than hold the window up: the left column
    // would otherwise be as tall as the Ladder form (600 px) and leave the
    // plots too little height.
    auto scrolled = [this](QWidget* form) {
        auto* area = new QScrollArea(this);
        area->setWidget(form);
        area->setWidgetResizable(true);
        area->setFrameShape(QFrame::NoFrame);
        // Only up and down: the column keeps the form's width.
        area->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
        area->setMinimumWidth(form->minimumSizeHint().width() + area->verticalScrollBar()->sizeHint().width());
        return area;
    };
    ladderDock_ = dock(tr("Ladder"), "ladderDock", scrolled(ladderPanel_), Qt::LeftDockWidgetArea);
    QDockWidget* simDock = dock(tr("Simulation"), "simulationDock", scrolled(simulationPanel_), Qt::LeftDockWidgetArea);
    scriptDock_ = dock(tr("Script"), "scriptDock", scriptPanel_, Qt::RightDockWidgetArea);
    QDockWidget* scriptDock = scriptDock_;
    eventsDock_ = dock(tr("Events"), "eventsDock", eventsPanel_, Qt::RightDockWidgetArea);
    QDockWidget* eventsDock = eventsDock_;
    tabifyDockWidget(ladderDock_, simDock);
    ladderDock_->raise();
    splitDockWidget(scriptDock, eventsDock, Qt::Vertical);
    // The event log grows while the script stays short: give the log the room.
    resizeDocks({scriptDock, eventsDock}, {200, 520}, Qt::Vertical);
    resizeDocks({scriptDock}, {380}, Qt::Horizontal);
}

// One design map per window, kept when closed: reopening shows its last map.
void MainWindow::showDesignMap() {
    if (!designMap_) designMap_ = new DesignMap(doc_, this);
    designMap_->show();
    designMap_->raise();
    designMap_->activateWindow();
}

// The teaching tools make their docks and menus; the window places them.
void MainWindow::createTeaching() {
    teaching_ = new TeachingDocks(doc_, sim_, view_, this);
    connect(teaching_->sideView(), &SideView::turnGiven, scriptPanel_, &ScriptPanel::addTurn);
    connect(teaching_->sideView(), &SideView::actionGiven, scriptPanel_, &ScriptPanel::addAction);
    connect(teaching_, &TeachingDocks::lessonRequested, this, [this](const QString& path) {
        if (maybeSave()) openFile(path);
    });
    connect(teaching_, &TeachingDocks::message, this,
            [this](const QString& text) { statusBar()->showMessage(text, 5000); });
    connect(teaching_->pacing(), &Pacing::loopChanged, this, [this](bool on) {
        const Pacing* pacing = teaching_->pacing();
        timeline_->setLoop(on ? std::make_optional(std::make_pair(pacing->loopFrom(), pacing->loopTo()))
                              : std::nullopt);
    });
    connect(teaching_, &TeachingDocks::editTextRequested, this, [this] { SceneTextDialog(doc_, this).exec(); });
    QDockWidget* side = teaching_->sideViewDock();
    addDockWidget(Qt::RightDockWidgetArea, side);
    // The script is seldom edited in class: the side view shares its place, in front.
    tabifyDockWidget(scriptDock_, side);
    side->raise();
    // Tabifying forgets the column's width the window asked for: ask again;
    // and the side view, in front, gets the larger part of the column's height.
    resizeDocks({side}, {std::max(380, scriptDock_->width())}, Qt::Horizontal);
    resizeDocks({side, eventsDock_}, {460, 260}, Qt::Vertical);
    addDockWidget(Qt::BottomDockWidgetArea, teaching_->plotsDock());
    addDockWidget(Qt::LeftDockWidgetArea, teaching_->lessonDock());
    tabifyDockWidget(ladderDock_, teaching_->lessonDock());
    // Before Help, which stays last.
    menuBar()->insertMenu(helpMenu_->menuAction(), teaching_->lessonsMenu());
    menuBar()->insertMenu(helpMenu_->menuAction(), teaching_->teachMenu());
    // In presentation mode the views stay; the editing panels go.
    presentation_ = new PresentationMode(this, {side, teaching_->plotsDock(), teaching_->lessonDock()}, playAct_);
    connect(teaching_->presentationAction(), &QAction::triggered, presentation_, &PresentationMode::toggle);
    connect(presentation_, &PresentationMode::activeChanged, teaching_->presentationAction(), &QAction::setChecked);
    connect(presentation_, &PresentationMode::activeChanged, teaching_, &TeachingDocks::setLarge);
    connect(presentation_, &PresentationMode::activeChanged, presentation_, &PresentationMode::arrangeDocks);
}

void MainWindow::createStatusBar() {
    auto label = [this](const QString& name, const QString& tip, int width) {
        auto* l = new QLabel(this);
        l->setObjectName(name);
        l->setToolTip(tip);
        l->setMinimumWidth(width);
        statusBar()->addPermanentWidget(l);
        return l;
    };
    warningLabel_ = new QLabel(this);
    warningLabel_->setObjectName("warning");
    warningLabel_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
    statusBar()->addWidget(warningLabel_, 1);
    timeLabel_ =
        label("time", tr("Simulated time of the frame on screen, and how far the run has been recorded."), 150);
    rateLabel_ = label("rate",
                       tr("Real-time factor (simulated seconds per second of the clock, over the last 2 s of "
                          "playing) and solver steps per second; "
                          "after an edit, how far the run back to the moment on screen has got."),
                       190);
    energyLabel_ =
        label("energy", tr("Kinetic plus potential energy; in brackets, what the energy books fail to explain."), 190);
    residualLabel_ = label("residual", tr("Largest gap left in a hinge pin after the last step."), 130);
    stepLabel_ = label("step",
                       tr("The integrator's last step: the scene's own; (auto) the engine's choice, at most 1 ms "
                          "and short enough to stay stable on long ladders; or (adaptive) the one the adaptive "
                          "integrator's error control chose for its tolerance."),
                       150);
    stillLabel_ = label("still",
                        tr("Blocks the motion has not reached yet: they hang still, joined into a few rigid "
                           "bodies, until it comes near them. The same motion, for much less computing "
                           "(docs/model.md section 3.7; solver.still_tail: separate turns it off)."),
                        120);
    stillLabel_->hide();
    linkStatusBarToConcepts(this);
}

void MainWindow::connectView() {
    connect(view_, &LadderView::dragBegun, sim_, &SimController::beginDrag);
    connect(view_, &LadderView::dragMoved, sim_, &SimController::moveDrag);
    connect(view_, &LadderView::dragEnded, sim_, &SimController::endDrag);
    connect(view_, &LadderView::turnGiven, scriptPanel_, &ScriptPanel::addTurn);
    connect(view_, &LadderView::actionGiven, scriptPanel_, &ScriptPanel::addAction);
    // The embedded 3-D window keeps the keyboard: its keys still reach our shortcuts.
    connect(view_, &LadderView::unhandledKey, this, [this](const QKeySequence& key) {
        for (QAction* a : findChildren<QAction*>())
            if (a->isEnabled() && a->shortcuts().contains(key)) return a->trigger();
    });
}

void MainWindow::onSceneChanged(SceneChange change) {
    const jl::Scene& scene = doc_->scene();
    if (change == SceneChange::Text) return;  // words: the panels that show them follow the document
    if (change == SceneChange::Duration) {
        // Only where the lesson ends: the motion is the same, nothing runs again.
        timeline_->setDuration(scene.duration);
        simulationPanel_->refresh();
        sim_->setDuration(scene.duration);
        return;
    }
    if (change == SceneChange::Drags) {
        // Drags the running simulation recorded itself need no rebuild (a
        // status from before a recall still on its way does not tell).
        const auto s = sim_->shown();
        if (s && s->loadSerial == loadsPosted_ && s->recorded && s->recorded->drags == scene.drags) return;
    }
    view_->setScene(scene, change == SceneChange::Whole);
    timeline_->setDuration(scene.duration);
    ladderPanel_->refresh();
    simulationPanel_->refresh();
    scriptPanel_->refresh();
    simulateEdit(change);
}

void MainWindow::onStatus(std::shared_ptr<const SimStatus> s) {
    if (s->frame) view_->showFrame(s->frame);
    timeline_->setState(s->frame ? s->frame->time : s->frameIndex * s->interval, s->headTime, s->events);
    eventsPanel_->setEvents(s->events);
    eventsPanel_->setTime(s->frame ? s->frame->time : 0);
    if (s->playing != playing_) {
        playing_ = s->playing;
        playAct_->setIcon(style()->standardIcon(playing_ ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
        playAct_->setText(playing_ ? tr("&Pause") : tr("&Play"));
    }
    const double t = s->frame ? s->frame->time : 0;
    timeLabel_->setText(tr("t = %1 s  (of %2 s)").arg(t, 0, 'f', 3).arg(s->headTime, 0, 'f', 2));
    showRunRate(*s);
    if (s->frame) showFrameNumbers(*s->frame);
    showStopOrNote(*s);
    syncRecordedDrags(*s);
}

// What the run is doing: running to an instant (how far, how long left),
// replaying, playing (at what rate), or paused (where).
void MainWindow::showRunRate(const SimStatus& s) {
    // A long ladder can take a while to run again up to the moment an edit
    // was made at (or to an event's instant): say so, rather than "paused"
    // while the frames move on, and, once it has run a few seconds, about
    // how long it still needs.
    if (s.seekingTo <= 0) seeking_.to = -1;
    if (s.seekingTo > 0) {
        const auto now = std::chrono::steady_clock::now();
        if (seeking_.to != s.seekingTo) seeking_ = {s.seekingTo, s.seekProgress, now};
        QString done = tr("%1 %").arg(std::floor(100 * s.seekProgress), 0, 'f', 0);
        const double wall = std::chrono::duration<double>(now - seeking_.since).count();
        const double ran = s.seekProgress - seeking_.fromProgress;
        if (wall >= kSecondsBeforeTimeLeft && ran > 0)
            done = tr("%1, %2 left").arg(done, durationText((1 - s.seekProgress) * wall / ran));
        rateLabel_->setText(tr("running to t = %1 s (%2)").arg(s.seekingTo, 0, 'f', 3).arg(done));
    } else if (s.playing && s.frameIndex < s.frameCount - 1)
        // Frames recorded earlier: nothing is simulated, so no rate to measure.
        rateLabel_->setText(tr("replaying recorded frames at %1×").arg(s.speed, 0, 'f', 2));
    else if (s.playing)
        rateLabel_->setText(s.realTimeFactor < 0 ? tr("playing; measuring the rate")
                                                 : tr("%1× real time over %2 s · %3 steps/s")
                                                       .arg(s.realTimeFactor, 0, 'f', 2)
                                                       .arg(s.rateSpan, 0, 'f', 1)
                                                       .arg(s.stepsPerSecond, 0, 'f', 0));
    else if (atInstant(s))
        rateLabel_->setText(tr("paused between frames %1 and %2").arg(s.frameIndex).arg(s.frameIndex + 1));
    else
        rateLabel_->setText(tr("paused at frame %1 of %2").arg(s.frameIndex).arg(s.frameCount - 1));
}

// The frame's energy, the pins' gap, the step and the still blocks.
void MainWindow::showFrameNumbers(const jl::Frame& f) {
    const jl::EnergyFrame& e = f.energy;
    energyLabel_->setText(tr("E = %1  (books %2)").arg(energyText(e.total()), energyText(e.balance())));
    residualLabel_->setText(tr("gap %1 m").arg(f.solver.residual, 0, 'e', 1));
    const jl::SolverFrame& solver = f.solver;
    const QString step = QString::number(solver.lastStep * 1e3, 'g', 3);
    // Before the first step there is no step to show (the engine's own
    // is chosen at each step, from the forces of that moment).
    if (solver.steps == 0)
        stepLabel_->setText(tr("no step yet"));
    else
        stepLabel_->setText(solver.adaptiveStep    ? tr("step %1 ms (adaptive)").arg(step)
                            : solver.automaticStep ? tr("step %1 ms (auto)").arg(step)
                                                   : tr("step %1 ms").arg(step));
    // A long ladder: how many of its blocks the motion has not reached.
    const int blocks = int(f.hinges.size()) + 1;
    stillLabel_->setVisible(solver.stillFrom >= 0);
    if (solver.stillFrom >= 0) stillLabel_->setText(tr("%L1 blocks still").arg(blocks - solver.stillFrom));
}

// Why the run stopped, in red; else what is happening now (a push, the
// events of the instant shown).
void MainWindow::showStopOrNote(const SimStatus& s) {
    if (!s.failure.empty()) {
        const QString failure = QString::fromStdString(s.failure);
        warningLabel_->setStyleSheet("color: #b00020; font-weight: bold;");
        warningLabel_->setText(tr("Stopped: %1").arg(failure));
        warningLabel_->setToolTip(failure);
        if (failure != shownFailure_) showFailure(failure);
    } else {
        warningLabel_->setStyleSheet({});
        QString note;
        if (s.dragging)
            note = tr("Pushing a block: release the button to let go.");
        else if (atInstant(s))
            note = eventsInWords(s.frame->events);
        warningLabel_->setText(note);
    }
}

// A failure says what failed, where and what to try, which is more than the
// status bar's width: the whole of it in a message that does not block the
// window (the last good frame stays on show to be looked at).
void MainWindow::showFailure(const QString& failure) {
    shownFailure_ = failure;
    auto* box = findChild<QMessageBox*>("failureMessage");
    if (!box) {
        box = new QMessageBox(QMessageBox::Warning, tr("The simulation stopped"), {}, QMessageBox::Ok, this);
        box->setObjectName("failureMessage");
        box->setModal(false);
    }
    box->setText(tr("The simulation stopped and keeps its last good state."));
    box->setInformativeText(failure);
    box->show();
}

// A finished mouse drag becomes part of the scene (saved, undoable), so a
// replay of the file reproduces it.
void MainWindow::syncRecordedDrags(const SimStatus& s) {
    if (s.loadSerial != loadsPosted_ || s.dragging || !s.recorded) return;
    if (s.recorded->drags == doc_->scene().drags) return;
    changeScene(doc_,
                SceneField<std::vector<jl::DragRecord>>{
                    UndoId::RecordDrag, "drags", SceneChange::Drags, [](const jl::Scene& sc) { return sc.drags; },
                    [](jl::Scene& sc, const std::vector<jl::DragRecord>& v) { sc.drags = v; }},
                s.recorded->drags, tr("Push a block"));
}

// The default sizes of the docks, asked for once the window is shown at its
// size (before, the layout shares out whatever size the window had then,
// and the result depended on the screen): the side view gets most of its
// column, the plots room for the energy chart's eight names.
void MainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    if (!arrangeOnShow_) return;
    arrangeOnShow_ = false;
    QTimer::singleShot(0, this, &MainWindow::arrangeDocks);
}

// A window manager frames the window only after it is shown, so the fit made
// before (readSettings) counted no title bar, and the status bar ended below
// the screen's edge. The frame's arrival moves the window: fit it again then,
// once for each new frame, so that a window the user moved or sized later is
// left alone.
void MainWindow::moveEvent(QMoveEvent* e) {
    QMainWindow::moveEvent(e);
    const QSize frame = frameGeometry().size() - size();
    if (frame == framedBy_) return;
    framedBy_ = frame;
    QTimer::singleShot(0, this, [this] { fitToScreen(this); });
}

void MainWindow::arrangeDocks() {
    QDockWidget* side = teaching_->sideViewDock();
    resizeDocks({side, eventsDock_}, {460, 260}, Qt::Vertical);
    resizeDocks({teaching_->plotsDock()}, {270}, Qt::Vertical);
}

void MainWindow::readSettings() {
    QSettings settings;
    if (!restoreGeometry(settings.value("window/geometry").toByteArray())) resize(1440, 900);
    fitToScreen(this);  // saved on a larger screen, or the default on a small one
    arrangeOnShow_ = !restoreState(settings.value("window/state").toByteArray());
    setSpeed(settings.value("simulation/speed", 1.0).toDouble());
    const int budgetMb = settings.value("simulation/historyMegabytes", 512).toInt();
    sim_->setMemoryBudget(std::size_t(budgetMb) << 20);
    simulationPanel_->setHistoryMegabytes(budgetMb);
}

void MainWindow::writeSettings() const {
    QSettings settings;
    settings.setValue("window/geometry", saveGeometry());
    settings.setValue("window/state", saveState());
    settings.setValue("simulation/speed", speed_);
}

}  // namespace jl::ui
