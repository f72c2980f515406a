#include "jl/sim/simulation.h"

#include "jl/engine/energy.h"
#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/scene/scalar_text.h"
#include "snapshot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <utility>

namespace jl {

namespace {

constexpr double kDragTimeConstant = 0.05;   // s, the mouse spring's response
constexpr double kDragMaxAcceleration = 20;  // in g: the spring's force cap per kg

Vec2 vec(const Point2& p) { return {p[0], p[1]}; }

// Whether two parts share a point already (a hinge, or a pair locked or
// folded by the ladder).
bool shareAPoint(const World& w, PartId a, PartId b) {
    for (ParticleId id = 0; id < w.particleCount(); ++id) {
        if (!w.isLive(id)) continue;
        bool onA = false, onB = false;
        for (const Attachment& x : w.particle(id).at) {
            onA = onA || x.part == a;
            onB = onB || x.part == b;
        }
        if (onA && onB) return true;
    }
    return false;
}

// The largest distance between the points a particle joins (m).
double particleSpread(const World& w, ParticleId id) {
    const std::vector<Attachment>& at = w.particle(id).at;
    const Vec2 first = w.pointPosition(at.front().part, at.front().local);
    double spread = 0;
    for (const Attachment& x : at) spread = std::max(spread, (w.pointPosition(x.part, x.local) - first).norm());
    return spread;
}

}  // namespace

Simulation::Simulation(const Scene& scene) : scene_(scene), stepper_(scene.solver.integrator, scene.solver.tolerance) {}

Simulation::Built Simulation::build(const Scene& scene) {
    Built b;
    std::unique_ptr<Simulation> s(new Simulation(scene));
    if (auto error = s->buildWorld()) {
        b.errors.push_back(*error);
        return b;
    }
    b.simulation = std::move(s);
    return b;
}

// ---- building the world of a scene ----

std::optional<std::string> Simulation::buildWorld() {
    world_.gravity = vec(scene_.gravity);
    world_.setWeldRigidPairs(scene_.solver.rigidPairs == RigidPairs::Weld);
    std::map<std::string, PartId> named;
    if (scene_.ladder) {
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
    }
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
    // A point reference becomes a particle: on the ground, on a part, or a
    // free particle's own.
    auto particleAt = [&](const PointRef& r) -> std::optional<ParticleId> {
        if (r.on == "world") return world_.anchor(vec(r.local));
        auto it = named.find(r.on);
        if (it == named.end()) return std::nullopt;
        if (world_.part(it->second).isPoint) {
            for (ParticleId id = 0; id < world_.particleCount(); ++id)
                if (world_.particle(id).at.front().part == it->second) return id;
        }
        return world_.addParticle(it->second, vec(r.local));
    };
    for (const PinSpec& pin : scene_.pins) {
        const auto a = particleAt(pin.a), b = particleAt(pin.b);
        if (!a || !b) return "a pin refers to '" + (a ? pin.b.on : pin.a.on) + "', which does not exist";
        // A pin joins two points that coincide. Points apart at the start would
        // be frozen where they stand (combine makes a rigid joint of what it
        // finds), with no gap left to measure: refuse, and say how far apart.
        constexpr double kAssembled = 1e-6;  // m: coordinates written to the micrometre
        const double apart = (world_.particlePosition(*a) - world_.particlePosition(*b)).norm();
        if (!(apart <= kAssembled)) {
            char text[160];
            std::snprintf(text, sizeof text,
                          "pin between '%s' and '%s': its two points are %.6g m apart at the start; "
                          "place them where they meet",
                          pin.a.on.c_str(), pin.b.on.c_str(), apart);
            return std::string(text);
        }
        auto e = world_.combine(*a, *b);
        if (!e) e = makeConsistentAfter(world_, "combine");
        if (e) return "pin between '" + pin.a.on + "' and '" + pin.b.on + "': " + e->message;
    }
    for (const SpringSpec& s : scene_.springs) {
        const auto a = particleAt(s.a), b = particleAt(s.b);
        if (!a || !b) return "a spring refers to '" + (a ? s.b.on : s.a.on) + "', which does not exist";
        const double rest = s.restLength.value_or((world_.particlePosition(*b) - world_.particlePosition(*a)).norm());
        world_.addSpring({*a, *b, s.stiffness, rest, s.damping});
    }
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
    if (auto below = belowTheFloor()) return below;
    // E(0) is the energy before the inputs at t = 0: what they did (pushes,
    // joins, impacts) is on the books already.
    const Energy e0 = energy(world_);
    initialEnergy_ = e0.total() + impactLoss_ - impactHeldWork_ - ledger_.user - ledger_.held + ledger_.damping;
    initialKinetic_ = e0.kinetic;
    initialPotential_ = e0.potential;
    // What "small" means for the books when nothing has moved yet: every
    // part lifted by its own half size (at rest, the flows are all zero and
    // the first step's rounding, or explicit Euler's first kick, would look
    // like a blow-up against them alone), and what the springs hold (without
    // gravity a plucked spring is all the energy there is to flow).
    energyFloor_ = 0;
    for (PartId p = 1; p < world_.partCount(); ++p)
        energyFloor_ += world_.part(p).mass * world_.gravity.norm() * (world_.part(p).halfSize.norm() + 1e-3);
    for (const Spring& s : world_.springs()) energyFloor_ += elasticEnergy(world_, s);
    lastResidual_ = pinResidual(world_);
    hangStillTail();
    return std::nullopt;
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

// ---- the script and the user's drags ----

// The next instant the step must land on: a scripted action, or the start or
// end of a held block's scripted move (its acceleration jumps there).
double Simulation::nextScheduledTime() const {
    double next = kOpenEnd;
    for (const ScriptAction& a : scene_.script)
        if (a.at > t_) next = std::min(next, a.at);
    // Every move of a held block (scripted or following the mouse) starts
    // and ends with a jump of the hand's acceleration: the force tests run there.
    for (int b = 1; b < world_.bodyCount(); ++b) {
        if (!world_.body(b).alive || !world_.body(b).kinematic) continue;
        for (PartId p : world_.body(b).parts) {
            if (!world_.part(p).drive) continue;
            for (const DriveMove& m : world_.part(p).drive->moves())
                for (double kink : {m.t0, m.t0 + m.duration})
                    if (kink > t_) next = std::min(next, kink);
        }
    }
    return next;
}

// The hand takes hold of a block where it is. A moving block stops dead:
// an impact on everything joined to it (a held block has infinite mass),
// taken up by the pins' impulses and booked like the ladder's impacts: the
// energy of the velocity jump is dissipated, the rest is the hand's work. A held block is outside the books (its energy
// is the hand's), so its own kinetic and potential energy leave them as the hand's work too. The force tests follow
// (applyDueInputs runs them after any action).
std::vector<Event> Simulation::grab(PartId part) {
    const double before = energy(world_).total();
    const std::vector<Twist> velocities = world_.partVelocities();
    world_.hold(part, Drive(world_.partPose(part)));
    makeConsistent(world_, world_.restructureTolerance, false);
    world_.updateKinematics(t_);
    // A neighbour locked or folded to the block that would move away from
    // it goes on: its contact would have to pull to stop it.
    std::vector<Event> released;
    if (ladder_)
        released = ladder_->takeUp(world_, dynamics_, t_, velocities, "a grab's contacts");
    else
        projectVelocities(world_, dynamics_);
    const double dissipated = jumpEnergy(world_, velocities);
    impactLoss_ += dissipated;
    impactHeldWork_ += energy(world_).total() - before + dissipated;
    return released;
}

void Simulation::applyScriptAction(const ScriptAction& a) {
    using K = ScriptAction::Kind;
    const bool blockOk = a.block >= 0 && a.block < blockCount();
    if (!blockOk && a.kind != K::Cut) return;
    // What the action touches moves on its own from here.
    wakeThrough(a.kind == K::Cut ? a.hinge : a.block);
    if (a.kind == K::Join) wakeThrough(a.otherBlock);
    const PartId part = blockOk ? blockPart(a.block) : 0;
    Event e{t_, EventKind::Script, -1, -1, {}};
    std::vector<Event> released;  // contacts the action opened
    switch (a.kind) {
        case K::Turn:
        case K::Move: {
            if (!world_.isHeld(part)) released = grab(part);
            const double turn = a.kind == K::Turn ? a.angle : 0.0;
            const Vec2 offset = a.kind == K::Move ? vec(a.offset) : Vec2::Zero();
            world_.drive(part)->add({a.at, a.duration, offset, turn});
            e.text =
                "the hand " + std::string(a.kind == K::Turn ? "turns" : "moves") + " block " + std::to_string(a.block);
            break;
        }
        case K::Hold:
            released = grab(part);
            e.text = "the hand holds block " + std::to_string(a.block);
            break;
        case K::Release: {
            // The block comes back into the books with its energy, which the
            // hand held until now: the hand's work.
            const double before = energy(world_).total();
            world_.release(part);
            impactHeldWork_ += energy(world_).total() - before;
            e.text = "the hand lets go of block " + std::to_string(a.block);
            break;
        }
        case K::Push: {
            // The impulse's work is P . (v- + v+)/2 at the point it acts on; the
            // pins carry the rest of the change of kinetic energy into held
            // blocks (their impulsive work). A held block takes the push itself.
            if (world_.isHeld(part)) break;
            const double before = energy(world_).kinetic;
            const Vec2 local = vec(a.point), impulse = vec(a.impulse);
            const Vec2 v0 = world_.pointVelocity(part, local);
            if (ladder_) {
                released = ladder_->push(world_, dynamics_, t_, a.block, local, impulse);
            } else {
                const int b = world_.part(part).body;
                const Vec2 x = world_.pointPosition(part, local);
                world_.v.segment<2>(3 * b) += world_.body(b).invMass * impulse;
                world_.v[3 * b + 2] += world_.body(b).invInertia * cross(x - world_.q.segment<2>(3 * b), impulse);
                projectVelocities(world_, dynamics_);
            }
            const double work = 0.5 * impulse.dot(v0 + world_.pointVelocity(part, local));
            ledger_.user += work;
            impactHeldWork_ += energy(world_).kinetic - before - work;
            e.text = "block " + std::to_string(a.block) + " is pushed";
            break;
        }
        case K::Cut:
            // A refused action is said in the log, so a script's author sees why.
            if (!ladder_) break;
            if (auto refused = ladder_->cut(world_, a.hinge))
                e.text = "the cut of hinge " + std::to_string(a.hinge) + " is refused: " + *refused;
            else
                e = {t_, EventKind::Cut, a.hinge, -1, "the ribbons of hinge " + std::to_string(a.hinge) + " are cut"};
            break;
        case K::Join:
            if (!ladder_ || a.otherBlock < 0 || a.otherBlock >= blockCount()) break;
            if (auto refused = join(a))
                e.text = "the join of corner " + std::to_string(a.corner) + " of block " + std::to_string(a.block) +
                         " to corner " + std::to_string(a.otherCorner) + " of block " + std::to_string(a.otherBlock) +
                         " is refused: " + *refused;
            break;
    }
    if (!e.text.empty()) record(e);
    for (Event& r : released) record(r);
}

// A scripted join: the two corners are pulled together (positions only: the
// mass-weighted projection onto the new pin) and their motion is merged
// (velocities only: a plastic impact, the merge of a rigid pair and the
// projection onto the pin). The books, as for the ladder's own impacts:
// the pull's change of potential energy is the user's work; the merge
// dissipates the energy of its velocity jump (>= 0, in any frame) and the
// held blocks' impulses do the rest of the change (held work).
// Hinges the pull drove past their limits are settled at once by the
// ladder's events; their snaps finish the pull (user's work too).
// Refused, leaving the world as it was, when it would not make a hinge:
// between two blocks that already share a point or move as one body (the
// world's combine would make them one rigid body at their current pose, a
// gap between the corners locked inside it for a later cut to close; in weld
// mode it would turn one about the other, through it if need be), or when
// the corners do not end up together (two held blocks, a failed projection),
// or when the pull leaves a corner inside a block it meets by contact.
std::optional<std::string> Simulation::join(const ScriptAction& a) {
    const PartId first = blockPart(a.block), second = blockPart(a.otherBlock);
    if (world_.part(first).body == world_.part(second).body || shareAPoint(world_, first, second))
        return "the blocks are joined already (a second point would make them one rigid body, not a hinge)";
    // Joining the corners of a cut hinge makes the hinge again (with its own
    // particles, so that it locks and flips as before); any other join is a
    // plain pin the ladder knows nothing of.
    const std::optional<int> hinge = ladder_->cutHingeJoinedBy(a.block, a.corner, a.otherBlock, a.otherCorner);
    const ParticleId p = hinge ? ladder_->hinge(*hinge).own[size_t(a.corner)] : ladder_->particle(a.block, a.corner);
    const ParticleId q =
        hinge ? ladder_->hinge(*hinge).own[size_t(4 + a.corner)] : ladder_->particle(a.otherBlock, a.otherCorner);
    const World saved = world_;
    const Energy e0 = energy(world_);
    const std::vector<Twist> before = world_.partVelocities();
    if (auto e = world_.combine(p, q)) return e->message;  // refused by the world: nothing changed
    const double tolerance = scene_.solver.projectionTolerance;
    const ProjectionResult pulled = makeConsistent(world_, tolerance);
    if (!pulled.converged || !(particleSpread(world_, p) <= tolerance) || !world_.q.allFinite() ||
        !world_.v.allFinite()) {
        world_ = saved;
        dynamics_.forgetStructure();
        return pulled.converged ? "the corners cannot be brought together (both blocks are held)"
                                : "the pull onto the new pin did not converge";
    }
    // Contacts meet a corner as it arrives at a face, never one that starts
    // inside: a pull through another block (or the table) is not a motion
    // they can answer.
    if (auto through = ladder_->blockContacts().inside(world_, *ladder_)) {
        world_ = saved;
        dynamics_.forgetStructure();
        return "the pull would pass through: " + *through;
    }
    const Energy e1 = energy(world_);
    // The merge's loss is the energy of its velocity jump in the mass
    // metric, held parts left out (as a grab's and an impact's): it needs
    // no frame, and a moving hand's share goes to the held work below.
    const double dissipated = jumpEnergy(world_, before);
    ledger_.user += e1.potential - e0.potential;
    impactLoss_ += dissipated;
    impactHeldWork_ += e1.kinetic - e0.kinetic + dissipated;
    record({t_, EventKind::Join, -1, -1,
            "corner " + std::to_string(a.corner) + " of block " + std::to_string(a.block) + " is joined to corner " +
                std::to_string(a.otherCorner) + " of block " + std::to_string(a.otherBlock)});
    if (hinge) ladder_->rehinged(world_, *hinge, a.corner);
    dynamics_.evaluate(world_, t_);
    const double settling = energy(world_).potential;
    for (Event& ev : ladder_->settle(world_, dynamics_, t_, &impactLoss_, &impactHeldWork_)) record(ev);
    ledger_.user += energy(world_).potential - settling;
    return std::nullopt;
}

// The user's drag: the mouse spring on a free block; a held block's hand
// follows the mouse instead (docs/model.md sections 10 and 11.3).
void Simulation::applyDragSample(const DragRecord& d, const DragRecord::Sample& s) {
    if (d.block < 0 || d.block >= blockCount()) return;
    wakeThrough(d.block);
    const PartId part = blockPart(d.block);
    if (Drive* drive = world_.drive(part)) {
        const Pose final = drive->at(kOpenEnd).pose;
        drive->add({t_, 4 * kDragTimeConstant, vec(s.target) - final.apply(vec(d.point)), 0.0});
        return;
    }
    const double m = world_.part(part).mass;
    const double omega = 1.0 / kDragTimeConstant;
    UserDrag g{part,          vec(d.point),
               vec(s.target), m * omega * omega,
               2 * m * omega, kDragMaxAcceleration * m * std::max(world_.gravity.norm(), 9.81)};
    for (UserDrag& live : world_.drags())
        if (live.part == part && live.local == g.local) {
            live = g;
            return;
        }
    world_.drags().push_back(g);
}

// Script actions and drag samples due now; the step always lands on them.
void Simulation::applyDueInputs() {
    constexpr double eps = 1e-12;
    bool changed = false;
    while (nextAction_ < scene_.script.size() && scene_.script[nextAction_].at <= t_ + eps) {
        applyScriptAction(scene_.script[nextAction_++]);
        changed = true;
    }
    for (size_t i = 0; i < scene_.drags.size(); ++i) {
        const DragRecord& d = scene_.drags[i];
        while (nextDragSample_[i] < d.samples.size() && d.samples[nextDragSample_[i]].t <= t_ + eps)
            applyDragSample(d, d.samples[nextDragSample_[i]++]);
        if (d.end <= t_ + eps) removeMouseSpring(d);
    }
    if (changed) {
        // Held blocks' accelerations may jump here: test the contacts.
        dynamics_.evaluate(world_, t_);
        if (ladder_)
            for (Event& e : ladder_->settle(world_, dynamics_, t_, &impactLoss_, &impactHeldWork_)) record(e);
    }
}

void Simulation::beginDrag(int block, const Vec2& local, const Vec2& target) {
    if (block < 0 || block >= blockCount()) return;
    endDrag();
    DragRecord d;
    d.block = block;
    d.point = {local.x(), local.y()};
    d.samples.push_back({t_, {target.x(), target.y()}});
    d.end = kOpenEnd;
    scene_.drags.push_back(d);
    nextDragSample_.push_back(1);
    liveDrag_ = int(scene_.drags.size()) - 1;
    applyDragSample(d, d.samples.back());
}

void Simulation::moveDrag(const Vec2& target) {
    if (liveDrag_ < 0) return;
    DragRecord& d = scene_.drags[size_t(liveDrag_)];
    // Several moves between two steps: the last one wins, as in a replay.
    if (d.samples.back().t == t_)
        d.samples.back().target = {target.x(), target.y()};
    else
        d.samples.push_back({t_, {target.x(), target.y()}});
    nextDragSample_[size_t(liveDrag_)] = d.samples.size();
    applyDragSample(d, d.samples.back());
}

// The world's spring of a recorded drag, gone once the drag has ended.
void Simulation::removeMouseSpring(const DragRecord& d) {
    if (d.block < 0 || d.block >= blockCount()) return;
    const PartId part = blockPart(d.block);
    auto& drags = world_.drags();
    drags.erase(std::remove_if(drags.begin(), drags.end(),
                               [&](const UserDrag& g) { return g.part == part && g.local == vec(d.point); }),
                drags.end());
}

void Simulation::endDrag() {
    if (liveDrag_ < 0) return;
    DragRecord& d = scene_.drags[size_t(liveDrag_)];
    d.end = t_;
    // A drag of a free block while no time passed (the run was paused) did
    // nothing: it is not kept, so it is neither replayed nor saved. (A drag
    // of a held block moves the hand over the next 0.2 s: that one stays.)
    if (d.end <= d.samples.front().t && !world_.isHeld(blockPart(d.block))) {
        removeMouseSpring(d);
        scene_.drags.erase(scene_.drags.begin() + liveDrag_);
        nextDragSample_.erase(nextDragSample_.begin() + liveDrag_);
        liveDrag_ = -1;
        return;
    }
    liveDrag_ = -1;
    applyDueInputs();
}

// ---- frames, picking, snapshots ----

Frame Simulation::frame() {
    Frame f;
    f.time = t_;
    f.poses.reserve(blocks_.size());
    f.held.reserve(blocks_.size());
    for (PartId p : blocks_) {
        f.poses.push_back(world_.partPose(p));
        f.held.push_back(world_.isHeld(p));
    }
    if (ladder_) {
        f.hinges = ladder_->hingeFrames(world_);
        if (ribbonsInFrames_) f.ribbons = ladder_->ribbons(world_);
        f.blockContacts = ladder_->blockContacts().frames(world_, dynamics_);
    }
    const Energy e = energy(world_);
    f.energy.kinetic = e.kinetic;
    f.energy.potential = e.potential;
    f.energy.heldWork = ledger_.held + impactHeldWork_;
    f.energy.userWork = ledger_.user;
    f.energy.dampingLoss = ledger_.damping;
    f.energy.impactLoss = impactLoss_;
    f.energy.initial = initialEnergy_;
    f.solver = stats_;
    f.solver.evaluations = dynamics_.evaluations();
    f.solver.residual = lastResidual_;
    f.solver.pins = int(world_.pins().size());
    f.solver.stillFrom = ladder_ && ladder_->stillFrom() < ladder_->blockCount() ? ladder_->stillFrom() : -1;
    for (int b = 0; b < world_.bodyCount(); ++b)
        if (world_.body(b).alive && !world_.body(b).kinematic) ++f.solver.bodies;
    f.events = std::move(pending_);
    pending_.clear();
    if (const auto& drags = std::as_const(world_).drags(); !drags.empty()) {
        const UserDrag& g = drags.front();
        f.dragging = true;
        f.dragFrom = world_.pointPosition(g.part, g.local);
        f.dragTo = g.target;
    }
    f.failure = failure_;
    return f;
}

std::optional<std::pair<int, Vec2>> Simulation::pick(const Vec2& point) const {
    constexpr double margin = 0.002;  // m: thin blocks stay pickable
    for (int i = blockCount() - 1; i >= 0; --i) {
        const Part& part = world_.part(blockPart(i));
        const Pose pose = world_.partPose(blockPart(i));
        const Vec2 local = rotate(-pose.angle, point - pose.position);
        if (std::abs(local.x()) <= part.halfSize.x() + margin && std::abs(local.y()) <= part.halfSize.y() + margin)
            return std::make_pair(i, local);
    }
    return std::nullopt;
}

}  // namespace jl
