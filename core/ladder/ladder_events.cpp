// The ladder's events: impacts at the limits of the fold angle and releases
// of contacts that would pull (docs/model.md section 8), as a deterministic
// active set.
#include "jl/engine/energy.h"
#include "jl/engine/projection.h"
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace jl {

namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kTouch = Ladder::kTouchBand;  // rad: this close to a limit touches it

}  // namespace

// A free hinge at a limit (within kTouch, either side: the located time
// leaves it a hair past) that it is moving into, or resting on with its
// acceleration pushing into it. A hinge deeper past the limit (end-of-step
// events) is hit whatever its motion. One just released sits at the limit
// moving away: not hit, whatever the sign of the rounding in phi.
bool Ladder::touchingLimit(const World& w, int j, bool folded, bool resting) const {
    const double phi = hinge(j).foldAngle;
    const double gap = folded ? kPi - phi : phi;  // >= 0 admissible
    if (gap < -kTouch) return true;
    if (gap > kTouch) return false;  // nearly every hinge, in every round: no rate needed
    const double rate = folded ? -foldRate(w, j) : foldRate(w, j);  // < 0 closing
    if (rate < -restingRate_) return true;
    return resting && rate <= restingRate_ && (folded ? -foldAcceleration(w, j) : foldAcceleration(w, j)) < 0;
}

bool Ladder::bothHeld(const World& w, int j) const {
    return w.body(w.part(block(j - 1)).body).kinematic && w.body(w.part(block(j)).body).kinematic;
}

// `launchedBy` as Hinge::launchedBy says: by default a release by the
// contact's own force (or a push), which starts no rebound.
void Ladder::release(World& w, int j, EventKind kind, double t, double launchedBy) {
    if (kind == EventKind::Unlock) unlock(w, j);
    if (kind == EventKind::FlipFlop) flipFlop(w, j);
    if (kind == EventKind::Unfold) unfold(w, j);
    Hinge& h = hinges_[size_t(j - 1)];
    h.releasedAt = t;
    h.launchedBy = launchedBy;
    h.held = false;
    // The parted bodies were projected onto their pins: phi may read a hair
    // past the limit it leaves. That is its zero until it moves clear.
    const double phi = foldAngle(w, j);
    h.releaseGap = std::min(0.0, h.foldAngle < kPi / 2 ? phi : kPi - phi);
}

// A contact closed at t. If an impact opened it, the open interval was a
// rebound; one within the Zeno time and shorter than the rebound that
// launched it belongs to a shrinking sequence, and the contact is held at
// its accumulation point (docs/model.md section 8.6, "No chattering").
bool Ladder::noteClose(int j, double t) {
    Hinge& h = hinges_[size_t(j - 1)];
    const double open = t - h.releasedAt;
    h.lastRebound = h.launchedBy >= 0 ? open : 0;
    h.held = h.launchedBy > 0 && open <= zenoTime_ && open < h.launchedBy;
    return h.held;
}

// The most negative contact force (or impulse) among locked and folded
// hinges, and what releasing it means: unlock, flip-flop or unfold.
// `spareHeld`: held contacts are left closed (an impact that ends a rebound
// of their own Zeno sequence).
std::optional<std::pair<int, EventKind>> Ladder::pullingContact(const World& w, const Dynamics& d, const Impact* impact,
                                                                const std::vector<int>& keep, bool spareHeld) const {
    std::optional<std::pair<int, EventKind>> worst;
    double most = std::numeric_limits<double>::infinity();
    for (int j = 1; j < liveEnd(); ++j) {
        const HingeMode mode = hinge(j).mode;
        if (mode != HingeMode::OpenLocked && mode != HingeMode::Folded) continue;
        if ((spareHeld && hinge(j).held) || std::find(keep.begin(), keep.end(), j) != keep.end()) continue;
        const HingeContact c = split(w, j, internalWrench(w, d, j, impact));
        const double tolerance = pullThreshold(c, impact != nullptr);
        if (mode == HingeMode::OpenLocked && c.normal < -tolerance && c.normal < most) {
            most = c.normal;
            worst = {j, EventKind::Unlock};
        }
        if (mode == HingeMode::Folded) {
            // A pair that can tip over both ends carries on over the far one.
            if (c.nearEnd < -tolerance && c.nearEnd < most) {
                most = c.nearEnd;
                worst = {j, EventKind::FlipFlop};
            } else if (c.farEnd < -tolerance && c.farEnd < most && c.nearEnd >= -tolerance) {
                most = c.farEnd;
                worst = {j, EventKind::Unfold};
            }
        }
    }
    return worst;
}

// The slow-release rule (docs/model.md section 8.6, "No chattering"): releasing hinge j at this impact would
// part the pair slower than v_min while its free acceleration turns it back
// into the limit, so it would only close again at once: it stays locked and
// the force test decides afterwards. Tried on a copy of the world, kept by
// the ladder so that its buffers are reused (grazing hinges ask at every
// impact); the solvers are reset, so nothing but capacity carries from call
// to call.
struct Ladder::ChatterTrial {
    World world;
    std::optional<Ladder> ladder;
    Dynamics dynamics;
};
template class Fresh<Ladder::ChatterTrial>;

bool Ladder::wouldChatter(const World& w, double t, int j, EventKind kind, const std::vector<Twist>& before) const {
    ChatterTrial& scratch = *chatterTrial_;
    World& trial = scratch.world;
    trial = w;
    if (scratch.ladder)
        *scratch.ladder = *this;
    else
        scratch.ladder.emplace(*this);
    Ladder& after = *scratch.ladder;
    Dynamics& d = scratch.dynamics;
    d.forgetStructure();
    after.release(trial, j, kind, t);
    trial.setPartVelocities(before);
    projectVelocities(trial, d);
    d.evaluate(trial, t);
    // Away from the limit: phi grows from 0 after an unlock, falls from pi
    // after an unfold or a flip (measured at the new corner).
    const double away = kind == EventKind::Unlock ? 1.0 : -1.0;
    const double speed = away * after.foldRate(trial, j);
    const double accel = away * after.foldAcceleration(trial, j);
    return speed < spec_.hinges.minReboundSpeed && accel < 0;
}

// A perfectly plastic impact at the hinges `hits` with every other
// constraint active: combine at the limit, then repeat the same impact while
// a contact impulse would pull (release it) or a free hinge would be driven
// through a limit (lock it too). Restitution turns the plastic result into
// a bounce while the rebound is faster than v_min.
std::vector<Event> Ladder::impact(World& w, Dynamics& d, double t, const std::vector<int>& hits, double* loss,
                                  double* heldWork, std::vector<int>* releasedNow) {
    std::vector<Event> events;
    const std::vector<Twist> before = w.partVelocities();
    const double keBefore = energy(w).kinetic;
    std::vector<double> approach(hits.size());
    // The shortest rebound this impact ends (0: none), which launches the
    // rebounds of the contacts it releases; and whether it ends one of a
    // shrinking sequence: then it is that sequence's accumulation point,
    // and the contacts held there stay closed through it. Any other impact
    // tests them as it tests every contact.
    double rebound = 0;
    bool accumulating = false;
    const auto closed = [&](int j) {
        accumulating = noteClose(j, t) || accumulating;
        const double r = hinge(j).lastRebound;
        if (r > 0 && (rebound == 0 || r < rebound)) rebound = r;
    };
    // Every approach speed before any hit merges its pair: a merge gives the
    // pair one velocity, which changes the rate of the hinge next to it.
    for (size_t i = 0; i < hits.size(); ++i) approach[i] = std::abs(foldRate(w, hits[i]));
    for (size_t i = 0; i < hits.size(); ++i) {
        const int j = hits[i];
        const bool folding = hinge(j).foldAngle > kPi / 2;
        if (bothHeld(w, j)) {
            // The pair would be one rigid body driven by two hands whose
            // motions need not agree, and its contact force is undetermined.
            if (error_.empty())
                error_ = "blocks " + std::to_string(j - 1) + " and " + std::to_string(j) +
                         " are both held and meet at hinge " + std::to_string(j) + " (t = " + std::to_string(t) +
                         " s): a lock between two hands is not modelled; let go of one of them first";
            return events;
        }
        if (folding)
            fold(w, j);
        else
            lock(w, j);
        closed(j);
        events.push_back({t, folding ? EventKind::Fold : EventKind::Lock, j, hinge(j).corner, {}});
    }
    Eigen::VectorXd impulses;
    const Impact im{&before, &impulses};
    // A hinge released in this impact stays free in it, even at its limit
    // (docs/model.md section 8.4): the next step decides whether it closes again.
    std::vector<int>& released = *releasedNow;
    std::vector<int> kept;  // the slow-release rule: stays locked through this impact
    bool settled = false;
    for (int guard = 0; guard < 4 * blockCount() + 4 && !settled; ++guard) {
        w.setPartVelocities(before);
        projectVelocities(w, d, &impulses);
        updateAngles(w);
        if (auto pull = pullingContact(w, d, &im, kept, accumulating)) {
            if (wouldChatter(w, t, pull->first, pull->second, before)) {
                kept.push_back(pull->first);
                continue;
            }
            release(w, pull->first, pull->second, t, rebound);
            released.push_back(pull->first);
            events.push_back({t, pull->second, pull->first, hinge(pull->first).corner, {}});
            continue;
        }
        bool driven = false;
        for (int j = 1; j < liveEnd() && !driven; ++j) {
            if (hinge(j).mode != HingeMode::Free || std::find(released.begin(), released.end(), j) != released.end())
                continue;
            for (bool folded : {false, true})
                if (!driven && touchingLimit(w, j, folded, false)) {
                    if (folded)
                        fold(w, j);
                    else
                        lock(w, j);
                    closed(j);
                    events.push_back({t, folded ? EventKind::Fold : EventKind::Lock, j, hinge(j).corner, {}});
                    driven = true;
                }
        }
        settled = !driven;
    }
    if (!settled) capped(t, "an impact's contacts");
    double dissipated = jumpEnergy(w, before);
    // Restitution: phi_dot+ = -e phi_dot- for the hinges that were hit.
    const double e = spec_.hinges.restitution;
    bool anyBounce = false;
    for (size_t i = 0; e > 0 && i < hits.size(); ++i) {
        const int j = hits[i];
        const HingeMode mode = hinge(j).mode;
        if ((mode != HingeMode::OpenLocked && mode != HingeMode::Folded) || hinge(j).held ||
            e * approach[i] <= spec_.hinges.minReboundSpeed)
            continue;
        release(w, j, mode == HingeMode::OpenLocked ? EventKind::Unlock : EventKind::Unfold, t, rebound);
        events.push_back({t, EventKind::Bounce, j, hinge(j).corner, {}});
        anyBounce = true;
    }
    // Releases restructure only: the parts keep their plastic velocities.
    if (anyBounce) dissipated = bounce(w, d, before, e);
    *loss += dissipated;
    *heldWork += energy(w).kinetic - keBefore + dissipated;
    return events;
}

std::vector<Event> Ladder::push(World& w, Dynamics& d, double t, int i, const Vec2& local, const Vec2& impulse) {
    const PartId p = block(i);
    const Part& part = w.part(p);
    // The velocities the impulse gives the block on its own: a block locked
    // to others (or to the hand) takes it through their contacts, which the
    // loop below tests as it tests an impact's.
    std::vector<Twist> before = w.partVelocities();
    const Vec2 arm = w.pointPosition(p, local) - w.partPose(p).position;
    before[size_t(p)].linear += impulse / part.mass;
    if (part.inertia > 0) before[size_t(p)].angular += cross(arm, impulse) / part.inertia;
    return takeUp(w, d, t, before, "a push's contacts");
}

std::vector<Event> Ladder::takeUp(World& w, Dynamics& d, double t, const std::vector<Twist>& before,
                                  const std::string& what) {
    std::vector<Event> events;
    Eigen::VectorXd impulses;
    const Impact im{&before, &impulses};
    std::vector<int> kept;
    bool settled = false;
    for (int guard = 0; guard < 4 * blockCount() + 4 && !settled; ++guard) {
        w.setPartVelocities(before);
        projectVelocities(w, d, &impulses);
        updateAngles(w);
        const auto pull = pullingContact(w, d, &im, kept);
        if ((settled = !pull)) break;
        if (wouldChatter(w, t, pull->first, pull->second, before)) {
            kept.push_back(pull->first);
            continue;
        }
        release(w, pull->first, pull->second, t);
        events.push_back({t, pull->second, pull->first, hinge(pull->first).corner, words(pull->second, pull->first)});
    }
    if (!settled) capped(t, what);
    return events;
}

// An active-set loop that ran out of passes: a bug or a case the rules do
// not settle, said in the run's diagnostics rather than left half done.
void Ladder::capped(double t, const std::string& what) {
    if (error_.empty()) error_ = what + " at t = " + std::to_string(t) + " s could not be settled";
}

std::vector<Event> Ladder::resolve(World& w, Dynamics& d, double t, double* loss, double* heldWork) {
    std::vector<Event> events;
    std::vector<int> released;  // in this pass: free even at a limit
    bool unsettled = true;
    for (int guard = 0; guard < 8 * blockCount() + 8; ++guard) {
        // A lock closes the pins at its limit (join), but a lock and an
        // unlock of the same hinge at one instant were seen to leave gaps
        // of 4e-10 m (heavy-middle.yaml at 1.81 s): the located instant is
        // read off the step's interpolant, whose state misses the pins by
        // its own error (1.1e-9 m there). Closed again here, so that every
        // event leaves the pins within tolerance (docs/model.md 14.3).
        if (!events.empty() && pinResidual(w) > gapTolerance_) {
            if (auto e = closePinGaps(w, "an event")) error_ = e->message;
            projectVelocities(w, d);
        }
        settled_ = d.evaluate(w, t);
        updateAngles(w);
        std::vector<int> hits;
        for (int j = 1; j < liveEnd(); ++j)
            if (hinge(j).mode == HingeMode::Free && std::find(released.begin(), released.end(), j) == released.end() &&
                (touchingLimit(w, j, false, true) || touchingLimit(w, j, true, true)))
                hits.push_back(j);
        if (!hits.empty()) {
            for (Event& e : impact(w, d, t, hits, loss, heldWork, &released)) events.push_back(std::move(e));
            continue;
        }
        if (auto pull = pullingContact(w, d, nullptr)) {
            released.push_back(pull->first);
            release(w, pull->first, pull->second, t);
            events.push_back({t, pull->second, pull->first, hinge(pull->first).corner, {}});
            continue;
        }
        unsettled = false;
        break;
    }
    // A settled pass ends on an evaluation of the state it leaves: another
    // would be a whole-ladder pass for nothing.
    if (unsettled) {
        capped(t, "the contacts (" + std::to_string(events.size()) + " events at one instant)");
        settled_ = d.evaluate(w, t);
        updateAngles(w);
    }
    for (Event& e : events) e.text = words(e.kind, e.hinge);
    return events;
}

// ---- what the views draw ----

std::vector<HingeFrame> Ladder::hingeFrames(const World& w) const {
    std::vector<HingeFrame> out(hinges_.size());
    for (int j = 1; j < blockCount(); ++j) {
        const Hinge& h = hinge(j);
        out[size_t(j - 1)] = {h.mode, h.corner, h.foldAngle, cornerWorld(w, j - 1, h.corner)};
    }
    return out;
}

}  // namespace jl
