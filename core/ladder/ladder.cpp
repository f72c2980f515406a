#include "jl/ladder/ladder.h"

#include "jl/base/heap_bytes.h"
#include "jl/engine/projection.h"
#include "jl/ladder/block_corners.h"
#include "jl/scene/ladder_blocks.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace jl {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kNoEvent = 1.0;  // the value of a function with no event to watch

// Within [-pi, pi] std::remainder returns x itself; it is slow (it saves
// and restores the floating-point environment), and the change of a fold
// angle between two calls is nearly always that small.
double wrapToPi(double x) { return std::abs(x) <= kPi ? x : std::remainder(x, 2 * kPi); }

}  // namespace

std::optional<std::string> Ladder::validate(const LadderSpec& spec) {
    if (spec.blocks < 2) return "a ladder needs at least 2 blocks";
    if (!(spec.block.length > 0)) return "block length must be positive";
    for (int h : spec.held)
        if (h < 0 || h >= spec.blocks) return "held block " + std::to_string(h) + " does not exist";
    return std::nullopt;
}

Ladder::Ladder(World& w, const LadderSpec& spec) : spec_(spec), length_(spec.block.length) {
    const int n = spec.blocks;
    blocks_.resize(size_t(n));
    thickness_.resize(size_t(n));
    corners_.resize(size_t(n));
    const std::vector<BlockSpec> blocks = ladderBlocks(spec);
    for (int i = 0; i < n; ++i) {
        const BlockSpec& b = blocks[size_t(i)];
        const double t = b.thickness;
        thickness_[size_t(i)] = t;
        // Upright at angle 0: the length runs along the block's local y.
        blocks_[size_t(i)] = w.addBox(massOf(b), Vec2(t, length_), b.width, Pose{});
        for (int k = 0; k < 4; ++k)
            corners_[size_t(i)][size_t(k)] = w.addParticle(blocks_[size_t(i)], cornerLocal(i, k));
    }
    hinges_.resize(size_t(n - 1));
    stillPoints_.assign(size_t(n - 1), {-1, -1});
    stillFrom_ = n;
    for (int j = 1; j < n; ++j) hinges_[size_t(j - 1)].corner = (j % 2 == 1) ? 0 : 3;
    // phi = sense * (theta_j - theta_{j-1} + offset) for each corner k: the
    // angle of -d_b in the frame (d_a, n_a), whose handedness is the sense.
    foldLinear_.resize(size_t(n - 1));
    for (int j = 1; j < n; ++j)
        for (int k = 0; k < 4; ++k) {
            const Vec2 c = cornerLocal(j - 1, k);
            const Vec2 da = cornerLocal(j - 1, k ^ 1) - c, na = cornerLocal(j - 1, k ^ 2) - c;
            const Vec2 db = cornerLocal(j, k ^ 1) - cornerLocal(j, k);
            FoldLinear& f = foldLinear_[size_t(j - 1)][size_t(k)];
            f.sense = cross(da, na) > 0 ? 1.0 : -1.0;
            f.offset = std::atan2(db.y(), db.x()) + kPi - std::atan2(da.y(), da.x());
        }
    // A small fraction of the time a block takes to fall its own length.
    const double g = w.gravity.norm();
    zenoTime_ = g > 0 ? 0.0125 * std::sqrt(length_ / g) : 1e-3;
    // The scales of the contact tests. Without gravity, 1 m/s^2 stands in
    // for it (a scripted push sets the forces then).
    double lightest = std::numeric_limits<double>::infinity();
    for (const BlockSpec& b : blocks) lightest = std::min(lightest, massOf(b));
    const double accel = g > 0 ? g : 1.0, timeScale = std::sqrt(length_ / accel);
    forceTolerance_ = 1e-8 * lightest * accel;
    impulseTolerance_ = 5e-8 * lightest * accel * timeScale;
    restingRate_ = 1e-10 / timeScale;
    place(w);
    for (int j = 1; j < n; ++j) {
        Hinge& h = hinges_[size_t(j - 1)];
        for (int k = 0; k < 4; ++k) {
            h.own[size_t(k)] = w.addParticle(blocks_[size_t(j - 1)], cornerLocal(j - 1, k));
            h.own[size_t(4 + k)] = w.addParticle(blocks_[size_t(j)], cornerLocal(j, k));
        }
        w.combine(h.own[size_t(h.corner)], h.own[size_t(4 + h.corner)]);
        if (spec.hinges.damping > 0)
            dampers_.push_back(w.addRotaryDamper({blocks_[size_t(j - 1)], blocks_[size_t(j)], spec.hinges.damping}));
    }
    for (int h : spec.held) {
        const PartId p = blocks_[size_t(h)];
        w.hold(p, Drive(w.partPose(p)));
        makeConsistent(w, w.restructureTolerance, false);
    }
    updateAngles(w);
}

Vec2 Ladder::cornerLocal(int i, int k) const { return blockCorner(i, k, thickness_[size_t(i)], length_); }

Vec2 Ladder::cornerWorld(const World& w, int i, int k) const { return w.pointPosition(block(i), cornerLocal(i, k)); }

// ---- placing the blocks ----

void Ladder::place(World& w) {
    const InitialState& init = spec_.initial;
    if (init.kind == InitialState::Kind::Poses) {
        for (const BlockState& s : init.poses)
            w.setPartState(block(s.block), Pose{Vec2(s.position[0], s.position[1]), s.angle},
                           Twist{Vec2(s.velocity[0], s.velocity[1]), s.angularVelocity});
        return;
    }
    if (init.kind == InitialState::Kind::FoldAngles) {
        // Block 0 at the origin, upright, unless a pose places it.
        Pose first;
        for (const BlockState& s : init.poses)
            if (s.block == 0) first = Pose{Vec2(s.position[0], s.position[1]), s.angle};
        w.setPartState(block(0), first, {});
        for (int j = 1; j < blockCount(); ++j) {
            const int k = hinge(j).corner;
            const Vec2 pin = cornerWorld(w, j - 1, k);
            const Vec2 da = (cornerWorld(w, j - 1, k ^ 1) - pin).normalized();
            const Vec2 na = (cornerWorld(w, j - 1, k ^ 2) - pin).normalized();
            const double phi = init.foldAngles[size_t(j - 1)];
            const Vec2 db = -std::cos(phi) * da - std::sin(phi) * na;
            const Vec2 dl = cornerLocal(j, k ^ 1) - cornerLocal(j, k);
            const double angle = std::atan2(db.y(), db.x()) - std::atan2(dl.y(), dl.x());
            w.setPartState(block(j), Pose{pin - rotate(angle, cornerLocal(j, k)), angle}, {});
        }
        return;
    }
    placeHanging(w);
}

// The hanging equilibrium: each block turns so that the centre of mass of
// itself and everything below hangs straight under its upper hinge. The
// blocks below hang from its lower hinge, so each angle follows alone.
void Ladder::placeHanging(World& w) {
    const int n = blockCount();
    std::vector<double> below(size_t(n) + 1, 0.0);
    for (int i = n - 1; i >= 0; --i) below[size_t(i)] = below[size_t(i) + 1] + w.part(block(i)).mass;
    const Vec2 down = w.gravity.norm() > 0 ? Vec2(w.gravity.normalized()) : Vec2(0, -1);
    w.setPartState(block(0), Pose{}, {});
    for (int i = 1; i < n; ++i) {
        const int k = hinge(i).corner;
        const Vec2 top = cornerLocal(i, k);
        Vec2 u = w.part(block(i)).mass * (-top);
        if (i + 1 < n) u += below[size_t(i) + 1] * (cornerLocal(i, hinge(i + 1).corner) - top);
        const double angle = std::atan2(down.y(), down.x()) - std::atan2(u.y(), u.x());
        const Vec2 pin = cornerWorld(w, i - 1, k);
        w.setPartState(block(i), Pose{pin - rotate(angle, top), angle}, {});
    }
}

// ---- fold angles ----

// phi = atan2(-n_a . d_b, -d_a . d_b) depends only on the two blocks'
// relative angle, linearly: no trigonometry at run time (this runs for
// every hinge at every evaluation of the event functions).
double Ladder::foldAngle(const World& w, int j) const {
    const FoldLinear& f = foldLinear_[size_t(j - 1)][size_t(hinge(j).corner)];
    const double raw = f.sense * (blockAngle(w, j) - blockAngle(w, j - 1) + f.offset);
    const double last = hinge(j).foldAngle;
    return last + wrapToPi(raw - last);
}

double Ladder::blockAngle(const World& w, int i) const {
    const Part& part = w.part(block(i));
    return w.q[3 * part.body + 2] + part.inBody.angle;
}

double Ladder::foldAcceleration(const World& w, int j) const {
    return foldSense(w, j) * (w.a[3 * w.part(block(j)).body + 2] - w.a[3 * w.part(block(j - 1)).body + 2]);
}

// +1 if phi grows as block j turns counter-clockwise relative to block j-1:
// the sign of d_a x n_a (a block-frame property: it flips with the corner).
double Ladder::foldSense(const World&, int j) const {
    return foldLinear_[size_t(j - 1)][size_t(hinge(j).corner)].sense;
}

double Ladder::foldRate(const World& w, int j) const {
    return foldSense(w, j) * (w.partVelocity(block(j)).angular - w.partVelocity(block(j - 1)).angular);
}

// Locked and folded pairs are rigid at exactly 0 and pi (snapped when they
// formed); free hinges are tracked continuously.
void Ladder::updateAngles(const World& w) {
    for (int j = 1; j < liveEnd(); ++j) {
        Hinge& h = hinges_[size_t(j - 1)];
        if (h.mode == HingeMode::Free) {
            h.foldAngle = foldAngle(w, j);
            if (h.foldAngle > kTouchBand && h.foldAngle < kPi - kTouchBand) h.releaseGap = 0;  // clear of both limits
        }
        if (h.mode == HingeMode::OpenLocked) h.foldAngle = 0;
        if (h.mode == HingeMode::Folded) h.foldAngle = kPi;
    }
}

// Two functions per hinge, >= 0 while the mode may stand.
double Ladder::eventFunctions(const World& w, const Dynamics& d, std::vector<double>& out) const {
    angleEventFunctions(w, out);
    double smallestForce = std::numeric_limits<double>::infinity();
    for (int j = 1; j < liveEnd(); ++j) {
        double* g = &out[2 * size_t(j - 1)];
        switch (hinge(j).mode) {
            case HingeMode::Free:
            case HingeMode::Cut:
                continue;
            case HingeMode::OpenLocked: {
                const HingeContact c = contact(w, d, j);
                g[0] = c.normal + pullThreshold(c, false);
                break;
            }
            case HingeMode::Folded: {
                const HingeContact c = contact(w, d, j);
                const double threshold = pullThreshold(c, false);
                g[0] = c.nearEnd + threshold;
                g[1] = c.farEnd + threshold;
                break;
            }
        }
        smallestForce = std::min({smallestForce, g[0], g[1]});
    }
    return smallestForce;
}

// Free hinge j's two functions at fold angle phi: events where phi crosses 0
// or pi, measured from where a release left it (releaseGap).
std::array<double, 2> Ladder::limitFunctions(int j, double phi) const {
    const double zero = hinge(j).releaseGap - kAngleTolerance;
    return {phi - zero, kPi - phi - zero};
}

void Ladder::angleEventFunctions(const World& w, std::vector<double>& out) const {
    out.assign(2 * size_t(liveEnd() - 1), kNoEvent);
    for (int j = 1; j < liveEnd(); ++j) {
        if (hinge(j).mode != HingeMode::Free) continue;
        const auto [open, folded] = limitFunctions(j, foldAngle(w, j));
        out[2 * size_t(j - 1)] = open;
        out[2 * size_t(j - 1) + 1] = folded;
    }
}

double Ladder::angleEventFunction(const World& w, int k) const {
    const int j = k / 2 + 1;
    if (hinge(j).mode != HingeMode::Free) return kNoEvent;
    return limitFunctions(j, foldAngle(w, j))[size_t(k % 2)];
}

std::array<int, 2> Ladder::angleEventBodies(const World& w, int k) const {
    const int j = k / 2 + 1;
    return {w.part(block(j - 1)).body, w.part(block(j)).body};
}

// ---- events ----

// Turns the lower block's body about the hinge so phi is exactly `target`
// (the located time leaves it within the event tolerance of the limit).
void Ladder::snap(World& w, int j, double target) {
    const double delta = target - foldAngle(w, j);
    if (delta == 0) return;
    const Vec2 pin = cornerWorld(w, j - 1, hinge(j).corner);
    int b = w.part(block(j)).body;
    double turn = foldSense(w, j) * delta;
    if (w.body(b).kinematic) {  // the hand holds the lower side: turn the upper one
        b = w.part(block(j - 1)).body;
        turn = -turn;
        if (w.body(b).kinematic) return;
    }
    const Vec2 origin = w.q.segment<2>(3 * b);
    w.q.segment<2>(3 * b) = pin + rotate(turn, origin - pin);
    w.q[3 * b + 2] += turn;
    hinges_[size_t(j - 1)].foldAngle = target;
}

// Only the positions are closed here: joins happen in impacts, which set
// every velocity afterwards with the impact's own projection.
void Ladder::join(World& w, int j, int k) {
    const Hinge& h = hinge(j);
    auto e = w.combine(h.own[size_t(k)], h.own[size_t(4 + k)]);
    if (!e) e = closePinGaps(w, "combine");
    if (e) error_ = "hinge " + std::to_string(j) + " could not join corner " + std::to_string(k) + ": " + e->message;
}

// Parting a corner splits a rigid pair (or takes a weld's second point
// away): every block keeps its pose and velocity, which met the pins before
// and still meet the fewer pins after, so there is nothing to project (it
// would be a pass over the whole ladder at every flip and unlock).
void Ladder::part(World& w, int j, int k) {
    if (auto e = w.separate(hinge(j).own[size_t(k)]))
        error_ = "hinge " + std::to_string(j) + " could not part corner " + std::to_string(k) + ": " + e->message;
}

// A lock is a further combine (the pair becomes one body), at phi = 0.
void Ladder::lock(World& w, int j) {
    snap(w, j, 0.0);
    hinges_[size_t(j - 1)].mode = HingeMode::OpenLocked;
    join(w, j, hinge(j).corner ^ 2);
}

// Face to face, the far corners k^1 meet too: combine them.
void Ladder::fold(World& w, int j) {
    snap(w, j, kPi);
    hinges_[size_t(j - 1)].mode = HingeMode::Folded;
    join(w, j, hinge(j).corner ^ 1);
}

void Ladder::unlock(World& w, int j) {
    part(w, j, hinge(j).corner ^ 2);
    hinges_[size_t(j - 1)].mode = HingeMode::Free;
    hinges_[size_t(j - 1)].foldAngle = 0;
}

// The face-to-face pair tips over the far end: a separate at k leaves the
// pair hinged at k^1 on both blocks, and phi, measured there, falls from pi.
void Ladder::flipFlop(World& w, int j) {
    part(w, j, hinge(j).corner);
    Hinge& h = hinges_[size_t(j - 1)];
    h.corner ^= 1;
    h.mode = HingeMode::Free;
    h.foldAngle = kPi;
}

void Ladder::unfold(World& w, int j) {
    part(w, j, hinge(j).corner ^ 1);
    Hinge& h = hinges_[size_t(j - 1)];
    h.mode = HingeMode::Free;
    h.foldAngle = kPi;
}

std::optional<std::string> Ladder::cut(World& w, int j) {
    if (j < 1 || j >= blockCount()) return "hinge " + std::to_string(j) + " does not exist";
    Hinge& h = hinges_[size_t(j - 1)];
    if (h.mode == HingeMode::Cut) return "hinge " + std::to_string(j) + " is already cut";
    if (h.mode == HingeMode::OpenLocked) unlock(w, j);
    if (h.mode == HingeMode::Folded) unfold(w, j);
    part(w, j, h.corner);
    h.mode = HingeMode::Cut;
    h.held = false;
    // The damper stands for friction in the ribbons' hinge: cut, it is gone.
    if (!dampers_.empty()) w.setRotaryDamping(dampers_[size_t(j - 1)], 0);
    return std::nullopt;
}

std::optional<int> Ladder::cutHingeJoinedBy(int blockA, int cornerA, int blockB, int cornerB) const {
    if (cornerA != cornerB || std::abs(blockA - blockB) != 1) return std::nullopt;
    const int j = std::max(blockA, blockB);
    const Hinge& h = hinge(j);
    if (h.mode != HingeMode::Cut || (cornerA != h.corner && cornerA != (h.corner ^ 1))) return std::nullopt;
    return j;
}

void Ladder::rehinged(World& w, int j, int k) {
    if (!dampers_.empty()) w.setRotaryDamping(dampers_[size_t(j - 1)], spec_.hinges.damping);
    Hinge& h = hinges_[size_t(j - 1)];
    h.corner = k;
    h.mode = HingeMode::Free;
    h.foldAngle = kPi / 2;  // the reference of foldAngle: phi in (-pi/2, 3pi/2]
    h.foldAngle = foldAngle(w, j);
}

std::string Ladder::words(EventKind kind, int j) const {
    const std::string a = std::to_string(j - 1), b = std::to_string(j);
    switch (kind) {
        case EventKind::Lock:
            return "blocks " + a + " and " + b + " lock end to end";
        case EventKind::Unlock:
            return "blocks " + a + " and " + b + " unlock";
        case EventKind::Fold:
            return "blocks " + a + " and " + b + " fold face to face";
        case EventKind::Unfold:
            return "block " + b + " unfolds from block " + a;
        case EventKind::FlipFlop:
            return "block " + b + " flips over the far end of block " + a;
        case EventKind::Bounce:
            return "blocks " + a + " and " + b + " bounce apart";
        case EventKind::Cut:
            return "the ribbons of hinge " + std::to_string(j) + " are cut";
        default:
            return {};
    }
}

std::size_t Ladder::heapBytes() const {
    using jl::heapBytes;
    const InitialState& initial = spec_.initial;
    return heapBytes(spec_.overrides) + heapBytes(spec_.held) + heapBytes(initial.poses) +
           heapBytes(initial.foldAngles) + heapBytes(blocks_) + heapBytes(thickness_) + heapBytes(corners_) +
           heapBytes(hinges_) + heapBytes(dampers_) + heapBytes(foldLinear_) + heapBytes(stillPoints_) +
           blockContacts_.heapBytes();
}

}  // namespace jl
