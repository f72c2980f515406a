// SimWorker: making frames. The engine steps until it has given a frame;
// frames already made are shown from the history (or made again from its
// nearest keyframe), and an edit or a push discards the future.
#include "ui/play/sim_worker.h"

#include <algorithm>
#include <cmath>

namespace jl::ui {

// Steps `sim` (its frame grid set to frameGrid()) until it has given frame
// `index`, one step at a time so that closing the program never waits for a
// long stretch of simulation. Every frame it gives on the way (a long step
// can pass more than one frame time) goes to `take` in order, at exactly its
// grid time, with the events since the frame before it. False on a failure
// (the simulation keeps its last good state) or when aborted; false too,
// with no failure, when `interruptible` and a command has come in (after one
// step at least, so that a stream of commands still lets the run advance).
bool SimWorker::framesThrough(jl::Simulation& sim, int index, std::vector<jl::Event>& carried,
                              const std::function<void(int, FramePtr)>& take, bool interruptible) {
    const jl::FrameGrid grid = sim.frameGrid();
    const auto hand = [&](jl::Frame f) {
        const double k = grid.nearest(f.time);
        f.time = grid.at(k);  // within rounding of it: the grid's time, exactly
        const auto after = std::find_if(carried.begin(), carried.end(),
                                        [&](const jl::Event& e) { return e.time > f.time + 1e-9 * grid.every; });
        f.events.assign(carried.begin(), after);
        carried.erase(carried.begin(), after);
        take(int(k), std::make_shared<const jl::Frame>(std::move(f)));
        return int(k);
    };
    for (int last = -1, steps = 0; last < index; ++steps) {
        if (abort_ || !sim.failure().empty()) return false;
        if (interruptible && steps > 0 && commandWaiting()) return false;
        if (!sim.stepOnce()) return false;
        // A step records its events at its ends (a located event ends it;
        // scripted actions start it): each frame inside the step takes those
        // not later than itself.
        std::vector<jl::Event> events = sim.takeEvents();
        carried.insert(carried.end(), events.begin(), events.end());
        for (jl::Frame& f : sim.takeGridFrames()) last = hand(std::move(f));
        if (grid.on(sim.time())) last = hand(sim.frame());
    }
    return true;
}

// Puts `sim` in the state of the last keyframe from which frame `index` can
// be simulated again, and returns that keyframe's index (-1: none). A
// keyframe holds the state at the end of the step that passed its frame's
// time, so it can lie a little after that time, and after `index`'s too.
int SimWorker::restoreKeyframeFor(jl::Simulation& sim, int index) {
    const double t = index * history_.interval();
    for (int k = history_.keyframeAtOrBefore(index).first; k >= 0; k -= history_.keyframeEvery()) {
        const auto [at, key] = history_.keyframeAtOrBefore(k);
        if (!key) return -1;
        sim.restore(*key);
        if (sim.time() <= t + 1e-9 * history_.interval()) {
            sim.setFrameGrid(frameGrid());
            (void)sim.takeGridFrames();
            return at;
        }
    }
    return -1;
}

bool SimWorker::simulateNextFrame() {
    if (!sim_ || !failure_.empty()) {
        playing_ = false;
        return false;
    }
    if (!ahead_.empty()) {
        releaseAhead();
        return true;
    }
    rewindAhead();
    const int next = history_.count();
    FramePtr first;
    midFrame_ = true;
    const bool ok = framesThrough(
        *sim_, next, carried_,
        [&](int k, FramePtr f) {
            if (k != history_.count()) return;  // the grid gives each frame once, in order
            if (!f->events.empty()) {
                events_->insert(events_->end(), f->events.begin(), f->events.end());
                eventsChanged_ = true;
            }
            history_.append(f, history_.isKeyframeIndex(k) ? sim_->snapshot() : nullptr, k);
            feed(f);
            if (k == next) first = f;
        },
        true);
    if (abort_) return false;
    // A command came in: the frame is finished later, from where it got to
    // (the steps do not depend on when they are taken).
    if (!ok && sim_->failure().empty()) return false;
    if (!ok || !first) {
        fail(sim_->failure().empty() ? std::string("the solver stopped") : sim_->failure());
        showFrame(history_.head());  // the last good frame
        return false;
    }
    midFrame_ = false;
    headHash_ = sim_->stateHash();
    cursor_ = next;
    shown_ = std::move(first);
    dirty_ = true;
    return true;
}

// A seek far ahead can take long: show the way there. Any new command (a
// pause, another seek) ends it where it got to: simulateNextFrame stops
// between two steps when one is waiting.
bool SimWorker::simulateTo(int index) {
    auto lastShown = Clock::now();
    seekingTo_ = index * history_.interval();
    seekProgress_ = std::clamp(double(history_.head()) / index, 0.0, 1.0);
    bool reached = true;
    while (reached && history_.head() < index) {
        reached = simulateNextFrame();
        seekProgress_ = std::clamp(double(history_.head()) / index, 0.0, 1.0);
        if (Clock::now() - lastShown > kWorkSlice * 4) {
            publish();
            lastShown = Clock::now();
        }
    }
    seekingTo_ = -1;
    dirty_ = true;
    return reached;
}

void SimWorker::showFrame(int index) {
    auto f = history_.frame(index);
    if (!f) f = regenerate(index);
    if (!f) return;
    cursor_ = index;
    shown_ = std::move(f);
    dirty_ = true;
}

// An evicted frame: re-simulate it on a scratch copy from the keyframe before
// it; the head simulation stays where it is.
std::shared_ptr<const jl::Frame> SimWorker::regenerate(int index) {
    auto built = build(sim_->scene());
    if (!built.simulation) return nullptr;
    jl::Simulation& s = *built.simulation;
    s.setFrameGrid(frameGrid());
    if (restoreKeyframeFor(s, index) < 0) return nullptr;
    FramePtr result;
    const jl::FrameGrid grid = frameGrid();
    if (grid.on(s.time()) && int(grid.nearest(s.time())) == index) {
        jl::Frame f = s.frame();
        f.time = grid.at(index);
        result = std::make_shared<const jl::Frame>(std::move(f));
        history_.restoreFrame(index, result, index);
        return result;
    }
    std::vector<jl::Event> ignored;  // already in the log
    if (!framesThrough(s, index, ignored, [&](int k, FramePtr f) {
            history_.restoreFrame(k, f, index);
            if (k == index) result = std::move(f);
        }))
        return nullptr;
    return result;
}

// The head moves back to the cursor: frames, events and recorded drags after
// it are dropped and the simulation is put in the cursor's state.
void SimWorker::discardFuture() {
    const double tc = cursor_ * history_.interval();
    jl::Scene scene = sim_->scene();
    bool dragsChanged = false;
    for (auto it = scene.drags.begin(); it != scene.drags.end();) {
        if (!it->samples.empty() && it->samples.front().t > tc) {
            it = scene.drags.erase(it);
            dragsChanged = true;
            continue;
        }
        if (it->end > tc) {
            std::erase_if(it->samples, [tc](const jl::DragRecord::Sample& s) { return s.t > tc; });
            it->end = tc;
            dragsChanged = true;
        }
        ++it;
    }
    if (dragsChanged) {
        // The simulation's own record of drags cannot be cut, so rebuild it
        // from the shortened scene and replay up to the cursor.
        auto built = build(scene);
        if (!built.simulation) return fail(joinLines(built.errors));
        sim_ = std::move(built.simulation);
        sim_->setFrameGrid(frameGrid());
    } else if (restoreKeyframeFor(*sim_, cursor_) < 0) {
        return fail("the recorded run could not be resumed at this frame");
    }
    history_.truncateAfter(cursor_);
    while (!feed_.empty() && feed_.back()->time > tc) {
        feed_.pop_back();
        feedChanged_ = true;
    }
    std::erase_if(*events_, [tc](const jl::Event& e) { return e.time > tc; });
    eventsChanged_ = true;
    // On to the end of the step that passes the frame on screen, not
    // shortened to land on it: a replay of the drag that follows must take
    // the very same steps (it lands on the drag's first instant, where the
    // step ended). The frames that step passes after the cursor's are this
    // run's frames too, and so are the events after the cursor's time.
    carried_.clear();
    std::vector<jl::Event> since;
    if (sim_->time() < tc && !framesThrough(*sim_, cursor_, since, [&](int k, FramePtr f) {
            if (k <= cursor_ || k != history_.count()) return;  // already on record
            events_->insert(events_->end(), f->events.begin(), f->events.end());
            history_.append(f, history_.isKeyframeIndex(k) ? sim_->snapshot() : nullptr, cursor_);
            feed(std::move(f));
        }))
        return fail(sim_->failure().empty() ? std::string("the run could not be resumed at this frame")
                                            : sim_->failure());
    std::erase_if(since, [tc](const jl::Event& e) { return e.time <= tc; });  // already in the log
    carried_ = std::move(since);
    midFrame_ = false;
    headHash_ = sim_->stateHash();
    recorded_ = std::make_shared<const jl::Scene>(sim_->scene());
}

}  // namespace jl::ui
