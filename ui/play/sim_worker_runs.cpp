// SimWorker: runs kept for Undo. A push in the past keeps the run it
// replaces; Undo and Redo of a push bring back the run of the drags they
// restore as it was kept (its frames, events and head simulation, nothing
// computed again), the run on record being kept in its turn.
#include "ui/play/sim_worker.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace jl::ui {

void SimWorker::swapRun(KeptRun& other) {
    std::swap(sim_, other.sim);
    std::swap(midFrame_, other.midFrame);
    std::swap(history_, other.history);
    std::swap(events_, other.events);
    std::swap(carried_, other.carried);
    std::swap(headHash_, other.headHash);
    std::swap(recorded_, other.recorded);
    std::swap(failure_, other.failure);
}

// Before a push cuts the run at the cursor: the run whole goes to the
// keeper, and the push's run goes on from the cursor on a new simulation
// of the same scene (discardFuture puts it in the cursor's state), the
// kept one staying at its head. Frames up to the cursor are shared.
void SimWorker::keepRunBeforePush() {
    auto built = build(sim_->scene());
    if (!built.simulation) return;
    built.simulation->setFrameGrid(frameGrid());
    KeptRun kept;
    kept.sim = std::exchange(sim_, std::move(built.simulation));
    kept.midFrame = midFrame_;
    kept.history = history_;
    kept.events = std::make_shared<std::vector<jl::Event>>(*events_);
    kept.carried = carried_;
    kept.headHash = headHash_;
    kept.recorded = std::make_shared<const jl::Scene>(kept.sim->scene());
    kept.failure = failure_;
    kept_.keep(std::move(kept), budget_);
}

void SimWorker::apply(const cmd::Recall& c) {
    std::optional<KeptRun> found = kept_.take(c.scene.drags);
    // The run on record is kept for Redo (or Undo), unless it is the one
    // asked for, or a drag is under way in it (half a gesture: not a run).
    const bool onRecord = sim_ && recorded_ && history_.count() > 0 && !sim_->dragging();
    if (onRecord && recorded_->drags == c.scene.drags) {
        feedWholeRun();
        return;
    }
    if (onRecord) {
        KeptRun current;
        swapRun(current);
        kept_.keep(std::move(current), budget_);
    }
    if (!found) {
        startRun(c.scene);
        if (c.time > 0) apply(cmd::Seek{c.time});
        return;
    }
    swapRun(*found);
    feedWholeRun();
    stoppedAtEnd_ = false;
    const int at = int(std::floor(c.time / history_.interval() + 1e-6));
    showFrame(std::clamp(at, 0, history_.head()));
    rebasePace();
}

// The run on record replaced the one the window had: a new run to the
// plots (SimStatus::loadSerial), which take its frames again from the first
// (those evicted from the history are left out: they would be computed again).
void SimWorker::feedWholeRun() {
    ++loadSerial_;
    feedFirst_ += feed_.size();
    feed_.clear();
    for (int i = 0; i < history_.count(); ++i)
        if (auto f = history_.frame(i)) feed(std::move(f));
    feedChanged_ = true;
    eventsChanged_ = true;
    dirty_ = true;
}

}  // namespace jl::ui
