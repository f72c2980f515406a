// A running scene: advances a world step by step, applies the script and the
// user's drags at their times, handles the ladder's events, produces frames.
// Deterministic: the same scene and drags give bit-identical states whatever
// the caller's frame rate (steps are never cut to suit the caller).
#pragma once

#include "jl/engine/dynamics.h"
#include "jl/engine/kept_evaluation.h"
#include "jl/engine/step_interpolant.h"
#include "jl/engine/stepper.h"
#include "jl/engine/stiff_mode.h"
#include "jl/engine/world.h"
#include "jl/ladder/ladder.h"
#include "jl/ladder/pin_stops.h"
#include "jl/scene/scene.h"
#include "jl/sim/event_bracket.h"
#include "jl/sim/frame.h"

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace jl {

// The full state at one instant, enough to carry on bit-identically.
struct Snapshot;
// What a snapshot takes in memory: itself and what it holds on the heap.
// Most of it grows with the ladder's particles, 14 a block, not with what
// a frame shows: 12 MB for 10,000 blocks, five times a frame (2.6 MB).
std::size_t snapshotBytes(const Snapshot& s);
struct Energy;
struct MotionStep;

class Simulation {
public:
    struct Built {
        std::unique_ptr<Simulation> simulation;
        std::vector<std::string> errors;  // empty when built
    };
    // Builds the world of a scene (already validated by the loader).
    static Built build(const Scene& scene);

    double time() const { return t_; }
    const Scene& scene() const { return scene_; }  // the recorded drags included
    const World& world() const { return world_; }
    const Ladder* ladder() const { return ladder_ ? &*ladder_ : nullptr; }
    const PinStops* stops() const { return stops_ ? &*stops_ : nullptr; }  // a general scene's pin stops
    int blockCount() const { return int(blocks_.size()); }
    PartId blockPart(int block) const { return blocks_[size_t(block)]; }
    // This thread's CPU time spent so far on events (s): all of it, from the
    // step's end past an event to the events settled (located first when the
    // scene asks), and the part that located them inside their steps. The
    // share of a run that events take, read within the run itself (the
    // difference of two runs' times is lost in the machine's drift between
    // them). A profile, as MuJoCo's timers are: not part of the state; kept
    // only after setTimingEvents(true) (the benchmark's), since reading the
    // clock costs a few per cent of an event on a short ladder.
    void setTimingEvents(bool on) { timingEvents_ = on; }
    double eventSeconds() const { return eventSeconds_; }
    double locatingSeconds() const { return locatingSeconds_; }

    // The current state as a frame; events since the previous call move into it.
    Frame frame();
    // Whether frames carry the ribbons (two per hinge, to draw): a recording
    // that only writes numbers leaves them out (they were 7 % of a run).
    void setRibbonsInFrames(bool on) { ribbonsInFrames_ = on; }
    bool ribbonsInFrames() const { return ribbonsInFrames_; }
    // Just the events since the previous call (a frame costs O(N) trig: a
    // recorder that needs every event but not every frame takes these).
    std::vector<Event> takeEvents() { return std::exchange(pending_, {}); }
    double lastResidual() const { return lastResidual_; }  // m, after the last step
    double lastStep() const { return stats_.lastStep; }    // s, the last step taken
    // The fastest rate of the motion now, what makes it and where
    // (jl/engine/stiff_mode.h): what sets the step of an explicit method.
    StiffMode stiffestMode() const;

    // Steps until time() >= t (possibly a little past it: the last step is not
    // shortened). Returns false, keeping the last good state, on failure.
    bool advanceTo(double t);
    // Steps until time() == t exactly, the last step shortened to land on
    // it: for measurements at a given instant (the benchmark's errors). The
    // views use advanceTo, so their frame times never shape the trajectory.
    bool advanceExactlyTo(double t) {
        while (t_ < t && failure_.empty())
            if (!takeStep(t)) break;
        return failure_.empty();
    }
    // One internal step (or up to the next scripted instant).
    bool stepOnce();
    // The same, but never past `limit`: the last step of a run that must end
    // at exactly that time is shortened to land on it.
    bool stepOnceUpTo(double limit) { return takeStep(limit); }
    // Runs until an event happens or `limit` is reached; true if one happened.
    bool advanceToNextEvent(double limit);

    // Frames at exact times without letting those times shape the steps:
    // with a grid (grid.origin + k grid.every for every whole k), a step that
    // passes a time of the grid (strictly inside the step) leaves the state
    // at that time, read off the step's dense output, as a frame to take. A
    // step that ends on a grid time leaves none: frame() is that frame. A
    // grid with every = 0 is off.
    void setFrameGrid(const FrameGrid& grid) {
        grid_ = grid;
        gridDoneUpTo_ = t_;  // instants up to now are the caller's (frame())
    }
    const FrameGrid& frameGrid() const { return grid_; }
    std::vector<Frame> takeGridFrames() { return std::exchange(gridFrames_, {}); }
    const std::string& failure() const { return failure_; }

    // The mouse spring of docs/model.md section 11.3 on block `block`, grabbed at
    // `local` (block frame), pulled toward `target` (plane). Recorded into
    // scene().drags with the time each sample takes effect, so a replay of
    // the scene reproduces it exactly.
    void beginDrag(int block, const Vec2& local, const Vec2& target);
    void moveDrag(const Vec2& target);
    void endDrag();
    bool dragging() const { return liveDrag_ >= 0; }

    // Which block is under a point of the plane, and where on it (block frame).
    std::optional<std::pair<int, Vec2>> pick(const Vec2& point) const;

    // Solve every step's constraints with the sparse factorisation, even a
    // plain chain the O(N) elimination would take: so the benchmark can
    // compare the two models of a rigid pair (solver.rigid_pairs) on one solver.
    void useSparseSolver(bool on) {
        dynamics_.setForceSparse(on);
        keptEnd_.forget();  // the other solver may differ in the last bit
    }

    std::shared_ptr<const Snapshot> snapshot() const;
    void restore(const Snapshot& s);
    ~Simulation();
    // A hash of the bits of every block pose and velocity and the hinge modes
    // (FNV-1a over whole words): equal states give equal hashes.
    std::uint64_t stateHash() const;

private:
    explicit Simulation(const Scene& scene);
    // Building (simulation_build.cpp).
    std::optional<std::string> buildWorld();
    std::optional<std::string> addLadder(std::map<std::string, PartId>& named);
    void addBodies(std::map<std::string, PartId>& named);
    void addStops(const std::map<std::string, PartId>& named);
    void openBooks();
    void hangStillTail();
    std::optional<std::string> belowTheFloor() const;
    void wakeThrough(int block);
    double nextScheduledTime() const;
    void applyDueInputs();
    void applyScriptAction(const ScriptAction& a);
    std::vector<Event> grab(PartId part);  // the contacts it opened
    std::vector<Event> pushBlock(PartId part, const ScriptAction& a);
    // A scripted join; the reason if refused (the world unchanged then).
    std::optional<std::string> join(const ScriptAction& a);
    void applyDragSample(const DragRecord& d, const DragRecord::Sample& s);
    void removeMouseSpring(const DragRecord& d);
    // Stepping (simulation_step.cpp), a step in its stages. A step as
    // chosen before it is taken:
    struct StepPlan {
        double start = 0;      // s, the time the step starts at
        double h = 0;          // s, the step to take
        double chosen = 0;     // s, the step chosen before landing on `scheduled`
        double scheduled = 0;  // s, the next instant a step must land on
        bool lands = false;    // whether this step lands on it
        bool adaptive = false;
        double next0 = 0;  // s, the adaptive method's next step before this one
    };
    bool takeStep(double limit);
    StepPlan planStep(double limit);
    void keepStepStart(bool adaptive);
    bool blownUp(const MotionStep& m, double chosen);
    std::optional<bool> ladderAtStepEnd(MotionStep& m, double& taken, const StepPlan& plan);
    bool settleEvents(MotionStep& m, double& taken, double fEnd, double forces, const StepPlan& plan);
    void retakeToDip(double dip);
    void settleOrRetake(MotionStep& m, double& taken, std::vector<Event> happened,
                        const std::function<std::vector<Event>()>& settle);
    void retakeWhole(MotionStep& m, double& taken);
    static constexpr int kRelocations = 4;  // located again after an instant that settled nothing
    // The pin stops at the step's end (simulation_stops.cpp), as the ladder's.
    std::optional<bool> stopsAtStepEnd(MotionStep& m, double& taken, const StepPlan& plan);
    void locateStop(double& taken);
    double stopFunctionsAmong(double t, bool forces);
    void wakeTailIfReached(double taken);
    // The dynamics at a step's ends, kept (simulation_step_ends.cpp).
    const Powers* startAsLastEnd();
    double eventFunctionsAtEnd(const MotionStep& m, double taken, double* forces);
    Powers stepEndAsTaken(double taken);
    // The ladder's events inside a step (simulation_events.cpp).
    double smallestEventFunction(double t, double* forces = nullptr);
    double eventFunctionsNow(double* forces);
    bool locateEvent(double& taken, double fEnd, double forcesAtEnd, double from = 0);
    void eventFunctionsAtStart();
    void passFrom(double from, std::vector<int>& hinges, std::vector<int>& contacts);
    bool passed(int k) const {
        return !passed_.empty() && std::find(passed_.begin(), passed_.end(), k) != passed_.end();
    }
    EventBracket narrowAmong(const std::vector<int>& among, bool anglesOnly, EventBracket b);
    double positionFunctions(double h);
    EventBracket narrowContacts(const std::vector<int>& crossed, bool afterHinges, bool positionsOnly, double from,
                                double atStart, double atEnd, EventBracket b);
    void restoreStepStart();
    void keepBeforeChange();
    bool stopOnLadderError(double stepStart);
    bool stopAt(double stepStart, std::string why);  // a copy: restoring clears the ladder's error
    std::optional<std::string> squeezedByTheHand(double heldBefore) const;
    void emitGridFrames(double taken);
    void record(const Event& e);
    bool booksDiverged() const;
    double energyFlowed(const Energy& e) const;
    double booksImbalance(double total) const;
    double fastestRate();
    double fixedStep();
    void noteStep(double h);
    bool retryWithSmallerStep();
    bool retakeIfStiffened(const StepPlan& plan, double taken);
    // Where within the step just taken a free hinge dips past a limit (0: none).
    double limitDip(double taken);
    std::string blowUpAdvice(double h) const;
    // What a Snapshot holds, in its order (simulation_snapshot.cpp).
    template <class Self>
    static auto stateOf(Self& s) {
        return std::tie(s.world_, s.ladder_, s.stops_, s.stepper_, s.ledger_, s.t_, s.impactLoss_, s.impactHeldWork_,
                        s.nextAction_, s.nextDragSample_, s.stats_, s.stepScale_, s.imbalanceBase_, s.booksScale_);
    }
    void fail(const std::string& why);

    static constexpr double kOpenEnd = std::numeric_limits<double>::max();  // no time limit

    Scene scene_;
    World world_;
    Dynamics dynamics_;
    // The dynamics evaluated at a step's ends: the end of one step is the
    // start of the next, and locating an event or reading frames off a step
    // needs both ends again.
    KeptEvaluation keptStart_, keptEnd_;
    bool ribbonsInFrames_ = true;
    Stepper stepper_;
    Ledger ledger_;
    std::optional<Ladder> ladder_;
    std::optional<PinStops> stops_;
    std::vector<PartId> blocks_;
    double t_ = 0;
    double initialEnergy_ = 0;
    double initialKinetic_ = 0, initialPotential_ = 0;  // after the inputs at t = 0
    double energyFloor_ = 0;                            // J, the least energy scale of the blow-up check
    double impactLoss_ = 0, impactHeldWork_ = 0;
    size_t nextAction_ = 0;
    std::vector<size_t> nextDragSample_;
    int liveDrag_ = -1;
    std::vector<Event> pending_;
    std::string failure_;
    SolverFrame stats_;
    bool timingEvents_ = false;
    double eventSeconds_ = 0, locatingSeconds_ = 0;
    double lastResidual_ = 0;
    double stepScale_ = 1;      // automatic step: halved after each step that blew up
    double imbalanceBase_ = 0;  // J, the books' imbalance at the last halving (the check watches growth past it)
    double booksScale_ = 0;     // J, the largest energyFlowed of the steps kept so far
    // While a step is taken again for its end (retakeIfStiffened), until it
    // is kept: the rate that end had, and how many tries.
    double stiffenedRate_ = 0;  // 1/s
    int retakes_ = 0;
    // fastestVibration of the last pin forces, with what it was computed
    // from: a step's end (the retake's check) and the next step's plan read
    // the same forces, and each reading is a pass over every pin.
    struct KeptVibration {
        bool known = false;
        std::uint64_t forces = 0, revision = 0;  // Dynamics::forcesGeneration, World::revision
        double omega = 0;                        // rad/s
    };
    KeptVibration keptVibration_;
    // Kept from step to step so that stepping allocates nothing.
    Eigen::VectorXd stepStartQ_, stepStartV_;  // the state the step started from
    Eigen::VectorXd stepStartA_;               // and its accelerations (adaptive steps with limits)
    Ledger stepStartLedger_;
    std::vector<double> eventValues_;
    Powers lastPowers_;  // of smallestEventFunction's evaluation
    int hingeFunctions_ = 0;
    double hingeForces_ = 0;    // eventFunctionsNow: the smallest of the hinges' force functions
    bool locating_ = false;     // locateEvent: a block contact's function counts if it crossed at the step's end  //
                                // eventValues_: the hinges' functions, then the block contacts'
    std::vector<int> crossed_;  // locateEvent: the event functions past their event at the step's end
    std::vector<int> passed_;   // locateEvent from an instant that settled nothing: those past their event there
    StepInterpolant interpolant_;
    FrameGrid grid_;
    double gridDoneUpTo_ = 0;        // s, grid frames are emitted after this time
    std::vector<Frame> gridFrames_;  // emitted, not yet taken
    // The state before the step's first change of structure (an event, a
    // script action, a wake of the still tail): what a ladder error raised
    // later in the step goes back to. Taken only when a change comes, into
    // storage kept from step to step (a copy, no allocation).
    std::shared_ptr<Snapshot> beforeChange_;
    bool changeKept_ = false;
    bool wokeUnkept_ = false;  // the tail woke in this step with nothing kept before it
};

}  // namespace jl
