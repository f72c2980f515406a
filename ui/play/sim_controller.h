// The UI's handle on the running simulation: posts commands to the worker
// thread and, on a ~60 Hz timer, picks up the newest published status.
#pragma once

#include "jl/base/geometry.h"
#include "jl/scene/scene.h"
#include "ui/play/sim_status.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <memory>

class QThread;

namespace jl::ui {

class SimWorker;

class SimController : public QObject {
    Q_OBJECT
public:
    explicit SimController(QObject* parent = nullptr);
    ~SimController() override;

    void load(const jl::Scene& scene);
    void play();
    void pause();
    void togglePlay();
    void stepForward();
    void stepBack();
    void restart();
    void seek(double time);  // s; beyond the head it simulates up to there
    // The state at exactly `time` (an event's instant), between two frames.
    void showInstant(double time);
    void setSpeed(double factor);      // 0.01 .. 4
    void setDuration(double seconds);  // the scene's length, where playing stops
    void setMemoryBudget(std::size_t bytes);
    // Only the drags changed (Undo or Redo of a push): the run of `scene`,
    // shown at `time`; a run kept since it was replaced comes back as it was.
    void recall(const jl::Scene& scene, double time);
    // The mouse spring: `point` and `target` lie in the ladder's plane (m).
    // A push on `block` at `local` (its own frame), as the view found it in
    // the frame of time `shownTime` it showed (block -1: whatever block the
    // worker finds at `point` in its own state).
    void beginDrag(const jl::Vec2& point, int block = -1, const jl::Vec2& local = jl::Vec2::Zero(),
                   double shownTime = -1);
    void moveDrag(const jl::Vec2& target);
    void endDrag();

    // The newest status the worker published; never waits on the worker.
    std::shared_ptr<const SimStatus> status() const;
    // The status the views last drew (updated by the timer).
    std::shared_ptr<const SimStatus> shown() const { return shown_; }

signals:
    void statusChanged(std::shared_ptr<const jl::ui::SimStatus> status);

private:
    void poll();

    std::unique_ptr<SimWorker> worker_;
    QThread* thread_ = nullptr;
    QTimer poll_;
    std::shared_ptr<const SimStatus> shown_;
    QElapsedTimer sinceShown_;  // since shown_ was taken (draw_pace.h)
};

}  // namespace jl::ui
