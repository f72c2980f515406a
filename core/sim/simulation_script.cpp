// The script: the next instant a step must land on, the actions and drag
// samples due then, and what each action does (the hand's grab, release,
// push; a cut; a join), with the books of each.
#include "jl/engine/energy.h"
#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/sim/simulation.h"

#include <algorithm>

namespace jl {

namespace {

Vec2 vec(const Point2& p) { return {p[0], p[1]}; }

// Whether two parts share a point already (a hinge, or a pair locked or
// folded by the ladder).
bool shareAPoint(const World& w, PartId a, PartId b) {
    for (ParticleId id = 0; id < w.particleCount(); ++id) {
        if (!w.isLive(id)) continue;
        bool onA = false, onB = false;
        w.forEachAttachment(id, [&](const Attachment& x) {
            onA = onA || x.part == a;
            onB = onB || x.part == b;
        });
        if (onA && onB) return true;
    }
    return false;
}

// The largest distance between the points a particle joins (m).
double particleSpread(const World& w, ParticleId id) {
    const std::vector<Attachment> at = w.attachments(id);
    const Vec2 first = w.pointPosition(at.front().part, at.front().local);
    double spread = 0;
    for (const Attachment& x : at) spread = std::max(spread, (w.pointPosition(x.part, x.local) - first).norm());
    return spread;
}

}  // namespace

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
            world_.editDrive(part)->add({a.at, a.duration, offset, turn});
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
        case K::Push:
            // A held block takes the push itself.
            if (world_.isHeld(part)) break;
            released = pushBlock(part, a);
            e.text = "block " + std::to_string(a.block) + " is pushed";
            break;
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

// A scripted push of a free block: an impulse at a point of it. The
// impulse's work is P . (v- + v+)/2 at the point it acts on; the pins carry
// the rest of the change of kinetic energy into held blocks (their
// impulsive work). Returns the contacts it opened.
std::vector<Event> Simulation::pushBlock(PartId part, const ScriptAction& a) {
    std::vector<Event> released;
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
    return released;
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

}  // namespace jl
