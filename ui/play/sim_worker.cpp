#include "ui/play/sim_worker.h"

#include "ui/play/catch_up.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <optional>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace jl::ui {

namespace {
// How often the rates shown are read again: readable, and close to the
// moment they are read at.
constexpr auto kRateShownEvery = std::chrono::milliseconds(100);

double secondsBetween(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}
}  // namespace

std::string SimWorker::joinLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += (s.empty() ? "" : "\n") + l;
    return s.empty() ? std::string("the scene could not be built") : s;
}

jl::Simulation::Built SimWorker::build(const jl::Scene& scene) {
    auto built = jl::Simulation::build(scene);
    if (built.simulation) built.simulation->setRibbonsInFrames(false);
    return built;
}

void SimWorker::post(SimCommand c) {
    {
        std::lock_guard lock(queueMutex_);
        queue_.push_back(std::move(c));
    }
    wake_.notify_one();
}

bool SimWorker::commandWaiting() const {
    std::lock_guard lock(queueMutex_);
    return !queue_.empty();
}

std::shared_ptr<const SimStatus> SimWorker::status() const {
    std::lock_guard lock(statusMutex_);
    return status_;
}

// A simulation running flat out (seeking, or playing faster than it can)
// must not take the processor from the UI thread; one that keeps pace must
// not be starved by it either (the UI redraws as often as it can: at a
// lower priority, a 200-block ladder played at 0.8x real time on two
// cores). On Linux the niceness is per thread.
static void setNiceness(int nice) {
    thread_local int current = 0;
    if (nice == current) return;
    current = nice;
#ifdef __linux__
    setpriority(PRIO_PROCESS, id_t(syscall(SYS_gettid)), nice);
#endif
}

void SimWorker::run() {
    setNiceness(8);
    paceWall_ = Clock::now();
    while (!quit_ && !abort_) {
        std::deque<SimCommand> batch;
        {
            std::unique_lock lock(queueMutex_);
            if (queue_.empty()) {
                const double wait = playing_            ? (canWorkAhead() ? 0.0 : nextFrameWaitSeconds())
                                    : framesWanted_ > 0 ? 0.0
                                                        : 0.1;
                if (wait > 0)
                    wake_.wait_for(lock, std::chrono::duration<double>(wait), [this] { return !queue_.empty(); });
            }
            batch.swap(queue_);
        }
        // Nothing thrown by the engine may leave this thread: it becomes a
        // failure in words, shown with the last good frame.
        try {
            for (const auto& c : batch) {
                apply(c);
                if (quit_) return;
            }
            if (playing_)
                advancePaced();
            else if (framesWanted_ > 0 && simulateNextFrame())
                --framesWanted_;
            if (!failure_.empty()) framesWanted_ = 0;
        } catch (const std::exception& e) {
            fail(std::string("internal error: ") + e.what());
        } catch (...) {
            fail("internal error");
        }
        measure();
        if (dirty_) publish();
    }
}

void SimWorker::apply(const SimCommand& c) {
    std::visit(
        [this](const auto& v) {
            using T = std::decay_t<decltype(v)>;
            // Frames asked for one by one: a new way to go cancels those not yet made.
            if constexpr (!std::is_same_v<T, cmd::StepForward> && !std::is_same_v<T, cmd::Speed> &&
                          !std::is_same_v<T, cmd::Budget> && !std::is_same_v<T, cmd::Duration> &&
                          !std::is_same_v<T, cmd::DragMove> && !std::is_same_v<T, cmd::DragEnd> &&
                          !std::is_same_v<T, cmd::DragBegin>)
                framesWanted_ = 0;
            // The frame on screen jumps (or playing starts): a new stretch to measure.
            if constexpr (!std::is_same_v<T, cmd::Speed> && !std::is_same_v<T, cmd::Budget> &&
                          !std::is_same_v<T, cmd::Duration> && !std::is_same_v<T, cmd::DragMove> &&
                          !std::is_same_v<T, cmd::DragEnd>)
                rate_.restart();
            // The head simulation is the one on record again before a command can reach it.
            if constexpr (!std::is_same_v<T, cmd::Speed> && !std::is_same_v<T, cmd::Budget> &&
                          !std::is_same_v<T, cmd::Duration> && !std::is_same_v<T, cmd::Pause> &&
                          !std::is_same_v<T, cmd::Play> && !std::is_same_v<T, cmd::DragMove> &&
                          !std::is_same_v<T, cmd::DragEnd> && !std::is_same_v<T, cmd::Seek> &&
                          !std::is_same_v<T, cmd::StepForward> && !std::is_same_v<T, cmd::StepBack> &&
                          !std::is_same_v<T, cmd::Restart>)
                rewindAhead();
            if constexpr (std::is_same_v<T, cmd::Load> || std::is_same_v<T, cmd::Seek> ||
                          std::is_same_v<T, cmd::ShowInstant> || std::is_same_v<T, cmd::DragBegin> ||
                          std::is_same_v<T, cmd::Recall>) {
                apply(v);
            } else if constexpr (std::is_same_v<T, cmd::Play>) {
                play();
            } else if constexpr (std::is_same_v<T, cmd::Pause>) {
                playing_ = false;
            } else if constexpr (std::is_same_v<T, cmd::StepForward>) {
                playing_ = false;
                // One frame on: shown at once when recorded, else simulated
                // between commands (see run()).
                if (cursor_ < history_.head())
                    showFrame(cursor_ + 1);
                else if (sim_ && failure_.empty())
                    ++framesWanted_;
            } else if constexpr (std::is_same_v<T, cmd::StepBack>) {
                playing_ = false;
                // From an instant between two frames, back is the frame before it.
                if (showingInstant())
                    showFrame(cursor_);
                else if (cursor_ > 0)
                    showFrame(cursor_ - 1);
            } else if constexpr (std::is_same_v<T, cmd::Restart>) {
                if (history_.count() > 0) showFrame(0);
                rebasePace();
            } else if constexpr (std::is_same_v<T, cmd::Speed>) {
                speed_ = std::clamp(v.factor, 0.01, 4.0);
                rebasePace();
            } else if constexpr (std::is_same_v<T, cmd::Duration>) {
                duration_ = v.seconds;
                if (cursor_ * history_.interval() < duration_ - 1e-9) stoppedAtEnd_ = false;
            } else if constexpr (std::is_same_v<T, cmd::Budget>) {
                budget_ = v.bytes;
                history_.setBudget(v.bytes);
                kept_.trim(v.bytes);
            } else if constexpr (std::is_same_v<T, cmd::DragMove>) {
                if (!sim_ || !sim_->dragging()) return;
                sim_->moveDrag(v.target);
                // Paused, the spring does nothing yet, but the line should follow the hand.
                if (!playing_) shown_ = std::make_shared<const jl::Frame>(sim_->frame());
            } else if constexpr (std::is_same_v<T, cmd::DragEnd>) {
                if (!sim_ || !sim_->dragging()) return;
                sim_->endDrag();
                recorded_ = std::make_shared<const jl::Scene>(sim_->scene());
                if (!playing_) shown_ = std::make_shared<const jl::Frame>(sim_->frame());
            } else if constexpr (std::is_same_v<T, cmd::Quit>) {
                quit_ = true;
            }
            dirty_ = true;
        },
        c);
}

void SimWorker::apply(const cmd::Load& c) {
    kept_.clear();  // runs of another scene
    startRun(c.scene);
}

void SimWorker::startRun(const jl::Scene& scene) {
    failure_.clear();
    events_ = std::make_shared<std::vector<jl::Event>>();
    eventsChanged_ = true;
    ++loadSerial_;
    feedFirst_ += feed_.size();  // the old run's frames: no longer anyone's
    feed_.clear();
    feedChanged_ = true;
    history_.reset(scene.solver.frameInterval, budget_);
    cursor_ = 0;
    midFrame_ = false;
    shown_.reset();
    recorded_ = std::make_shared<const jl::Scene>(scene);
    duration_ = scene.duration;
    stoppedAtEnd_ = false;
    auto built = build(scene);
    sim_ = std::move(built.simulation);
    if (!sim_) {
        fail(joinLines(built.errors));
        return;
    }
    // Frame i is the state at exactly i * interval, read off the step that
    // passes that time (the frame times never shape the steps).
    sim_->setFrameGrid(frameGrid());
    carried_.clear();
    auto first = std::make_shared<const jl::Frame>(sim_->frame());
    for (const auto& e : first->events) events_->push_back(e);
    history_.append(first, sim_->snapshot(), 0);
    feed(first);
    shown_ = first;
    headHash_ = sim_->stateHash();
    rebasePace();
}

void SimWorker::apply(const cmd::Seek& c) {
    setNiceness(8);  // a seek simulates flat out
    if (!sim_ || history_.count() == 0) return;
    const int index = std::max(0, int(std::floor(c.time / history_.interval() + 1e-6)));
    // A step can give more than one frame: the head may pass the one asked for.
    if (index <= history_.head() || simulateTo(index)) showFrame(index);
    rebasePace();
}

void SimWorker::apply(const cmd::ShowInstant& c) {
    setNiceness(8);
    if (!sim_ || history_.count() == 0) return;
    const jl::FrameGrid grid = frameGrid();
    // An instant is a still: playing on would replace it by the next frame at once.
    playing_ = false;
    if (c.time <= 0 || grid.on(c.time)) return apply(cmd::Seek{c.time});
    const int before = int(std::floor(c.time / grid.every));
    // The run must have passed the instant: its drags are recorded up to the
    // head, and the keyframe to start from must be there.
    if (before >= history_.head() && !simulateTo(before + 1)) return;
    showFrame(before);
    // Up to half a second of a long ladder to run again: the status says
    // where it is going meanwhile.
    seekingTo_ = c.time;
    seekProgress_ = 0;
    if (auto f = instantFrame(c.time, before)) shown_ = std::move(f);
    seekingTo_ = -1;
    dirty_ = true;
    rebasePace();
}

// The state at `time`, between frames `before` and `before + 1`, simulated
// on a scratch copy from the keyframe before it (as an evicted frame is):
// the steps do not depend on where frames are read, so this is the run's
// own state at that instant, bit for bit. An event's instant ends a step,
// so the state there is the settled one, after the event; the frame carries
// the events of that instant.
std::shared_ptr<const jl::Frame> SimWorker::instantFrame(double time, int before) {
    auto built = build(sim_->scene());
    if (!built.simulation) return nullptr;
    jl::Simulation& s = *built.simulation;
    if (restoreKeyframeFor(s, before) < 0) return nullptr;
    // A grid through the instant: the state there is read off the step
    // that passes it, or is the step's end.
    const jl::FrameGrid at{time, history_.interval()};
    s.setFrameGrid(at);
    std::vector<jl::Event> events;
    std::optional<jl::Frame> found;
    // Another command (a pause, a click elsewhere) ends it, the frame before
    // the instant staying on show.
    const double start = s.time();
    auto lastShown = Clock::now();
    for (int steps = 0; !found && !abort_; ++steps) {
        if (steps > 0 && commandWaiting()) return nullptr;
        if (!s.stepOnce()) return nullptr;
        if (Clock::now() - lastShown > kWorkSlice * 4) {
            seekProgress_ = std::clamp((s.time() - start) / (time - start), 0.0, 1.0);
            publish();
            lastShown = Clock::now();
        }
        for (const jl::Event& e : s.takeEvents()) events.push_back(e);
        for (jl::Frame& f : s.takeGridFrames())
            if (at.nearest(f.time) == 0) found = std::move(f);
        if (!found && at.on(s.time()) && at.nearest(s.time()) == 0) found = s.frame();
        if (!found && s.time() > time) return nullptr;
    }
    if (!found) return nullptr;
    found->time = time;
    found->events.clear();
    for (const jl::Event& e : events)
        if (std::abs(e.time - time) <= 1e-9 * at.every) found->events.push_back(e);
    return std::make_shared<const jl::Frame>(std::move(*found));
}

bool SimWorker::showingInstant() const {
    return shown_ && history_.count() > 0 &&
           std::abs(shown_->time - cursor_ * history_.interval()) > 1e-9 * history_.interval();
}

void SimWorker::apply(const cmd::DragBegin& c) {
    if (!sim_ || !failure_.empty()) return;
    // The push happens in the frame the window showed at the press: playing,
    // the worker may already be a frame or two further on (and a block that
    // swings fast is then somewhere else).
    // (An event's instant on screen lies between two frames: the push
    // starts from the frame before it, since history holds only frames.)
    if (c.shownTime >= 0 && history_.count() > 0) {
        const int shown = int(std::floor(c.shownTime / history_.interval() + 1e-6));
        if (shown != cursor_ && shown >= 0 && shown <= history_.head()) showFrame(shown);
    }
    // Pushing a block in the past rewrites what follows: simulate on from
    // the frame on screen (the view found a block there, in that frame).
    // So does pushing it while the next frame was half done. The run it
    // replaces is kept, for Undo to bring back.
    if (cursor_ < history_.head() || midFrame_) {
        if (cursor_ < history_.head()) keepRunBeforePush();
        discardFuture();
        if (!failure_.empty()) return;
    }
    const auto hit = c.block >= 0 ? std::make_optional(std::make_pair(c.block, c.local)) : sim_->pick(c.point);
    if (!hit) return;
    sim_->beginDrag(hit->first, hit->second, c.point);
    if (!playing_) shown_ = std::make_shared<const jl::Frame>(sim_->frame());
}

void SimWorker::play() {
    if (!sim_ || !failure_.empty()) return;
    // Before the scene's end, playing stops there again; at or past it (the
    // lesson ended, or an edit re-ran the scene up to its end) Play goes on.
    stoppedAtEnd_ = !(cursor_ * history_.interval() < duration_ - 1e-9);
    playing_ = true;
    rebasePace();
}

void SimWorker::rebasePace() {
    paceSim_ = cursor_ * history_.interval();
    paceWall_ = Clock::now();
}

double SimWorker::nextFrameWaitSeconds() const {
    const double due = (cursor_ + 1) * history_.interval();
    const double now = paceSim_ + secondsBetween(paceWall_, Clock::now()) * speed_;
    return std::clamp((due - now) / speed_, 0.0, 0.05);
}

void SimWorker::advancePaced() {
    // Keeping pace at real time or slower: the user is watching this.
    setNiceness(speed_ <= 1.0 ? 0 : 8);
    const auto start = Clock::now();
    const double desired = paceSim_ + secondsBetween(paceWall_, start) * speed_;
    const double dt = history_.interval();
    while ((cursor_ + 1) * dt <= desired + 1e-9) {
        // The scene's length: the lesson ends there (Play again goes on).
        if (!stoppedAtEnd_ && duration_ > 0 && cursor_ * dt >= duration_ - 1e-9) {
            stoppedAtEnd_ = true;
            playing_ = false;
            dirty_ = true;
            return;
        }
        if (cursor_ < history_.head())
            showFrame(cursor_ + 1);
        else if (!simulateNextFrame())
            return;
        if (Clock::now() - start > kWorkSlice) break;
    }
    // Behind the clock: the last kCatchUp s are made good, by frames due at
    // once (no wait); the rest is given up (the real-time factor tells the
    // user). Given up whole, a stall of a tenth of a second cost the run a
    // tenth for good: a 1,000-block ladder the engine runs at twice real
    // time played at 0.95x in the window.
    if ((cursor_ + 1) * dt > desired + 1e-9) workAhead(start);
    const double lag = desired - cursor_ * dt;
    paceSim_ -= lagGivenUp(lag);
    // Told the window, which then draws fewer frames (draw_pace.h).
    if (const double behind = std::clamp(lag, 0.0, kCatchUp); behind != behind_) {
        behind_ = behind;
        dirty_ = true;
    }
}

void SimWorker::fail(const std::string& why) {
    failure_ = why.empty() ? std::string("the run stopped") : why;
    playing_ = false;
    dirty_ = true;
}

// A sample of the time on screen at every turn of the loop; the rates the
// status bar shows are read off them a few times a second.
void SimWorker::measure() {
    const auto now = Clock::now();
    const bool replaying = cursor_ < history_.head();
    if (!playing_ || replaying != rateReplaying_) rate_.restart();
    rateReplaying_ = replaying;
    if (playing_) {
        const auto head = history_.frame(history_.head());
        rate_.add(secondsBetween(started_, now), cursor_ * history_.interval(),
                  head ? double(head->solver.steps) : 0.0);
    }
    if (now - rateShown_ < kRateShownEvery) return;
    rateShown_ = now;
    const double rtf = rate_.simulatedPerSecond().value_or(-1), sps = rate_.stepsPerSecond().value_or(-1);
    if (rtf != realTimeFactor_ || sps != stepsPerSecond_) dirty_ = true;
    realTimeFactor_ = rtf;
    stepsPerSecond_ = sps;
    rateSpan_ = rate_.span();
}

void SimWorker::feed(std::shared_ptr<const jl::Frame> f) {
    feed_.push_back(std::move(f));
    feedChanged_ = true;
}

void SimWorker::publish() {
    for (const std::uint64_t taken = taken_.load(std::memory_order_relaxed); feedFirst_ < taken && !feed_.empty();) {
        feed_.pop_front();
        ++feedFirst_;
        feedChanged_ = true;
    }
    if (feedChanged_) {
        publishedFeed_ =
            std::make_shared<const std::vector<std::shared_ptr<const jl::Frame>>>(feed_.begin(), feed_.end());
        feedChanged_ = false;
    }
    auto s = std::make_shared<SimStatus>();
    s->newFrames = publishedFeed_;
    s->firstNewFrame = feedFirst_;
    s->frame = shown_;
    if (eventsChanged_) {
        publishedEvents_ = std::make_shared<const std::vector<jl::Event>>(*events_);
        eventsChanged_ = false;
    }
    s->events = publishedEvents_;
    s->recorded = recorded_;
    s->frameIndex = cursor_;
    s->frameCount = history_.count();
    s->interval = history_.interval();
    const auto head = history_.frame(history_.head());
    s->headTime = head ? head->time : history_.head() * history_.interval();
    s->playing = playing_;
    s->seekingTo = seekingTo_;
    s->seekProgress = seekProgress_;
    s->dragging = sim_ && sim_->dragging();
    s->speed = speed_;
    s->realTimeFactor = realTimeFactor_;
    s->stepsPerSecond = stepsPerSecond_;
    s->rateSpan = rateSpan_;
    s->behind = playing_ ? behind_ : 0;
    s->headHash = headHash_;
    s->failure = failure_;
    s->serial = ++serial_;
    s->loadSerial = loadSerial_;
    std::lock_guard lock(statusMutex_);
    status_ = std::move(s);
    dirty_ = false;
}

void SimWorker::markFinished() {
    // Notify under the lock: once the waiter sees done_, it destroys us.
    const std::lock_guard lock(finishMutex_);
    done_ = true;
    finished_.notify_all();
}

bool SimWorker::waitFinished(std::chrono::milliseconds limit) {
    std::unique_lock lock(finishMutex_);
    return finished_.wait_for(lock, limit, [this] { return done_; });
}

}  // namespace jl::ui
