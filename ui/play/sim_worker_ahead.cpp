// SimWorker: frames made ahead of the clock. Playing on time, the worker
// goes on making up to kAheadFrames frames past the last one recorded, and
// keeps them back: each goes to the history, the events and the window
// only when the clock reaches it, exactly as if it had been made then. So
// the slack of a stretch the engine runs faster than real time carries the
// run through one it runs slower (the 1,000-block classic needs 0.15 to
// 0.65 of a core up to t = 4 s, then 1.2 to 1.6 up to t = 5.5 s: on a
// slow day 0.8 s short, docs/desktop-performance.md). Any command that
// reaches the head simulation first puts it back at the history's head
// (rewindAhead).
#include "ui/play/sim_worker.h"

#include <algorithm>

namespace jl::ui {

int SimWorker::framesAhead() const {
    int n = 0;
    for (const AheadGroup& g : ahead_) n += int(g.frames.size());
    return n;
}

// The steps that pass the next frame's time, kept back with the state
// after them. False when nothing more can be made ahead now (a command
// came in, or the engine failed: the run meets the failure again, and
// shows it, when the clock gets there).
bool SimWorker::makeAhead() {
    if (!aheadFrom_) {
        aheadFrom_ = sim_->snapshot();
        aheadCarried_ = carried_;
        aheadMidFrame_ = midFrame_;
    }
    AheadGroup g;
    g.carried = ahead_.empty() ? carried_ : ahead_.back().carried;
    const int first = history_.count() + framesAhead();
    const bool ok = framesThrough(
        *sim_, first, g.carried,
        [&](int k, FramePtr f) {
            if (k != first + int(g.frames.size())) return;  // the grid gives each frame once, in order
            g.keys.push_back(history_.isKeyframeIndex(k) ? sim_->snapshot() : nullptr);
            g.frames.push_back(std::move(f));
        },
        true);
    if (!ok || g.frames.empty()) {
        aheadStopped_ = true;  // until the head is put back
        return false;
    }
    g.after = sim_->snapshot();
    g.hash = sim_->stateHash();
    ahead_.push_back(std::move(g));
    return true;
}

// The first frames kept back, recorded as simulateNextFrame records the
// frames it makes.
void SimWorker::releaseAhead() {
    AheadGroup g = std::move(ahead_.front());
    ahead_.pop_front();
    const int first = history_.count();
    for (size_t i = 0; i < g.frames.size(); ++i) {
        const FramePtr& f = g.frames[i];
        if (!f->events.empty()) {
            events_->insert(events_->end(), f->events.begin(), f->events.end());
            eventsChanged_ = true;
        }
        history_.append(f, g.keys[i], first + int(i));
        feed(f);
    }
    carried_ = g.carried;
    headHash_ = g.hash;
    midFrame_ = false;
    cursor_ = first;
    shown_ = g.frames.front();
    dirty_ = true;
    // The head simulation is past the history's head by the frames still kept back.
    aheadFrom_ = g.after;
    aheadCarried_ = std::move(g.carried);
    aheadMidFrame_ = false;
    if (ahead_.empty() && !aheadStopped_) aheadFrom_.reset();
}

// The head simulation back at the history's head, the frames kept back dropped.
void SimWorker::rewindAhead() {
    ahead_.clear();
    aheadStopped_ = false;
    if (!aheadFrom_ || !sim_) return;
    sim_->restore(*aheadFrom_);
    sim_->setFrameGrid(frameGrid());
    (void)sim_->takeGridFrames();
    carried_ = std::move(aheadCarried_);
    midFrame_ = aheadMidFrame_;
    aheadFrom_.reset();
}

// Each group kept back holds a copy of the world: at most kAheadBlockFrames
// blocks' worth of them (120 frames of 1,000 blocks, 15 of 10,000, 1 of 150,000).
bool SimWorker::canWorkAhead() const {
    if (!playing_ || !sim_ || !failure_.empty() || aheadStopped_ || sim_->dragging()) return false;
    const std::size_t blocks = std::max<std::size_t>(1, shown_ ? shown_->poses.size() : 1);
    return std::size_t(framesAhead()) < std::min<std::size_t>(kAheadFrames, kAheadBlockFrames / blocks);
}

void SimWorker::workAhead(Clock::time_point start) {
    while (canWorkAhead() && Clock::now() - start < kWorkSlice && !commandWaiting() && !abort_)
        if (!makeAhead()) return;
}

}  // namespace jl::ui
