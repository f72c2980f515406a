#include "ui/play/sim_controller.h"

#include "ui/play/draw_pace.h"
#include "ui/play/sim_worker.h"

#include <QThread>

namespace jl::ui {

namespace {
constexpr std::size_t kDefaultBudget = std::size_t(512) << 20;
}

SimController::SimController(QObject* parent) : QObject(parent), worker_(std::make_unique<SimWorker>(kDefaultBudget)) {
    thread_ = QThread::create([w = worker_.get()] {
        w->run();
        w->markFinished();
    });
    thread_->setObjectName("simulation");
    thread_->start();
    poll_.setInterval(16);
    connect(&poll_, &QTimer::timeout, this, &SimController::poll);
    poll_.start();
}

SimController::~SimController() {
    worker_->abort();
    worker_->post(cmd::Quit{});
    // A single engine step cannot be interrupted; if one never ends, leave
    // the thread to the process's exit rather than hang the window's close.
    if (!worker_->waitFinished(std::chrono::milliseconds(3000))) {
        qWarning("the simulation thread did not stop; leaving it to the exit");
        (void)worker_.release();
        return;
    }
    thread_->wait();  // it has returned from run(): only the thread's exit remains
    delete thread_;
}

void SimController::load(const jl::Scene& scene) { worker_->post(cmd::Load{scene}); }
void SimController::play() { worker_->post(cmd::Play{}); }
void SimController::pause() { worker_->post(cmd::Pause{}); }
void SimController::togglePlay() {
    const auto s = status();
    if (s && s->playing)
        pause();
    else
        play();
}
void SimController::stepForward() { worker_->post(cmd::StepForward{}); }
void SimController::stepBack() { worker_->post(cmd::StepBack{}); }
void SimController::restart() { worker_->post(cmd::Restart{}); }
void SimController::seek(double time) { worker_->post(cmd::Seek{time}); }
void SimController::showInstant(double time) { worker_->post(cmd::ShowInstant{time}); }
void SimController::setSpeed(double factor) { worker_->post(cmd::Speed{factor}); }
void SimController::setDuration(double seconds) { worker_->post(cmd::Duration{seconds}); }
void SimController::setMemoryBudget(std::size_t bytes) { worker_->post(cmd::Budget{bytes}); }
void SimController::recall(const jl::Scene& scene, double time) { worker_->post(cmd::Recall{scene, time}); }
void SimController::beginDrag(const jl::Vec2& point, int block, const jl::Vec2& local, double shownTime) {
    worker_->post(cmd::DragBegin{point, block, local, shownTime});
}
void SimController::moveDrag(const jl::Vec2& target) { worker_->post(cmd::DragMove{target}); }
void SimController::endDrag() { worker_->post(cmd::DragEnd{}); }

std::shared_ptr<const SimStatus> SimController::status() const { return worker_->status(); }

void SimController::poll() {
    auto s = worker_->status();
    if (shown_ && s->serial == shown_->serial) return;
    // A run behind the clock: every other look, the processor to the simulation.
    if (shown_ && !drawNow(s->playing, s->behind, s->interval, double(sinceShown_.nsecsElapsed()) / 1e9,
                           poll_.interval() / 1000.0))
        return;
    sinceShown_.start();
    shown_ = std::move(s);
    emit statusChanged(shown_);
    if (shown_->newFrames) worker_->taken(shown_->firstNewFrame + shown_->newFrames->size());
}

}  // namespace jl::ui
