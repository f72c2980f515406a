#include "ui/teaching/teaching_docks.h"

#include "ui/edit/document.h"
#include "ui/play/pacing.h"
#include "ui/play/sim_controller.h"
#include "ui/teaching/exporter.h"
#include "ui/teaching/lessons.h"
#include "ui/teaching/run_plots.h"
#include "ui/teaching/sequence_dialog.h"
#include "ui/teaching/side_view.h"
#include "ui/view3d/ladder_view.h"
#include "ui/view3d/view_capture.h"
#include "ui/window/presentation_mode.h"

#include <QAction>
#include <QApplication>
#include <QDockWidget>
#include <QFileDialog>
#include <QMenu>
#include <QMessageBox>
#include <QProgressDialog>
#include <QSignalBlocker>
#include <QTimer>

namespace jl::ui {

TeachingDocks::TeachingDocks(Document* doc, SimController* sim, LadderView* view, QWidget* parent)
    : QObject(parent), doc_(doc), sim_(sim), view_(view), parent_(parent) {
    setObjectName("teaching");
    sideView_ = new SideView(parent);
    plots_ = new RunPlots(parent);
    lessonPanel_ = new LessonPanel(parent);
    pacing_ = new Pacing(sim, this);
    sideViewDock_ = dock(tr("Side view"), "sideViewDock", sideView_);
    plotsDock_ = dock(tr("Plots"), "plotsDock", plots_);
    lessonDock_ = dock(tr("Lesson"), "lessonDock", lessonPanel_);
    createMenus();

    connect(sim, &SimController::statusChanged, this, &TeachingDocks::onStatus);
    connect(plots_, &RunPlots::seekRequested, sim, &SimController::seek);
    connect(doc, &Document::changed, this, &TeachingDocks::onSceneChanged);
    connect(pacing_, &Pacing::message, this, &TeachingDocks::say);
    connect(lessonPanel_, &LessonPanel::editTextRequested, this, &TeachingDocks::editTextRequested);
    onSceneChanged();
}

QDockWidget* TeachingDocks::dock(const QString& title, const QString& name, QWidget* w) {
    auto* d = new QDockWidget(title, parent_);
    d->setObjectName(name);
    d->setWidget(w);
    return d;
}

void TeachingDocks::setLarge(bool on) {
    large_ = on;
    setLook();
    plots_->setLarge(on);
    lessonPanel_->setLarge(on);
}

void TeachingDocks::createMenus() {
    auto* lessons = new LessonsMenu(findLessons(lessonsDirectory()), parent_);
    connect(lessons, &LessonsMenu::openRequested, this, &TeachingDocks::lessonRequested);
    lessonsMenu_ = lessons;

    auto* teach = new QMenu(tr("&Teach"), parent_);
    teach->setObjectName("teachMenu");
    teachMenu_ = teach;
    auto add = [this, teach](const QString& text, const QKeySequence& key, const QString& tip, auto slot) {
        QAction* a = teach->addAction(text);
        a->setShortcut(key);
        a->setStatusTip(tip);
        a->setToolTip(tip);
        connect(a, &QAction::triggered, this, slot);
        return a;
    };
    add(tr("Run to the next &event"), Qt::Key_N,
        tr("Show the ladder at the instant of the next event, simulating on if needed"),
        [this] { pacing_->runToNextEvent(); });
    add(tr("&Loop a stretch"), Qt::Key_L,
        tr("Press once where the loop starts and once where it ends; press again to stop looping"),
        [this] { markLoop(); });
    presentationAction_ = teach->addAction(tr("&Presentation mode"));
    presentationAction_->setShortcut(Qt::Key_F5);
    presentationAction_->setStatusTip(tr("Full screen, large type, only the views; Esc or F5 to leave"));
    presentationAction_->setToolTip(presentationAction_->statusTip());
    presentationAction_->setCheckable(true);
    teach->addSeparator();
    auto toggle = [this, teach](const QString& text, const QKeySequence& key, bool on) {
        QAction* a = teach->addAction(text);
        a->setCheckable(true);
        a->setChecked(on);
        a->setShortcut(key);
        connect(a, &QAction::toggled, this, &TeachingDocks::setLook);
        return a;
    };
    blockNumbers_ = toggle(tr("&Block numbers"), Qt::Key_B, true);
    cornerNumbers_ = toggle(tr("&Corner numbers (0-3)"), Qt::Key_K, false);
    arrows_ = toggle(tr("Lengthwise &orientation arrows"), Qt::Key_O, false);
    teach->addSeparator();
    QMenu* exports = teach->addMenu(tr("E&xport"));
    exports->setObjectName("exportMenu");
    exports->addAction(tr("3-D view as a p&icture..."), this, &TeachingDocks::viewPicture);
    exports->addAction(tr("3-D view as a vi&deo (ffmpeg)..."), this, [this] { exportSequence(true, true); });
    exports->addAction(tr("Side view as a &picture..."), this, &TeachingDocks::sideViewPicture);
    exports->addAction(tr("&Image sequence..."), this, [this] { exportSequence(false, false); });
    exports->addAction(tr("&Video (ffmpeg)..."), this, [this] { exportSequence(true, false); });
    exports->addAction(tr("&Event log as CSV..."), this, &TeachingDocks::exportEvents);
    exports->addAction(tr("&Tables as CSV (poses, energies, events)..."), this, &TeachingDocks::exportTables);
    teach->addSeparator();
    for (QDockWidget* d : {sideViewDock_, plotsDock_, lessonDock_}) teach->addAction(d->toggleViewAction());
}

void TeachingDocks::setLook() {
    SideViewOptions o = sideView_->options();
    o.blockNumbers = blockNumbers_->isChecked();
    o.cornerNumbers = cornerNumbers_->isChecked();
    o.orientation = arrows_->isChecked();
    o.scale = large_ ? 2.0 * presentationSize(sideView_) : 1.0;
    sideView_->setOptions(o);
}

void TeachingDocks::onSceneChanged(SceneChange change) {
    const jl::Scene& scene = doc_->scene();
    sideView_->setScene(scene);
    plots_->setDuration(scene.duration);
    plots_->setTurning((scene.ladder ? scene.ladder->blocks : 0) + int(scene.bodies.size()));
    // New words describe the scene as it is; a change to the design (not a
    // drag, not where the lesson ends) may leave the old ones wrong, unless
    // it was undone back to the file. Whether it was is known once the undo
    // stack has taken the edit (its command runs before it is counted).
    if (change == SceneChange::Text) edited_ = false;
    lessonPanel_->showScene(scene, edited_);
    if (change == SceneChange::Text || change == SceneChange::Drags || change == SceneChange::Duration) return;
    QTimer::singleShot(0, this, [this] {
        if (edited_ == doc_->isModified()) return;
        edited_ = doc_->isModified();
        lessonPanel_->showScene(doc_->scene(), edited_);
    });
}

void TeachingDocks::onStatus(std::shared_ptr<const SimStatus> s) {
    if (s->frame && s->frame.get() != &sideView_->frame()) sideView_->showFrame(s->frame);
    plots_->showStatus(*s);
}

std::shared_ptr<const SimStatus> TeachingDocks::latest() const { return sim_->status(); }

void TeachingDocks::say(const QString& text) { emit message(text); }

void TeachingDocks::markLoop() {
    const auto s = latest();
    const double now = s && s->frame ? s->frame->time : 0;
    if (pacing_->looping()) {
        pacing_->clearLoop();
        loopStart_.reset();
        return say(tr("Looping stopped."));
    }
    if (!loopStart_) {
        loopStart_ = now;
        return say(tr("The loop starts at %1 s: press L again where it should end.").arg(now, 0, 'f', 3));
    }
    const double a = std::min(*loopStart_, now), b = std::max(*loopStart_, now);
    loopStart_.reset();
    if (b - a < 1e-6) return say(tr("The loop needs two different times."));
    pacing_->setLoop(a, b);
    sim_->seek(a);
    sim_->play();
    say(tr("Looping from %1 s to %2 s: press L to stop.").arg(a, 0, 'f', 3).arg(b, 0, 'f', 3));
}

void TeachingDocks::sideViewPicture() {
    const QString path =
        QFileDialog::getSaveFileName(parent_, tr("Side view as a picture"), "side-view.png", tr("PNG picture (*.png)"));
    if (path.isEmpty()) return;
    // Twice the size on screen: sharp on slides.
    if (!sideView_->render(sideView_->size() * 2).save(path, "PNG"))
        QMessageBox::warning(parent_, tr("Not exported"), tr("Could not write the picture %1.").arg(path));
}

void TeachingDocks::viewPicture() {
    const QString path =
        QFileDialog::getSaveFileName(parent_, tr("3-D view as a picture"), "ladder.png", tr("PNG picture (*.png)"));
    if (path.isEmpty()) return;
    const ExportResult result = Exporter::viewPicture(view_, path);
    if (!result.ok)
        QMessageBox::warning(parent_, tr("Not exported"), result.error);
    else
        say(tr("Exported %1.").arg(path));
}

void TeachingDocks::exportSequence(bool video, bool threeD) {
    const auto s = latest();
    if (video && Exporter::ffmpeg().isEmpty()) {
        QMessageBox::information(parent_, tr("Export a video"), Exporter::ffmpegMissing());
        return;
    }
    const double head = s ? s->headTime : 0;
    const double end = head > 0 ? head : doc_->scene().duration;
    SequenceDialog dialog(video ? SequenceDialog::Kind::Video : SequenceDialog::Kind::Pictures, 0, end,
                          std::max(end, doc_->scene().duration), parent_);
    if (dialog.exec() != QDialog::Accepted) return;
    SequenceRequest r = dialog.request();
    r.look = sideView_->options();
    if (threeD) r.painter = viewPainter(view_);
    QProgressDialog progress(tr("Drawing the pictures..."), tr("Cancel"), 0, Exporter::frameCount(r.from, r.to, r.fps),
                             parent_);
    progress.setWindowModality(Qt::WindowModal);
    r.progress = [&progress](int done, int) {
        progress.setValue(done);
        QApplication::processEvents();
        return !progress.wasCanceled();
    };
    // The run as recorded, with the user's drags: the pictures show what was on screen.
    const jl::Scene scene = s && s->recorded ? *s->recorded : doc_->scene();
    // The 3-D view draws the exported frames: the run on screen must not
    // draw its own into it meanwhile, and comes back after.
    if (threeD) sim_->pause();
    std::optional<QSignalBlocker> quiet;
    if (threeD) quiet.emplace(sim_);
    const ExportResult result = video ? Exporter::video(scene, r, dialog.target()) : Exporter::imageSequence(scene, r);
    quiet.reset();
    // The views missed what the run published meanwhile (a pause): they get the latest.
    if (const auto now = latest(); threeD && now) emit sim_->statusChanged(now);
    progress.reset();
    if (!result.ok)
        QMessageBox::warning(parent_, tr("Not exported"), result.error);
    else
        say(tr("Exported %n file(s).", nullptr, int(result.files.size())));
}

void TeachingDocks::exportTables() {
    const QString dir =
        QFileDialog::getExistingDirectory(parent_, tr("Folder for poses.csv, energy.csv and events.csv"));
    if (dir.isEmpty()) return;
    const auto s = latest();
    // Every frame of the recorded run, as the timeline has them.
    const jl::Scene scene = s && s->recorded ? *s->recorded : doc_->scene();
    const double end = s && s->headTime > 0 ? s->headTime : scene.duration;
    const ExportResult result = Exporter::tables(scene, 0, end, scene.solver.frameInterval, dir);
    if (!result.ok)
        QMessageBox::warning(parent_, tr("Not exported"), result.error);
    else
        say(tr("Wrote %1.").arg(result.files.join(", ")));
}

void TeachingDocks::exportEvents() {
    const auto s = latest();
    const QString path =
        QFileDialog::getSaveFileName(parent_, tr("Event log as CSV"), "events.csv", tr("CSV table (*.csv)"));
    if (path.isEmpty()) return;
    const ExportResult result = Exporter::eventsCsv(s && s->events ? *s->events : std::vector<jl::Event>{}, path);
    if (!result.ok) QMessageBox::warning(parent_, tr("Not exported"), result.error);
}

}  // namespace jl::ui
