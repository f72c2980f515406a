// The Jacob's ladder on the engine: blocks with xor-numbered corners, the
// hinge state machine of docs/model.md section 8 (free, open-locked, folded) and
// its events, written on World::combine/separate; which ribbons show.
#pragma once

#include "jl/engine/dynamics.h"
#include "jl/engine/fresh.h"
#include "jl/engine/world.h"
#include "jl/ladder/block_contact.h"
#include "jl/ladder/hinge_event.h"
#include "jl/scene/scene.h"

#include <algorithm>
#include <array>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace jl {

struct Hinge {
    HingeMode mode = HingeMode::Free;
    int corner = 0;        // k: the same corner number on both blocks
    double foldAngle = 0;  // phi, tracked continuously
    // The accumulation point of a Zeno sequence (docs/model.md section 8.6,
    // "No chattering"). A release by an impact (a bounce, or a release in
    // an impact's active set) starts a rebound. A rebound that ends within
    // the Zeno time and is shorter than the rebound whose end started it
    // belongs to a shrinking sequence: the contact is held, and impacts of
    // that sequence leave it closed. Its force, pushes and any other impact
    // test it as they test every contact.
    double releasedAt = -1e300;  // s, the last release
    // s, what released it: the rebound whose end did (> 0); an impact that
    // ended no rebound (0); its own force or a push, no rebound (-1).
    double launchedBy = -1;
    double lastRebound = 0;  // s, the rebound its last close ended (0: that close ended none)
    bool held = false;
    double releaseGap = 0;  // rad, <= 0: how far past the limit it left the pair read (projection noise)
    // The hinge's own particles at each corner k of the upper (side 0) and
    // lower (side 1) block: a block's corner can be a hinge point of both
    // its hinges at once (after a flip both sit at one end), so no two
    // hinges may restructure through the same particle.
    std::array<ParticleId, 8> own{-1, -1, -1, -1, -1, -1, -1, -1};
};

// Contact forces of a locked or folded hinge (docs/model.md section 8.3), N,
// positive = pushing block j away from block j-1.
struct HingeContact {
    double normal = 0;   // OPEN-LOCKED: N at corner k^2
    double nearEnd = 0;  // FOLDED: N_near at corner k (with the pin at k^1)
    double farEnd = 0;   // FOLDED: N_far at corner k^1 (with the pin at k)
    // |F| of the wrench these were split from plus the sizes of its normal
    // forces: the load the contact carries, which sets the size of their
    // rounding (N, or N s). Alike for a pair and its mirror image.
    double load = 0;
};

class Ladder {
public:
    // Adds the blocks to the world, pins hinge j at corner 0 (j odd) or 3
    // (j even), places them (hanging equilibrium, explicit poses or fold
    // angles) and holds the held blocks. Errors in words; world untouched then.
    static std::optional<std::string> validate(const LadderSpec& spec);
    Ladder(World& w, const LadderSpec& spec);

    int blockCount() const { return int(blocks_.size()); }
    int hingeCount() const { return int(hinges_.size()); }  // N-1
    PartId block(int i) const { return blocks_[size_t(i)]; }
    const Hinge& hinge(int j) const { return hinges_[size_t(j - 1)]; }

    // Where corner k of block i is, in the block's frame (jl/ladder/block_corners.h,
    // the one place that says where a hinge attaches to a block).
    Vec2 cornerLocal(int i, int k) const;
    Vec2 cornerWorld(const World& w, int i, int k) const;
    // The particle at corner k of block i (for scripted joins; hinges use their own).
    ParticleId particle(int i, int k) const { return corners_[size_t(i)][size_t(k)]; }
    // phi of hinge j at its current corner, continuous near the last value.
    double foldAngle(const World& w, int j) const;
    double foldRate(const World& w, int j) const;  // d phi / dt

    // Event functions: each is >= 0 while its hinge may stay in its mode; a
    // negative value is an event (located inside the step by the simulation).
    // A limit is an event where the fold angle crosses it: kAngleTolerance
    // is only the rounding of phi (computed from two body angles that may
    // have turned many times), never an overshoot that the physics sees. A
    // located crossing lands well inside kTouchBand, where resolve() acts on
    // it. A hinge just released measures its limit from where the release
    // left it.
    static constexpr double kAngleTolerance = 1e-12;  // rad
    // Fold angles of bodies just projected onto their pins carry the
    // projection's noise (1e-10 m over a 1 mm block): a hinge within this
    // band of a limit touches it, and one past it by more is past it.
    static constexpr double kTouchBand = 1e-7;  // rad
    // A contact force (impulse) counts as pulling only past these, scaled
    // to the ladder: forces to the weight of its lightest block, impulses to
    // that weight times the time scale sqrt(L/g), and a hinge rests when it
    // turns slower than a fraction of 1 / sqrt(L/g). A 1 mm and a 1 m block
    // get the same relative thresholds (docs/model.md section 8.3).
    double forceTolerance() const { return forceTolerance_; }      // N
    double impulseTolerance() const { return impulseTolerance_; }  // N s
    // The threshold for one hinge contact: the ladder's, or the same
    // fraction of the load the contact carries where that is larger (a
    // hinge that holds up a long or heavy ladder computes its force with
    // rounding in proportion to that load, not to the lightest block).
    double pullThreshold(const HingeContact& c, bool impulse) const;
    double restingRate() const { return restingRate_; }  // rad/s
    // The largest pin gap an event may leave (the scene's projection
    // tolerance, docs/model.md section 14.3); resolve closes any wider one.
    void setGapTolerance(double metres) { gapTolerance_ = metres; }
    // Needs the accelerations of the state (Dynamics::evaluate done).
    // Returns the smallest of the contact-force functions (+inf if none).
    double eventFunctions(const World& w, const Dynamics& d, std::vector<double>& out) const;
    // Only the fold-angle functions of free hinges (the others 1, no event): they
    // need positions alone, no evaluation of the dynamics.
    void angleEventFunctions(const World& w, std::vector<double>& out) const;
    // Entry k of angleEventFunctions alone (hinge k / 2 + 1; phi for even k,
    // pi - phi for odd k): it reads the angles of the two bodies
    // angleEventBodies gives, and nothing else.
    double angleEventFunction(const World& w, int k) const;
    std::array<int, 2> angleEventBodies(const World& w, int k) const;
    // A free hinge that passes a limit and comes back within one step shows
    // no sign change at the step's ends. The time within the step (from 0
    // to h; `w` holds its end, evaluated, and `start` its start) where the
    // quintic through each free hinge's angle, rate and acceleration at the
    // ends is past a limit, the earliest; or 0 if none dips. `start` is
    // swapped into the world and back.
    struct StepStart {
        Eigen::VectorXd &q, &v, &a;
    };
    double limitDip(World& w, StepStart& start, double h) const;

    // resolve, then the contacts between blocks that are not neighbours
    // (docs/model.md section 17), and the hinges again after each change
    // there, until neither has anything to do. What the simulation calls.
    std::vector<Event> settle(World& w, Dynamics& d, double t, double* impactLoss, double* heldWork);
    BlockContacts& blockContacts() { return blockContacts_; }
    const BlockContacts& blockContacts() const { return blockContacts_; }
    double length() const { return length_; }  // m, every block's
    const HingeOptions& hingeOptions() const { return spec_.hinges; }

    // Applies whatever events the state calls for (limits crossed, contacts
    // pulling), impacts included, until none remains. Returns what happened.
    std::vector<Event> resolve(World& w, Dynamics& d, double t, double* impactLoss, double* heldWork);
    // resolve ends on an evaluation of the state it leaves (w.a and d's
    // forces are that evaluation's): these are its powers.
    const Powers& settledPowers() const { return settled_; }

    // An impulse P at a point (block frame) of block i that the hand does not
    // hold itself, taken up like an impact: with every constraint active; a
    // locked or folded contact it would pull is released (most negative
    // first, the slow-release rule included) and P taken up again. Returns the releases.
    std::vector<Event> push(World& w, Dynamics& d, double t, int i, const Vec2& local, const Vec2& impulse);
    // The part velocities `before` a jump that the world's constraints must
    // take up (a push added in, or a block the hand has just taken hold
    // of), with the same active set: every contact closed, one that would
    // pull released and the jump taken up again. Returns the releases.
    std::vector<Event> takeUp(World& w, Dynamics& d, double t, const std::vector<Twist>& before,
                              const std::string& what);

    // Contact forces of hinge j in the state last evaluated by d.
    HingeContact contact(const World& w, const Dynamics& d, int j) const;

    // Scripted structural changes.
    std::optional<std::string> cut(World& w, int j);
    // A scripted join of corner k of two neighbouring blocks whose hinge is
    // cut, k on the hinge's side (k or k^1 of where it was): that joins the
    // hinge again. Its number, or nothing if the join is not that. The
    // caller combines hinge(j).own[k] with own[4 + k] (not the blocks'
    // corner particles, so that locks and flips work on it as before) and
    // then calls rehinged.
    std::optional<int> cutHingeJoinedBy(int blockA, int cornerA, int blockB, int cornerB) const;
    // The hinge is FREE at corner k again, phi taken from the poses (past
    // a limit if the join left it there: the next resolve settles it).
    void rehinged(World& w, int j, int k);
    // A restructuring the world refused (a bug, reported rather than ignored).
    const std::string& error() const { return error_; }
    void updateAngles(const World& w);  // track phi continuously after a step
    // s: a rebound shorter than this, and shorter than the one before it,
    // is part of a Zeno sequence (a small fraction of the ladder's own time
    // scale sqrt(L/g), about 1 ms for 60 mm blocks).
    double zenoTime() const { return zenoTime_; }

    // ---- the still tail (docs/model.md section 3.7) ----
    // Blocks first .. N-1 of a ladder at rest hang still until the motion
    // reaches them, joined into a few rigid segments (combine, a second
    // shared point per hinge). False, with nothing changed, if the tail would be shorter
    // than kLeastStillTail blocks, the world welds its rigid pairs, or a
    // tail hangs still already.
    bool hangStill(World& w, int first);
    // The first block of the still tail (blockCount() when there is none);
    // hinges 1 .. stillFrom() are live, the ones below join still blocks.
    int stillFrom() const { return stillFrom_; }
    // After a step: if the motion has reached the tail (its top hinge has
    // turned, or turns, by more than kStillTolerance block lengths: 6e-11 m
    // for 60 mm blocks, far below any integrator's error on a long ladder), the
    // next kWakeBlocks blocks move on their own again. Returns how many.
    int wakeIfReached(World& w);
    bool tailReached(const World& w) const;
    // Before something acts on block `block` (a push, a grab, a join): it
    // and the kWakeBlocks below it move on their own again. Returns how many.
    int wakeThrough(World& w, int block);
    double stillTailStrain(const World& w) const;  // m: what the rigid tail may be getting wrong
    static constexpr int kLeastStillTail = 32;     // blocks: a shorter tail does not pay for its joins
    static constexpr int kWakeBlocks = 16;
    static constexpr double kStillTolerance = 1e-9;  // of a block length

    std::vector<HingeFrame> hingeFrames(const World& w) const;
    std::vector<RibbonFrame> ribbons(const World& w) const;

    // What it holds on the heap (jl/base/heap_bytes.h): what a copy takes.
    std::size_t heapBytes() const;

private:
    std::array<double, 2> limitFunctions(int j, double phi) const;  // phi - z, pi - phi - z
    struct Wrench {
        Vec2 force = Vec2::Zero();
        double moment = 0;  // about the hinge point
    };
    void place(World& w);
    void placeHanging(World& w);
    // An impact's velocity jump: part velocities before it and pin impulses.
    struct Impact {
        const std::vector<Twist>* before = nullptr;
        const Eigen::VectorXd* pinImpulses = nullptr;
    };
    Wrench internalWrench(const World& w, const Dynamics& d, int j, const Impact* impact) const;
    Wrench weldWrench(const World& w, const Dynamics& d, int j, const Impact* impact) const;
    // The sums of internalWrench over the blocks first .. last (hinge_wrench.cpp).
    bool onSide(PartId part, int first, int last) const;
    void addSideMotion(Wrench& s, const World& w, int body, int first, int last, const Vec2& p,
                       const Impact* impact) const;
    void addPinsOnSide(Wrench& s, const World& w, const Eigen::VectorXd& lambda, int first, int last,
                       const Vec2& p) const;
    void addContactsOnSide(Wrench& s, const World& w, const Dynamics& d, const Impact* impact, int first, int last,
                           const Vec2& p) const;
    void addDampersOnSide(Wrench& s, const World& w, int first, int last) const;
    double foldAcceleration(const World& w, int j) const;
    double foldSense(const World& w, int j) const;
    double blockAngle(const World& w, int i) const;
    bool touchingLimit(const World& w, int j, bool folded, bool resting) const;
    std::vector<Event> impact(World& w, Dynamics& d, double t, const std::vector<int>& hits, double* loss,
                              double* heldWork, std::vector<int>* releasedNow);
    // The hinges a located strike packs against their limits (block_contact.cpp).
    std::vector<int> packedBy(const World& w) const;
    std::optional<std::pair<int, EventKind>> pullingContact(const World& w, const Dynamics& d, const Impact* impact,
                                                            const std::vector<int>& keep = {},
                                                            bool spareHeld = false) const;
    bool wouldChatter(const World& w, double t, int j, EventKind kind, const std::vector<Twist>& before) const;
    struct ChatterTrial;                // ladder_events.cpp
    Fresh<ChatterTrial> chatterTrial_;  // wouldChatter's copy of the world, this ladder and dynamics
    void release(World& w, int j, EventKind kind, double t, double launchedBy = -1);
    bool noteClose(int j, double t);
    void capped(double t, const std::string& what);
    bool bothHeld(const World& w, int j) const;  // the blocks of hinge j, each in a held body
    HingeContact split(const World& w, int j, const Wrench& on) const;
    void snap(World& w, int j, double target);
    void join(World& w, int j, int k);              // combine the hinge's points at corner k
    void part(World& w, int j, int k);              // separate them
    void partStill(World& w, int first, int last);  // the still points of hinges first .. last
    void lock(World& w, int j);
    void fold(World& w, int j);
    void unlock(World& w, int j);
    void flipFlop(World& w, int j);
    void unfold(World& w, int j);
    std::string words(EventKind kind, int j) const;

    LadderSpec spec_;
    std::vector<PartId> blocks_;
    std::vector<double> thickness_;
    std::vector<std::array<ParticleId, 4>> corners_;
    std::vector<Hinge> hinges_;
    std::vector<int> dampers_;
    double length_ = 0;
    double zenoTime_ = 1e-3;
    double forceTolerance_ = 1e-9, impulseTolerance_ = 1e-9, restingRate_ = 1e-9;
    double gapTolerance_ = 1e-10;  // m
    // phi = sense * (theta_j - theta_{j-1} + offset), per hinge and corner.
    struct FoldLinear {
        double sense = 1, offset = 0;
    };
    std::vector<std::array<FoldLinear, 4>> foldLinear_;
    std::string error_;
    BlockContacts blockContacts_;
    Powers settled_;  // of resolve's last evaluation
    // The still tail: its first block, the resting fold angle of the hinge
    // above it, and the second shared point of each still hinge (on the
    // upper and the lower block; -1 while the hinge is live).
    int stillFrom_ = 0;
    double stillRest_ = 0;
    std::vector<std::array<ParticleId, 2>> stillPoints_;
    // The hinges the event tests visit: 1 .. liveEnd() - 1.
    int liveEnd() const { return std::min(stillFrom_ + 1, blockCount()); }
};

extern template class Fresh<Ladder::ChatterTrial>;

// The ribbons Ladder::ribbons gives, from a frame's record of the ladder
// instead of the world: block i at poses[i], as blocks[i] (ladderBlocks)
// says, and hinges[j - 1] hinge j. A view makes them when it draws them, so the
// frames a long run records need not carry them (two per hinge).
std::vector<RibbonFrame> ladderRibbons(const LadderSpec& spec, std::span<const BlockSpec> blocks,
                                       std::span<const Pose> poses, std::span<const HingeFrame> hinges);

}  // namespace jl
