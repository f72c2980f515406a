#include "ui/sim_worker.h"

#include <algorithm>
#include <cmath>
#include <exception>

#ifdef __linux__
#include <sys/resource.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

namespace jl::ui {

namespace {
constexpr auto kWorkSlice = std::chrono::milliseconds(12);  // then drain commands again
constexpr double kMaxLag = 0.1;  // s of simulated time behind the clock before giving up catching up

double secondsBetween(std::chrono::steady_clock::time_point a, std::chrono::steady_clock::time_point b) {
    return std::chrono::duration<double>(b - a).count();
}

std::string joinLines(const std::vector<std::string>& lines) {
    std::string s;
    for (const auto& l : lines) s += (s.empty() ? "" : "\n") + l;
    return s.empty() ? std::string("the scene could not be built") : s;
}
}  // namespace

void SimWorker::post(SimCommand c) {
    {
        std::lock_guard lock(queueMutex_);
        queue_.push_back(std::move(c));
    }
    wake_.notify_one();
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
    rateWall_ = paceWall_ = Clock::now();
    while (!quit_ && !abort_) {
        std::deque<SimCommand> batch;
        {
            std::unique_lock lock(queueMutex_);
            if (queue_.empty()) {
                const double wait = playing_ ? nextFrameWaitSeconds() : 0.1;
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
            if (playing_) advancePaced();
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
            if constexpr (std::is_same_v<T, cmd::Load> || std::is_same_v<T, cmd::Seek> ||
                          std::is_same_v<T, cmd::DragBegin>) {
                apply(v);
            } else if constexpr (std::is_same_v<T, cmd::Play>) {
                play();
            } else if constexpr (std::is_same_v<T, cmd::Pause>) {
                playing_ = false;
            } else if constexpr (std::is_same_v<T, cmd::StepForward>) {
                playing_ = false;
                if (cursor_ < history_.head()) showFrame(cursor_ + 1);
                else simulateNextFrame();
            } else if constexpr (std::is_same_v<T, cmd::StepBack>) {
                playing_ = false;
                if (cursor_ > 0) showFrame(cursor_ - 1);
            } else if constexpr (std::is_same_v<T, cmd::Restart>) {
                if (history_.count() > 0) showFrame(0);
                rebasePace();
            } else if constexpr (std::is_same_v<T, cmd::Speed>) {
                speed_ = std::clamp(v.factor, 0.01, 4.0);
                rebasePace();
            } else if constexpr (std::is_same_v<T, cmd::Budget>) {
                budget_ = v.bytes;
                history_.setBudget(v.bytes);
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
    failure_.clear();
    events_ = std::make_shared<std::vector<jl::Event>>();
    eventsChanged_ = true;
    ++loadSerial_;
    feedFirst_ += feed_.size();  // the old run's frames: no longer anyone's
    feed_.clear();
    feedChanged_ = true;
    history_.reset(c.scene.solver.frameInterval, budget_);
    cursor_ = 0;
    shown_.reset();
    recorded_ = std::make_shared<const jl::Scene>(c.scene);
    duration_ = c.scene.duration;
    stoppedAtEnd_ = false;
    auto built = jl::Simulation::build(c.scene);
    sim_ = std::move(built.simulation);
    if (!sim_) {
        fail(joinLines(built.errors));
        return;
    }
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
    if (index > history_.head()) simulateTo(index);
    else showFrame(index);
    rebasePace();
}

void SimWorker::apply(const cmd::DragBegin& c) {
    if (!sim_ || !failure_.empty()) return;
    const auto hit = sim_->pick(c.point);
    if (!hit) return;
    // Pushing a block in the past rewrites what follows: simulate on from here.
    if (cursor_ < history_.head()) discardFuture();
    sim_->beginDrag(hit->first, hit->second, c.point);
    if (!playing_) shown_ = std::make_shared<const jl::Frame>(sim_->frame());
}

void SimWorker::play() {
    if (!sim_ || !failure_.empty()) return;
    if (cursor_ * history_.interval() < duration_ - 1e-9) stoppedAtEnd_ = false;  // it will stop there again
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
        if (cursor_ < history_.head()) showFrame(cursor_ + 1);
        else if (!simulateNextFrame()) return;
        if (Clock::now() - start > kWorkSlice) break;
    }
    // The engine is slower than the clock: carry on from here rather than
    // racing to catch up (the real-time factor tells the user).
    if (desired - cursor_ * dt > kMaxLag) rebasePace();
}

// Simulation::advanceTo, one step at a time so that closing the program
// never waits for a long stretch of simulation (the steps are the same).
bool SimWorker::advance(jl::Simulation& sim, double t) {
    while (sim.time() < t && sim.failure().empty()) {
        if (abort_) return false;
        if (!sim.stepOnce()) break;
    }
    return sim.failure().empty();
}

bool SimWorker::simulateNextFrame() {
    if (!sim_ || !failure_.empty()) {
        playing_ = false;
        return false;
    }
    const int next = history_.count();
    const bool ok = advance(*sim_, next * history_.interval());
    if (abort_) return false;
    if (!ok) {
        fail(sim_->failure().empty() ? std::string("the solver stopped") : sim_->failure());
        showFrame(history_.head());  // the last good frame
        return false;
    }
    auto f = std::make_shared<const jl::Frame>(sim_->frame());
    if (!f->events.empty()) {
        events_->insert(events_->end(), f->events.begin(), f->events.end());
        eventsChanged_ = true;
    }
    history_.append(f, history_.isKeyframeIndex(next) ? sim_->snapshot() : nullptr, next);
    feed(f);
    headHash_ = sim_->stateHash();
    cursor_ = next;
    shown_ = std::move(f);
    dirty_ = true;
    return true;
}

// A seek far ahead can take long: show the way there, and let any new
// command (a pause, another seek) end it where it got to.
bool SimWorker::simulateTo(int index) {
    auto lastShown = Clock::now();
    while (history_.head() < index) {
        if (!simulateNextFrame()) return false;
        if (Clock::now() - lastShown > kWorkSlice * 4) {
            publish();
            lastShown = Clock::now();
            std::lock_guard lock(queueMutex_);
            if (!queue_.empty()) return false;
        }
    }
    return true;
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
    const auto [k, key] = history_.keyframeAtOrBefore(index);
    if (!key) return nullptr;
    auto built = jl::Simulation::build(sim_->scene());
    if (!built.simulation) return nullptr;
    jl::Simulation& s = *built.simulation;
    s.restore(*key);
    std::shared_ptr<const jl::Frame> result;
    if (k == index) result = std::make_shared<const jl::Frame>(s.frame());
    for (int i = k + 1; i <= index; ++i) {
        if (!advance(s, i * history_.interval())) return nullptr;
        auto f = std::make_shared<const jl::Frame>(s.frame());
        history_.restoreFrame(i, f, index);
        if (i == index) result = std::move(f);
    }
    return result;
}

// The head moves back to the cursor: frames, events and recorded drags after
// it are dropped and the simulation is put in the cursor's state.
void SimWorker::discardFuture() {
    const double tc = shown_ ? shown_->time : cursor_ * history_.interval();
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
        auto built = jl::Simulation::build(scene);
        if (!built.simulation) return fail(joinLines(built.errors));
        sim_ = std::move(built.simulation);
    } else {
        const auto [k, key] = history_.keyframeAtOrBefore(cursor_);
        if (key) sim_->restore(*key);
    }
    if (cursor_ > 0 && !advance(*sim_, cursor_ * history_.interval())) return fail(sim_->failure());
    (void)sim_->frame();  // its events are already in the log
    history_.truncateAfter(cursor_);
    while (!feed_.empty() && feed_.back()->time > tc) {
        feed_.pop_back();
        feedChanged_ = true;
    }
    std::erase_if(*events_, [tc](const jl::Event& e) { return e.time > tc; });
    eventsChanged_ = true;
    headHash_ = sim_->stateHash();
    recorded_ = std::make_shared<const jl::Scene>(sim_->scene());
}

void SimWorker::fail(const std::string& why) {
    failure_ = why.empty() ? std::string("the run stopped") : why;
    playing_ = false;
    dirty_ = true;
}

void SimWorker::measure() {
    const auto now = Clock::now();
    const double dt = secondsBetween(rateWall_, now);
    if (dt < 0.5) return;
    const double simNow = cursor_ * history_.interval();
    const auto head = history_.frame(history_.head());
    const long long steps = head ? head->solver.steps : 0;
    const double rtf = playing_ ? std::max(0.0, simNow - rateSim_) / dt : 0;
    const double sps = playing_ ? double(std::max(0LL, steps - rateSteps_)) / dt : 0;
    if (rtf != realTimeFactor_ || sps != stepsPerSecond_) dirty_ = true;
    realTimeFactor_ = rtf;
    stepsPerSecond_ = sps;
    rateWall_ = now;
    rateSim_ = simNow;
    rateSteps_ = steps;
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
        publishedFeed_ = std::make_shared<const std::vector<std::shared_ptr<const jl::Frame>>>(feed_.begin(), feed_.end());
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
    s->dragging = sim_ && sim_->dragging();
    s->speed = speed_;
    s->realTimeFactor = realTimeFactor_;
    s->stepsPerSecond = stepsPerSecond_;
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
