// Building the world of a scene: its parts, pins and springs, the hand's
// first holds, the inputs due at t = 0 and the books opened after them, and
// the still tail of a ladder the motion has not reached yet.
#include "jl/engine/applied_forces.h"
#include "jl/engine/energy.h"
#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/scene/scalar_text.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace jl {

namespace {

Vec2 vec(const Point2& p) { return {p[0], p[1]}; }

using Names = std::map<std::string, PartId>;

// A point reference becomes a particle: on the ground, on a part, or a free
// particle's own.
std::optional<ParticleId> particleAt(World& w, const Names& named, const PointRef& r) {
    if (r.on == "world") return w.anchor(vec(r.local));
    auto it = named.find(r.on);
    if (it == named.end()) return std::nullopt;
    if (w.part(it->second).isPoint) {
        for (ParticleId id = 0; id < w.particleCount(); ++id)
            if (w.particle(id).own.part == it->second) return id;
    }
    return w.addParticle(it->second, vec(r.local));
}

// The scene's pins, each made one particle of the two points it joins.
std::optional<std::string> addPins(World& w, const Names& named, const std::vector<PinSpec>& pins) {
    for (const PinSpec& pin : pins) {
        const auto a = particleAt(w, named, pin.a), b = particleAt(w, named, pin.b);
        if (!a || !b) return "a pin refers to '" + (a ? pin.b.on : pin.a.on) + "', which does not exist";
        // A pin joins two points that coincide. Points apart at the start would
        // be frozen where they stand (combine makes a rigid joint of what it
        // finds), with no gap left to measure: refuse, and say how far apart.
        constexpr double kAssembled = 1e-6;  // m: coordinates written to the micrometre
        const double apart = (w.particlePosition(*a) - w.particlePosition(*b)).norm();
        if (!(apart <= kAssembled)) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "pin between '%s' and '%s': its two points are %.6g m apart at the start; "
                          "place them where they meet",
                          pin.a.on.c_str(), pin.b.on.c_str(), apart);
            return std::string(text);
        }
        auto e = w.combine(*a, *b);
        if (!e) e = makeConsistentAfter(w, "combine");
        if (e) return "pin between '" + pin.a.on + "' and '" + pin.b.on + "': " + e->message;
    }
    return std::nullopt;
}

// The scene's springs; one without a rest length rests as it starts.
std::optional<std::string> addSprings(World& w, const Names& named, const std::vector<SpringSpec>& springs) {
    for (const SpringSpec& s : springs) {
        const auto a = particleAt(w, named, s.a), b = particleAt(w, named, s.b);
        if (!a || !b) return "a spring refers to '" + (a ? s.b.on : s.a.on) + "', which does not exist";
        const double rest = s.restLength.value_or((w.particlePosition(*b) - w.particlePosition(*a)).norm());
        w.addSpring({*a, *b, s.stiffness, rest, s.damping});
    }
    return std::nullopt;
}

}  // namespace

std::optional<std::string> Simulation::buildWorld() {
    world_.gravity = vec(scene_.gravity);
    // A closed stop is a weld (docs/model.md section 18).
    const bool stops =
        std::any_of(scene_.pins.begin(), scene_.pins.end(), [](const PinSpec& p) { return p.minAngle || p.maxAngle; });
    world_.setWeldRigidPairs(scene_.solver.rigidPairs == RigidPairs::Weld || stops);
    std::map<std::string, PartId> named;
    if (auto e = addLadder(named)) return e;
    addBodies(named);
    if (auto e = addPins(world_, named, scene_.pins)) return e;
    if (auto e = addSprings(world_, named, scene_.springs)) return e;
    addStops(named);
    for (size_t i = 0; i < scene_.bodies.size(); ++i)
        if (scene_.bodies[i].held) {
            world_.hold(named[scene_.bodies[i].name], Drive(world_.partPose(named[scene_.bodies[i].name])));
            makeConsistent(world_, world_.restructureTolerance, false);
        }
    for (PartId p : blocks_) world_.setDamping(p, scene_.linearDamping, scene_.angularDamping);

    std::stable_sort(scene_.script.begin(), scene_.script.end(),
                     [](const ScriptAction& a, const ScriptAction& b) { return a.at < b.at; });
    nextDragSample_.assign(scene_.drags.size(), 0);
    world_.shrinkToFit();
    makeConsistent(world_, scene_.solver.projectionTolerance);
    dynamics_.evaluate(world_, 0);
    // Force tests at t = 0 (docs/model.md section 8.7), then the books open.
    applyDueInputs();
    if (ladder_)
        for (Event& e : ladder_->settle(world_, dynamics_, 0, &impactLoss_, &impactHeldWork_)) record(e);
    // A start the ladder cannot settle (hinges whose corners cannot be
    // joined) is a scene that cannot be built, not a run that fails later.
    if (ladder_ && !ladder_->error().empty()) return "at t = 0: " + ladder_->error();
    if (stops_) {
        if (auto outside = stops_->outsideAtStart(world_)) return *outside;
        for (Event& e : stops_->settle(world_, dynamics_, 0, &impactLoss_, &impactHeldWork_)) record(e);
        if (!stops_->error().empty()) return "at t = 0: " + stops_->error();
    }
    if (auto below = belowTheFloor()) return below;
    openBooks();
    lastResidual_ = pinResidual(world_);
    hangStillTail();
    return std::nullopt;
}

// The ladder of the scene, its blocks named "block:0", "block:1", ...
std::optional<std::string> Simulation::addLadder(std::map<std::string, PartId>& named) {
    if (!scene_.ladder) return std::nullopt;
    if (auto e = Ladder::validate(*scene_.ladder)) return e;
    ladder_.emplace(world_, *scene_.ladder);
    ladder_->blockContacts().setEnabled(scene_.solver.blockContact == BlockContact::On);
    if (scene_.floor) ladder_->blockContacts().setFloor(scene_.floor->height);
    ladder_->setGapTolerance(scene_.solver.projectionTolerance);
    ladder_->blockContacts().setAllowance(scene_.solver.projectionTolerance);
    for (int i = 0; i < ladder_->blockCount(); ++i) {
        blocks_.push_back(ladder_->block(i));
        named["block:" + std::to_string(i)] = ladder_->block(i);
    }
    return std::nullopt;
}

// The scene's own bodies and particles, after the ladder's blocks.
void Simulation::addBodies(std::map<std::string, PartId>& named) {
    for (const BodySpec& b : scene_.bodies) {
        const double mass = b.mass.value_or(b.density * b.length * b.thickness * b.width);
        const PartId p = world_.addBox(mass, Vec2(b.thickness, b.length), b.width, Pose{vec(b.position), b.angle},
                                       Twist{vec(b.velocity), b.angularVelocity}, b.inertia);
        named[b.name] = p;
        blocks_.push_back(p);
    }
    for (const ParticleSpec& s : scene_.particles) {
        const PartId p = world_.addPoint(s.mass, vec(s.position), vec(s.velocity));
        named[s.name] = p;
        blocks_.push_back(p);
    }
}

// The stops of the scene's pins (the reader lets them only between two bodies).
void Simulation::addStops(const std::map<std::string, PartId>& named) {
    std::vector<PinStop> stops;
    for (const PinSpec& p : scene_.pins)
        if (p.minAngle || p.maxAngle)
            stops.push_back({named.at(p.a.on), named.at(p.b.on), vec(p.a.local), vec(p.b.local), p.minAngle, p.maxAngle,
                             p.a.on, p.b.on, p.restitution});
    if (!stops.empty()) stops_.emplace(world_, std::move(stops));
}

// The books open after the inputs at t = 0. E(0) is the energy before them:
// what they did (pushes, joins, impacts) is on the books already.
void Simulation::openBooks() {
    const Energy e0 = energy(world_);
    initialEnergy_ = e0.total() + impactLoss_ - impactHeldWork_ - ledger_.user - ledger_.held + ledger_.damping;
    initialKinetic_ = e0.kinetic;
    initialPotential_ = e0.potential;
    // What "small" means for the books when nothing has moved yet: every
    // part lifted by its own half size (at rest, the flows are all zero and
    // the first step's rounding, or explicit Euler's first kick, would look
    // like a blow-up against them alone), and what the springs (the applied
    // forces' potentials) hold: without gravity a plucked spring is all the
    // energy there is to flow.
    energyFloor_ = 0;
    for (PartId p = 1; p < world_.partCount(); ++p)
        energyFloor_ += world_.part(p).mass * world_.gravity.norm() * (world_.part(p).halfSize.norm() + 1e-3);
    forEachAppliedPotential(world_, [&](double u) { energyFloor_ += u; });
}

// A block corner under the table top at the start (by more than the pins'
// tolerance): a scene that cannot be built, said with the block and how far.
std::optional<std::string> Simulation::belowTheFloor() const {
    if (!ladder_ || !scene_.floor) return std::nullopt;
    for (int i = 0; i < ladder_->blockCount(); ++i)
        for (int k = 0; k < 4; ++k) {
            const double gap = ladder_->cornerWorld(world_, i, k).y() - scene_.floor->height;
            if (gap < -scene_.solver.projectionTolerance)
                return "corner " + std::to_string(k) + " of block " + std::to_string(i) + " starts " +
                       formatNumber(-gap) + " m below the floor (floor.height " + formatNumber(scene_.floor->height) +
                       " m): raise the ladder or lower the floor";
        }
    return std::nullopt;
}

// The blocks of a ladder that the motion has not reached hang still as one
// body until it comes near them (docs/model.md section 3.7): below every
// block that moves or accelerates at the start, below every block the hand
// holds or a pin or spring of the scene holds, with Ladder::kWakeBlocks to
// spare. Air drag would act on each block by its own speed, and a tail that
// falls as one would not be the ladder's motion: not with drag.
void Simulation::hangStillTail() {
    if (!ladder_ || scene_.solver.stillTail != StillTail::Joined || scene_.linearDamping > 0 ||
        scene_.angularDamping > 0 || !(world_.gravity.norm() > 0) || scene_.floor)
        return;
    const int n = ladder_->blockCount();
    int deepest = 0;
    for (int h : scene_.ladder->held) deepest = std::max(deepest, h);
    // A block the script grabbed at t = 0 (a turn, move or hold due then)
    // is held by now: a segment holding it would be one kinematic body,
    // turned rigidly by the hand.
    for (int i = 0; i < n; ++i)
        if (world_.isHeld(blocks_[size_t(i)])) deepest = std::max(deepest, i);
    const auto touches = [&](const PointRef& r) {
        if (r.on.rfind("block:", 0) == 0) deepest = std::max(deepest, std::atoi(r.on.c_str() + 6));
    };
    for (const PinSpec& p : scene_.pins) touches(p.a), touches(p.b);
    for (const SpringSpec& s : scene_.springs) touches(s.a), touches(s.b);
    // Still: no speed at all, and accelerations within rounding of none (the
    // last evaluation is of the state after the inputs at t = 0). A move of
    // the hand that starts at t = 0 is not one of them: its acceleration
    // reaches every block through the pins at once, and the tail wakes when
    // the motion comes near it, as for a move that starts later.
    const bool handMoving = !world_.pathsOnOnePiece(-kOpenEnd, t_);
    if (handMoving) dynamics_.evaluate(world_, t_, -kOpenEnd);
    const double length = scene_.ladder->block.length;
    const double quiet = Ladder::kStillTolerance * world_.gravity.norm();
    for (int i = n - 1; i > deepest; --i) {
        const int b = world_.part(blocks_[size_t(i)]).body;
        const Eigen::Vector3d v = world_.v.segment<3>(3 * b), a = world_.a.segment<3>(3 * b);
        if (v.head<2>().norm() + length * std::abs(v[2]) > 0 || a.head<2>().norm() + length * std::abs(a[2]) > quiet) {
            deepest = i;
            break;
        }
    }
    if (ladder_->hangStill(world_, deepest + Ladder::kWakeBlocks + 1) || handMoving) dynamics_.evaluate(world_, t_);
}

// Parts the still tail through `block` (docs/model.md section 3.7). If
// anything woke, the world is evaluated again: the pin forces that the
// next automatic step is chosen from must be those of the pins there are now.
void Simulation::wakeThrough(int block) {
    if (ladder_ && ladder_->wakeThrough(world_, block) > 0) dynamics_.evaluate(world_, t_);
}

}  // namespace jl
