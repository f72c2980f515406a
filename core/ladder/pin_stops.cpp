// Stops on the pins of a general scene: their event functions, and their
// impacts and releases settled as one active set (docs/model.md section 18).
#include "jl/ladder/pin_stops.h"

#include "jl/base/heap_bytes.h"
#include "jl/engine/energy.h"
#include "jl/engine/projection.h"
#include "jl/ladder/quintic_dip.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

namespace jl {

namespace {

// This close to a limit (either side: a located instant leaves the angle a
// hair past it) a stop touches it, as a ladder hinge does (Ladder::kTouchBand).
constexpr double kTouch = 1e-7;  // rad

// A free stop's event is where its angle passes its limit by this, measured
// from where a release left it (Ladder::kAngleTolerance).
constexpr double kAngleTolerance = 1e-12;  // rad

// Slower than this a released stop would part too slowly to be a rebound
// (the slow-release rule; the ladder's default hinges.min_rebound_speed).
constexpr double kMinReboundSpeed = 1e-4;  // rad/s

std::string degrees(double rad) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.4g°", rad * 180 / std::numbers::pi);
    return text;
}

// rad: how far stop i's angle is inside its range from the nearer limit
// (negative past it); 1 with no limit.
double nearerGap(const PinStops& stops, const World& w, int i) {
    const double phi = stops.angle(w, i);
    const PinStop& s = stops.stop(i);
    return std::min(s.min ? phi - *s.min : 1.0, s.max ? *s.max - phi : 1.0);
}

}  // namespace

PinStops::PinStops(World& w, std::vector<PinStop> stops) : stops_(std::move(stops)) {
    closed_.assign(stops_.size(), 0);
    contacts_.resize(stops_.size());
    welds_.assign(stops_.size(), -1);
    pairs_.resize(stops_.size());
    double lightest = std::numeric_limits<double>::infinity(), arm = std::numeric_limits<double>::infinity();
    for (size_t i = 0; i < stops_.size(); ++i) {
        const PinStop& s = stops_[i];
        // A point of a at a lever from the pin, and the point of b that
        // lies on it when theta_b - theta_a is the limit: the two coincide
        // only there, so combining them welds the pair at exactly that angle.
        const double lever = std::max(w.part(s.a).halfSize.maxCoeff(), 1e-3);
        const Vec2 u(lever, 0);
        for (int side = 0; side < 2; ++side) {
            const std::optional<double>& limit = side == 0 ? s.min : s.max;
            if (!limit) continue;
            pairs_[i][size_t(side)] = {w.addParticle(s.a, s.pivotA + u),
                                       w.addParticle(s.b, s.pivotB + rotate(-*limit, u))};
        }
        lightest = std::min({lightest, w.part(s.a).mass, w.part(s.b).mass});
        arm = std::min(arm, lever);
    }
    // The scales of the contact tests, as the ladder's (docs/model.md
    // section 8.3): 1e-8 of the lightest body's weight at the shortest lever.
    const double g = w.gravity.norm() > 0 ? w.gravity.norm() : 1.0;
    if (stops_.empty()) return;
    const double timeScale = std::sqrt(arm / g);
    forceTolerance_ = 1e-8 * lightest * g * arm;
    impulseTolerance_ = 5e-8 * lightest * g * arm * timeScale;
    restingRate_ = 1e-10 / timeScale;
    // The ladder's Zeno time, 0.0125 sqrt(L / g) (docs/model.md section
    // 8.6), with the shortest lever's body length for L.
    zenoTime_ = 0.0125 * std::sqrt(2 * arm / g);
}

double PinStops::angle(const World& w, int i) const {
    return w.partPose(stop(i).b).angle - w.partPose(stop(i).a).angle;
}

double PinStops::rate(const World& w, int i) const {
    return w.partVelocity(stop(i).b).angular - w.partVelocity(stop(i).a).angular;
}

double PinStops::acceleration(const World& w, int i) const {
    return w.a[3 * w.part(stop(i).b).body + 2] - w.a[3 * w.part(stop(i).a).body + 2];
}

bool PinStops::anyClosed() const {
    return std::any_of(closed_.begin(), closed_.end(), [](int c) { return c != 0; });
}

std::optional<std::string> PinStops::outsideAtStart(const World& w) const {
    for (int i = 0; i < count(); ++i) {
        const double phi = angle(w, i);
        const PinStop& s = stop(i);
        if ((s.min && phi < *s.min - kTouch) || (s.max && phi > *s.max + kTouch))
            return "the pin between '" + s.nameA + "' and '" + s.nameB + "' starts at " + degrees(phi) +
                   ", outside its stops (" + (s.min ? degrees(*s.min) : "none") + " to " +
                   (s.max ? degrees(*s.max) : "none") + ")";
    }
    return std::nullopt;
}

// The weld between stop i's two bodies: the one found last time while it
// still joins them (a change of structure renumbers the welds), else
// searched for. -1 when there is none (both held: nothing to test).
int PinStops::weldOf(const World& w, int i) const {
    const int bodyA = w.part(stop(i).a).body, bodyB = w.part(stop(i).b).body;
    const std::vector<Pin>& pins = w.pins();
    const std::vector<Weld>& welds = w.welds();
    const auto joins = [&](int k) {
        const Pin& pin = pins[size_t(welds[size_t(k)].pin)];
        return (pin.bodyA == bodyA && pin.bodyB == bodyB) || (pin.bodyA == bodyB && pin.bodyB == bodyA);
    };
    int& found = welds_[size_t(i)];
    if (found >= 0 && found < int(welds.size()) && joins(found)) return found;
    found = -1;
    for (int k = 0; k < int(welds.size()) && found < 0; ++k)
        if (joins(k)) found = k;
    return found;
}

// The moment of the weld and pin between a and b on b, about the pin:
// the weld's multiplier times its arm is a moment on the world's body A,
// the pin's force acts on A at its point (World's Weld).
double PinStops::push(const World& w, const Eigen::VectorXd& multipliers, int i) const {
    const int k = weldOf(w, i);
    if (k < 0) return 0;
    const std::vector<Pin>& pins = w.pins();
    const Weld& weld = w.welds()[size_t(k)];
    const Pin& pin = pins[size_t(weld.pin)];
    const Eigen::Index row = 2 * Eigen::Index(pins.size()) + Eigen::Index(k);
    if (row >= multipliers.size()) return 0;
    const Vec2 pivot = w.pointPosition(stop(i).a, stop(i).pivotA);
    const Vec2 l = multipliers.segment<2>(2 * Eigen::Index(weld.pin));
    const Vec2 x = w.bodyPose(pin.bodyA).apply(pin.localA);
    const double onA = weld.arm * multipliers[row] + cross(x - pivot, l);
    const double onB = pin.bodyA == w.part(stop(i).b).body ? onA : -onA;
    return closed_[size_t(i)] < 0 ? onB : -onB;
}

double PinStops::eventFunctions(const World& w, const Dynamics& d, std::vector<double>& out) const {
    out.resize(stops_.size());
    double forces = 1.0;
    for (int i = 0; i < count(); ++i) {
        if (closed_[size_t(i)] != 0) {
            out[size_t(i)] = push(w, d.pinForces(), i) + forceTolerance_;
            forces = std::min(forces, out[size_t(i)]);
            continue;
        }
        out[size_t(i)] = nearerGap(*this, w, i) - (contacts_[size_t(i)].releaseGap - kAngleTolerance);
    }
    return forces;
}

void PinStops::track(const World& w) {
    for (int i = 0; i < count(); ++i) {
        if (closed_[size_t(i)] == 0 && nearerGap(*this, w, i) > kTouch) contacts_[size_t(i)].releaseGap = 0;
    }
}

// A free stop at its limit `side` (-1 least, +1 greatest) that it is moving
// into, or resting on with its acceleration pushing into it; deeper past
// the limit, whatever its motion. One just released sits at the limit
// moving away: not hit.
bool PinStops::touching(const World& w, int i, int side, bool resting) const {
    const PinStop& s = stop(i);
    const std::optional<double>& limit = side < 0 ? s.min : s.max;
    if (!limit) return false;
    const double gap = side < 0 ? angle(w, i) - *limit : *limit - angle(w, i);
    if (gap < -kTouch) return true;
    if (gap > kTouch) return false;
    const double into = side < 0 ? rate(w, i) : -rate(w, i);  // < 0 closing
    if (into < -restingRate_) return true;
    const double alpha = acceleration(w, i);
    return resting && into <= restingRate_ && (side < 0 ? alpha : -alpha) < 0;
}

void PinStops::close(World& w, int i, int side, double t) {
    const std::array<ParticleId, 2>& pair = pairs_[size_t(i)][side < 0 ? 0 : 1];
    if (auto e = w.combine(pair[0], pair[1]); e && error_.empty()) error_ = e->message;
    closed_[size_t(i)] = side;
    if (std::isnan(contacts_[size_t(i)].firstClosing)) contacts_[size_t(i)].firstClosing = t;
}

void PinStops::open(World& w, int i) {
    const std::array<ParticleId, 2>& pair = pairs_[size_t(i)][closed_[size_t(i)] < 0 ? 0 : 1];
    if (auto e = w.separate(pair[0]); e && error_.empty()) error_ = e->message;
    closed_[size_t(i)] = 0;
}

// Opened at t; `launchedBy` as Contact says (by default its own force or
// a push, which starts no rebound).
void PinStops::release(World& w, int i, double t, double launchedBy) {
    const int side = closed_[size_t(i)];
    open(w, i);
    Contact& c = contacts_[size_t(i)];
    // The parted bodies were projected onto their pins: the angle may read
    // a hair past the limit it leaves. That is its zero until it moves clear.
    const double phi = angle(w, i);
    c.releaseGap = std::min(0.0, side < 0 ? phi - *stop(i).min : *stop(i).max - phi);
    c.releasedAt = t;
    c.launchedBy = launchedBy;
    c.held = false;
}

// Closed at t, as Ladder::noteClose: the end of a rebound within the Zeno
// time and shorter than the rebound that launched it holds the contact.
bool PinStops::noteClose(int i, double t) {
    Contact& c = contacts_[size_t(i)];
    const double open = t - c.releasedAt;
    c.lastRebound = c.launchedBy >= 0 ? open : 0;
    c.held = c.launchedBy > 0 && open <= zenoTime_ && open < c.launchedBy;
    return c.held;
}

// The slow-release rule (docs/model.md section 8.6), as
// Ladder::wouldChatter: released in this impact, stop i would part slower
// than v_min while its acceleration turns it back into its limit, so it
// would only close again at once. Tried on a copy of the world.
bool PinStops::wouldChatter(const World& w, double t, int i, const std::vector<Twist>& before) const {
    World trial = w;
    Dynamics d;
    const int side = closed_[size_t(i)];
    trial.separate(pairs_[size_t(i)][side < 0 ? 0 : 1][0]);
    trial.setPartVelocities(before);
    projectVelocities(trial, d);
    d.evaluate(trial, t);
    const double away = side < 0 ? 1.0 : -1.0;
    const double speed = away * rate(trial, i);
    const double accel = away * acceleration(trial, i);
    return speed < kMinReboundSpeed && accel < 0;
}

void PinStops::say(std::vector<Said>& said, double t, int i, EventKind kind, bool atSpeed) {
    said.push_back({event(t, i, kind), i, atSpeed});
}

// What instant t did to each stop, in words (`trials`, said by `say`, with
// the stops closed before it): the active set's trials, a stop closed,
// released and closed again within the instant, are not events. A stop
// free before and after that was struck moving strikes and lets go (or
// bounces); one that only touched its limit at rest, and one closed before
// and after, have nothing to say.
std::vector<Event> PinStops::net(const std::vector<Said>& trials, const std::vector<int>& closedBefore) const {
    std::vector<Event> said;
    std::vector<bool> done(stops_.size(), false);
    for (size_t k = 0; k < trials.size(); ++k) {
        const int i = trials[k].stop;
        if (done[size_t(i)]) continue;
        done[size_t(i)] = true;
        const bool before = closedBefore[size_t(i)] != 0, after = closed_[size_t(i)] != 0;
        if (before && after) continue;
        std::optional<Event> strike, last;
        for (size_t m = k; m < trials.size(); ++m)
            if (trials[m].stop == i) {
                const bool struck = trials[m].event.kind == EventKind::Touch && (trials[m].atSpeed || after);
                if (!strike && struck) strike = trials[m].event;
                last = trials[m].event;
            }
        if (before) {
            said.push_back(event(last->time, i, EventKind::Part));
            continue;
        }
        if (!strike) continue;
        said.push_back(*strike);
        if (!after && last->kind != EventKind::Touch) said.push_back(*last);
    }
    return said;
}

Event PinStops::event(double t, int i, EventKind kind) const {
    const PinStop& s = stop(i);
    const std::string on = " its stop on '" + s.nameA + "'";
    if (kind == EventKind::Touch) {
        const int side = closed_[size_t(i)];
        return {t, kind, -1, -1, "'" + s.nameB + "' strikes" + on + " at " + degrees(side < 0 ? *s.min : *s.max)};
    }
    return {t, kind, -1, -1, "'" + s.nameB + (kind == EventKind::Bounce ? "' bounces off" : "' leaves") + on};
}

// Restitution at the stops struck (`hits`, with their rates of approach):
// each still closed, not held and with e times its approach above v_min
// bounces, released with a rebound starting. Returns the e for Newton's law
// over the whole impact (0: none bounces): the least of the stops that
// bounce, since one law serves every contact of an impact (docs/model.md
// section 18).
double PinStops::bounceAt(World& w, double t, const std::vector<std::pair<int, int>>& hits,
                          const std::vector<double>& approach, double rebound, std::vector<Said>& events) {
    double e = 0;
    for (size_t k = 0; k < hits.size(); ++k) {
        const int i = hits[k].first;
        const double ei = stop(i).restitution;
        if (closed_[size_t(i)] == 0 || contacts_[size_t(i)].held || ei * approach[k] <= kMinReboundSpeed) continue;
        release(w, i, t, rebound);
        say(events, t, i, EventKind::Bounce);
        e = e == 0 ? ei : std::min(e, ei);
    }
    return e;
}

// A perfectly plastic impact at the stops `hits` (stop, side) with every
// other constraint active: the stops welded at their limits, then the same
// impact repeated while a stop's impulse would pull (it opens) or a free
// stop would be driven through its limit (it closes too). As the ladder's
// (Ladder::impact): a release that would only close again at once is not
// made, and an impact that ends a shrinking sequence of rebounds leaves the
// contacts held in it closed. Restitution then turns the plastic result
// into a bounce (projection.h's bounce) at the stops struck.
std::vector<PinStops::Said> PinStops::impact(World& w, Dynamics& d, double t,
                                             const std::vector<std::pair<int, int>>& hits, double* loss,
                                             double* heldWork) {
    std::vector<Said> events;
    const std::vector<Twist> before = w.partVelocities();
    const double keBefore = energy(w).kinetic;
    // Every approach before any stop closes: a weld changes the rates next to it.
    std::vector<double> approach;
    for (const auto& hit : hits) approach.push_back(std::abs(rate(w, hit.first)));
    // The shortest rebound this impact ends (0: none), which launches the
    // rebounds of the stops it releases; and whether some stop became held.
    double rebound = 0;
    bool accumulating = false;
    const auto closing = [&](int i, int side, bool atSpeed) {
        close(w, i, side, t);
        accumulating = noteClose(i, t) || accumulating;
        const double r = contacts_[size_t(i)].lastRebound;
        if (r > 0 && (rebound == 0 || r < rebound)) rebound = r;
        say(events, t, i, EventKind::Touch, atSpeed);
    };
    for (size_t k = 0; k < hits.size(); ++k) {
        const auto [i, side] = hits[k];
        if (w.body(w.part(stop(i).a).body).kinematic && w.body(w.part(stop(i).b).body).kinematic) {
            if (error_.empty())
                error_ = "'" + stop(i).nameA + "' and '" + stop(i).nameB +
                         "' are both held and reach a stop: a stop between two hands is not modelled";
            return events;
        }
        closing(i, side, approach[k] > restingRate_);
    }
    if (auto e = closePinGaps(w, "a stop's impact"); e && error_.empty()) error_ = e->message;
    Eigen::VectorXd impulses;
    std::vector<int> kept;  // the slow-release rule: closed through this impact
    // The plastic impact is the least-energy projection of the velocities
    // onto the stops' one-sided constraints: an active set, found by
    // releasing the closed stop whose impulse pulls hardest, else closing
    // the free stop driven into its limit fastest, one at a time, until
    // neither is left. A stop released may close again, else the impact
    // could leave it moving into its limit, to be struck again at once.
    // Should that cycle (on rounding), the second half of the passes keeps
    // released stops free, as the ladder's rule for an instant does.
    const int passes = 10 * count() + 10;
    std::vector<int> released;
    bool settled = false;
    for (int pass = 0; pass < passes && !settled; ++pass) {
        w.setPartVelocities(before);
        projectVelocities(w, d, &impulses);
        std::optional<int> pull, driven;
        double most = -impulseTolerance_, fastest = 0;
        int drivenSide = 0;
        for (int i = 0; i < count(); ++i) {
            if (closed_[size_t(i)] != 0) {
                const bool spared =
                    (accumulating && contacts_[size_t(i)].held) || std::find(kept.begin(), kept.end(), i) != kept.end();
                if (const double p = spared ? 0 : push(w, impulses, i); p < most) most = p, pull = i;
                continue;
            }
            if (pass >= passes / 2 && std::find(released.begin(), released.end(), i) != released.end()) continue;
            for (int side : {-1, 1})
                if (touching(w, i, side, false)) {
                    const double into = side < 0 ? rate(w, i) : -rate(w, i);
                    if (!driven || into < fastest) driven = i, fastest = into, drivenSide = side;
                }
        }
        if (pull) {
            if (wouldChatter(w, t, *pull, before)) {
                kept.push_back(*pull);
                continue;
            }
            release(w, *pull, t, rebound);
            released.push_back(*pull);
            say(events, t, *pull, EventKind::Part);
        } else if (driven) {
            closing(*driven, drivenSide, true);
            if (auto e = closePinGaps(w, "a stop's impact"); e && error_.empty()) error_ = e->message;
        } else {
            settled = true;
        }
    }
    if (!settled && error_.empty()) error_ = "a stops' impact at t = " + std::to_string(t) + " s could not be settled";
    double dissipated = jumpEnergy(w, before);
    if (const double e = bounceAt(w, t, hits, approach, rebound, events); e > 0) dissipated = bounce(w, d, before, e);
    *loss += dissipated;
    *heldWork += energy(w).kinetic - keBefore + dissipated;
    return events;
}

// The events of instant t: impacts first, at every free stop moving into its
// limit (or past it); then, at rest, as in the impact: the closed stop
// whose moment pulls hardest opens, else the free stop resting on its
// limit with its acceleration into it fastest closes (an impact at no
// speed). Until nothing changes; should that cycle (on rounding), the
// second half of the passes keeps the stops released here free.
std::vector<Event> PinStops::settle(World& w, Dynamics& d, double t, double* impactLoss, double* heldWork) {
    std::vector<Said> events;
    const std::vector<int> closedBefore = closed_;
    std::vector<int> released;
    const int passes = 10 * count() + 10;
    bool unsettled = true;
    for (int pass = 0; pass < passes && error_.empty(); ++pass) {
        settled_ = d.evaluate(w, t);
        std::vector<std::pair<int, int>> hits;
        std::optional<int> pull;
        std::optional<std::pair<int, int>> resting;
        double most = -forceTolerance_, fastest = 0;
        for (int i = 0; i < count(); ++i) {
            if (closed_[size_t(i)] != 0) {
                if (const double p = push(w, d.pinForces(), i); p < most) most = p, pull = i;
                continue;
            }
            const bool keepFree =
                pass >= passes / 2 && std::find(released.begin(), released.end(), i) != released.end();
            for (int side : {-1, 1}) {
                if (touching(w, i, side, false)) {
                    hits.emplace_back(i, side);
                    break;
                }
                const double alpha = acceleration(w, i) * (side < 0 ? 1 : -1);
                if (!keepFree && touching(w, i, side, true) && alpha < fastest) fastest = alpha, resting = {i, side};
            }
        }
        if (!hits.empty() || (!pull && resting)) {
            if (hits.empty()) hits.push_back(*resting);
            for (Said& e : impact(w, d, t, hits, impactLoss, heldWork)) events.push_back(std::move(e));
            continue;
        }
        if (pull) {
            release(w, *pull, t, -1);
            released.push_back(*pull);
            say(events, t, *pull, EventKind::Part);
            continue;
        }
        unsettled = false;
        break;
    }
    if (unsettled) {
        if (error_.empty())
            error_ = "the stops (" + std::to_string(events.size()) + " events at t = " + std::to_string(t) +
                     " s) could not be settled";
        settled_ = d.evaluate(w, t);
    }
    // A free stop the instant leaves a hair past its limit (within the
    // touching band: moving away, or resting with its acceleration away)
    // measures its limits from there, as one just released does; else its
    // function would start the next step negative, that step's event could
    // not be located, and the step would be taken whole, the stops it
    // crossed settled late and deep.
    for (int i = 0; i < count(); ++i) {
        if (closed_[size_t(i)] != 0) continue;
        if (const double g = nearerGap(*this, w, i); g < 0)
            contacts_[size_t(i)].releaseGap = std::min(contacts_[size_t(i)].releaseGap, g);
    }
    return net(events, closedBefore);
}

// As Ladder::limitDip, for each free stop and each of its limits that the
// angle turns back from within the step. The start's angle, rate and
// acceleration are read from (q0, v0, a0) by the bodies' rows: no change
// of structure happens inside a step.
double PinStops::limitDip(const World& w, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0,
                          const Eigen::VectorXd& a0, double h) const {
    double first = 0;
    for (int i = 0; i < count(); ++i) {
        if (closed_[size_t(i)] != 0) continue;
        const Eigen::Index rowA = 3 * w.part(stop(i).a).body + 2, rowB = 3 * w.part(stop(i).b).body + 2;
        const double phi1 = angle(w, i), rate1 = rate(w, i), accel1 = w.a[rowB] - w.a[rowA];
        const double phi0 = phi1 - (w.q[rowB] - w.q[rowA]) + (q0[rowB] - q0[rowA]);
        const double rate0 = v0[rowB] - v0[rowA], accel0 = a0[rowB] - a0[rowA];
        for (int side : {-1, 1}) {
            const std::optional<double>& limit = side < 0 ? stop(i).min : stop(i).max;
            // The gap to this limit, its rate and acceleration: it must turn
            // back from the limit inside the step for a dip to hide there.
            const double sign = side < 0 ? 1.0 : -1.0;
            if (!limit || !(sign * rate0 < 0 && sign * rate1 > 0)) continue;
            const double zero = contacts_[size_t(i)].releaseGap - kAngleTolerance;
            const double gap0 = sign * (phi0 - *limit) - zero, gap1 = sign * (phi1 - *limit) - zero;
            if (gap0 <= 0 || gap1 <= 0) continue;  // a crossing at an end: located
            const auto [s, value] = quinticLowest(gap0, sign * rate0 * h, sign * accel0 * h * h, gap1, sign * rate1 * h,
                                                  sign * accel1 * h * h);
            if (value < 0 && (first == 0 || s * h < first)) first = s * h;
        }
    }
    return first;
}

std::size_t PinStops::heapBytes() const {
    using jl::heapBytes;
    return heapBytes(stops_) + heapBytes(closed_) + heapBytes(contacts_) + heapBytes(welds_) + heapBytes(pairs_);
}

}  // namespace jl
