// The simulation thread's loop: drains the UI's commands between steps,
// paces the run to real time, records frames and publishes the newest status.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame_history.h"
#include "jl/sim/simulation.h"
#include "ui/play/kept_runs.h"
#include "ui/play/rate_window.h"
#include "ui/play/sim_status.h"

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <variant>

namespace jl::ui {

namespace cmd {
struct Load {
    jl::Scene scene;
};
struct Play {};
struct Pause {};
struct StepForward {};
struct StepBack {};
struct Restart {};
struct Seek {
    double time;
};
// The state at exactly `time` (an event's instant), which lies between two
// frames: shown, paused, without being recorded; the cursor is the frame before it.
struct ShowInstant {
    double time;
};
struct Speed {
    double factor;
};
struct Budget {
    std::size_t bytes;
};
// The scene's length changed: where playing stops, nothing to simulate again.
struct Duration {
    double seconds;
};
// A push at `point`: on `block` (-1: the block there, picked in the worker's
// state) at `local` in its frame, in the frame of time `shownTime` that the
// window showed at the press (negative: the frame the worker is at).
struct DragBegin {
    jl::Vec2 point;
    int block = -1;
    jl::Vec2 local = jl::Vec2::Zero();
    double shownTime = -1;
};
struct DragMove {
    jl::Vec2 target;
};
struct DragEnd {};
// The scene's drags changed alone (Undo or Redo of a push): the run of
// `scene` shown at `time`, brought back whole when it was kept, else run
// again up to there. The run on record is kept in its turn.
struct Recall {
    jl::Scene scene;
    double time;
};
struct Quit {};
}  // namespace cmd

using SimCommand = std::variant<cmd::Load, cmd::Play, cmd::Pause, cmd::StepForward, cmd::StepBack, cmd::Restart,
                                cmd::Seek, cmd::ShowInstant, cmd::Speed, cmd::Budget, cmd::Duration, cmd::DragBegin,
                                cmd::DragMove, cmd::DragEnd, cmd::Recall, cmd::Quit>;

class SimWorker {
public:
    explicit SimWorker(std::size_t budgetBytes) : budget_(budgetBytes) {}
    // Called from the UI thread; never blocks on the simulation.
    void post(SimCommand c);
    // Asks a long advance to stop between two steps (the program is closing).
    void abort() { abort_ = true; }
    // The thread's last act, and a wait for it with a deadline. Through a
    // std::mutex, so ThreadSanitizer sees that the worker's writes happen
    // before its destruction (QThread::wait synchronises inside Qt, which
    // Debian's Qt does not instrument).
    void markFinished();
    bool waitFinished(std::chrono::milliseconds limit);
    std::shared_ptr<const SimStatus> status() const;
    // The window has taken the new frames numbered below `count`
    // (SimStatus::firstNewFrame): the next publication leaves them out.
    void taken(std::uint64_t count) { taken_.store(count, std::memory_order_relaxed); }
    // The thread body; returns after a Quit command.
    void run();

private:
    using Clock = std::chrono::steady_clock;
    // Work on the engine in slices this long, then drain commands again.
    static constexpr auto kWorkSlice = std::chrono::milliseconds(12);
    // The engine on a scene, its frames without ribbons: the views make
    // those of the frame they draw, when they draw them (a 10,000-block
    // ladder's ribbons were a fifth of this thread's time).
    static jl::Simulation::Built build(const jl::Scene& scene);
    // A scene's build errors as the failure shown.
    static std::string joinLines(const std::vector<std::string>& lines);
    void apply(const SimCommand& c);
    void apply(const cmd::Load& c);
    void startRun(const jl::Scene& scene);
    void apply(const cmd::Recall& c);
    void apply(const cmd::Seek& c);
    void apply(const cmd::ShowInstant& c);
    void apply(const cmd::DragBegin& c);
    void play();
    void advancePaced();
    using FramePtr = std::shared_ptr<const jl::Frame>;
    bool framesThrough(jl::Simulation& sim, int index, std::vector<jl::Event>& carried,
                       const std::function<void(int, FramePtr)>& take, bool interruptible = false);
    bool commandWaiting() const;
    int restoreKeyframeFor(jl::Simulation& sim, int index);
    jl::FrameGrid frameGrid() const { return {0.0, history_.interval()}; }
    bool simulateNextFrame();
    // Frames made ahead of the clock and kept back (sim_worker_ahead.cpp).
    static constexpr std::size_t kAheadFrames = 120;  // 2 s at 60 frames a second
    static constexpr std::size_t kAheadBlockFrames = 150000;
    struct AheadGroup {
        std::vector<FramePtr> frames;                           // in order, their events attached
        std::vector<std::shared_ptr<const jl::Snapshot>> keys;  // each one's keyframe, or null
        std::shared_ptr<const jl::Snapshot> after;              // the head simulation after them
        std::vector<jl::Event> carried;                         // events after the last of them
        std::uint64_t hash = 0;
    };
    int framesAhead() const;
    bool makeAhead();
    void releaseAhead();
    void rewindAhead();
    bool canWorkAhead() const;
    void workAhead(Clock::time_point start);
    bool simulateTo(int index);
    void showFrame(int index);
    std::shared_ptr<const jl::Frame> regenerate(int index);
    std::shared_ptr<const jl::Frame> instantFrame(double time, int before);
    bool showingInstant() const;
    void discardFuture();
    void keepRunBeforePush();
    void swapRun(KeptRun& other);
    void feedWholeRun();
    void fail(const std::string& why);
    void rebasePace();
    void measure();
    void publish();
    double nextFrameWaitSeconds() const;

    // Shared with the UI thread.
    mutable std::mutex queueMutex_;
    std::condition_variable wake_;
    std::deque<SimCommand> queue_;
    mutable std::mutex statusMutex_;
    std::shared_ptr<const SimStatus> status_ = std::make_shared<SimStatus>();
    std::atomic<bool> abort_{false};
    std::atomic<std::uint64_t> taken_{0};
    std::mutex finishMutex_;
    std::condition_variable finished_;
    bool done_ = false;

    // The worker's own; touched only on its thread.
    std::size_t budget_;
    // At the head of the history: at the end of the step that gave the last
    // frame, or some steps past it when a command came in between two steps
    // of the next frame (midFrame_; a frame of a 100,000-block ladder takes
    // seconds, and a pause must not wait for it).
    std::unique_ptr<jl::Simulation> sim_;
    bool midFrame_ = false;
    int framesWanted_ = 0;  // Step forward pressed at the head, frames not yet made
    FrameHistory history_;
    // Runs a push in the past replaced, and the runs Undo put aside.
    KeptRuns kept_;
    int cursor_ = 0;
    bool playing_ = false;
    double seekingTo_ = -1;    // s, while simulateTo (or instantFrame) is on its way there
    double seekProgress_ = 0;  // 0 .. 1 of that way
    // Playing stops once at the scene's duration; Play from there goes on past it.
    double duration_ = 0;  // s, 0: none
    bool stoppedAtEnd_ = false;
    bool quit_ = false;
    bool dirty_ = true;
    double speed_ = 1.0;
    std::string failure_;
    std::shared_ptr<const jl::Frame> shown_;
    // Events the head simulation has recorded after the last frame it gave:
    // they go with the next frame (its time is not earlier than theirs).
    std::vector<jl::Event> carried_;
    // Kept back, oldest first; the head simulation at the history's head
    // (and its carried events) while it is past it; no more made ahead
    // until it is put back.
    std::deque<AheadGroup> ahead_;
    std::shared_ptr<const jl::Snapshot> aheadFrom_;
    std::vector<jl::Event> aheadCarried_;
    bool aheadMidFrame_ = false;
    bool aheadStopped_ = false;
    // Frames appended to the history and not yet taken by the window; the
    // first is number feedFirst_ (SimStatus::newFrames).
    void feed(std::shared_ptr<const jl::Frame> f);
    std::deque<std::shared_ptr<const jl::Frame>> feed_;
    std::uint64_t feedFirst_ = 0;
    std::shared_ptr<const std::vector<std::shared_ptr<const jl::Frame>>> publishedFeed_;
    bool feedChanged_ = true;
    std::shared_ptr<std::vector<jl::Event>> events_ = std::make_shared<std::vector<jl::Event>>();
    std::shared_ptr<const std::vector<jl::Event>> publishedEvents_;
    std::shared_ptr<const jl::Scene> recorded_;
    bool eventsChanged_ = true;
    std::uint64_t headHash_ = 0;
    std::uint64_t serial_ = 0, loadSerial_ = 0;
    // Pacing: simulated time paceSim_ was on screen at wall time paceWall_.
    double paceSim_ = 0;
    Clock::time_point paceWall_;
    double behind_ = 0;  // s the frame on screen trailed the clock at the last advance (SimStatus::behind)
    // Rates over the last seconds of playing, from the frame on screen;
    // replaying recorded frames is a stretch apart from simulating them.
    RateWindow rate_;
    bool rateReplaying_ = false;
    Clock::time_point started_ = Clock::now(), rateShown_;
    double realTimeFactor_ = -1, stepsPerSecond_ = -1, rateSpan_ = 0;
};

}  // namespace jl::ui
