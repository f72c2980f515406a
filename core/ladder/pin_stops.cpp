// Stops on the pins of a general scene: their event functions, and their
// impacts and releases settled as one active set (docs/model.md section 18).
#include "jl/ladder/pin_stops.h"

#include "jl/engine/energy.h"
#include "jl/engine/projection.h"

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

std::string degrees(double rad) {
    char text[32];
    std::snprintf(text, sizeof text, "%+.4g°", rad * 180 / std::numbers::pi);
    return text;
}

}  // namespace

PinStops::PinStops(World& w, std::vector<PinStop> stops) : stops_(std::move(stops)) {
    closed_.assign(stops_.size(), 0);
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
}

double PinStops::angle(const World& w, int i) const {
    return w.partPose(stop(i).b).angle - w.partPose(stop(i).a).angle;
}

double PinStops::rate(const World& w, int i) const {
    return w.partVelocity(stop(i).b).angular - w.partVelocity(stop(i).a).angular;
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

// The moment of the weld and pin between a and b on b, about the pin:
// the weld's multiplier times its arm is a moment on the world's body A,
// the pin's force acts on A at its point (World's Weld).
double PinStops::push(const World& w, const Eigen::VectorXd& multipliers, int i) const {
    const PinStop& s = stop(i);
    const int bodyA = w.part(s.a).body, bodyB = w.part(s.b).body;
    const std::vector<Pin>& pins = w.pins();
    const std::vector<Weld>& welds = w.welds();
    const Vec2 pivot = w.pointPosition(s.a, s.pivotA);
    for (size_t k = 0; k < welds.size(); ++k) {
        const Pin& pin = pins[size_t(welds[k].pin)];
        if (!((pin.bodyA == bodyA && pin.bodyB == bodyB) || (pin.bodyA == bodyB && pin.bodyB == bodyA))) continue;
        const Eigen::Index row = 2 * Eigen::Index(pins.size()) + Eigen::Index(k);
        if (row >= multipliers.size()) return 0;
        const Vec2 l = multipliers.segment<2>(2 * Eigen::Index(welds[k].pin));
        const Vec2 x = w.bodyPose(pin.bodyA).apply(pin.localA);
        const double onA = welds[k].arm * multipliers[row] + cross(x - pivot, l);
        const double onB = pin.bodyA == bodyB ? onA : -onA;
        return closed_[size_t(i)] < 0 ? onB : -onB;
    }
    return 0;  // no weld between them (both held): nothing to test
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
        const double phi = angle(w, i);
        const PinStop& s = stop(i);
        out[size_t(i)] = std::min(s.min ? phi - *s.min : 1.0, s.max ? *s.max - phi : 1.0);
    }
    return forces;
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
    const double alpha = w.a[3 * w.part(s.b).body + 2] - w.a[3 * w.part(s.a).body + 2];
    return resting && into <= restingRate_ && (side < 0 ? alpha : -alpha) < 0;
}

void PinStops::close(World& w, int i, int side) {
    const std::array<ParticleId, 2>& pair = pairs_[size_t(i)][side < 0 ? 0 : 1];
    if (auto e = w.combine(pair[0], pair[1]); e && error_.empty()) error_ = e->message;
    closed_[size_t(i)] = side;
}

void PinStops::open(World& w, int i) {
    const std::array<ParticleId, 2>& pair = pairs_[size_t(i)][closed_[size_t(i)] < 0 ? 0 : 1];
    if (auto e = w.separate(pair[0]); e && error_.empty()) error_ = e->message;
    closed_[size_t(i)] = 0;
}

// The closed stop whose contact pulls hardest, beyond the tolerance.
std::optional<int> PinStops::pulling(const World& w, const Eigen::VectorXd& multipliers, bool impulse) const {
    std::optional<int> worst;
    double least = -(impulse ? impulseTolerance_ : forceTolerance_);
    for (int i = 0; i < count(); ++i) {
        if (closed_[size_t(i)] == 0) continue;
        const double p = push(w, multipliers, i);
        if (p < least) least = p, worst = i;
    }
    return worst;
}

Event PinStops::event(double t, int i, bool closing) const {
    const PinStop& s = stop(i);
    const int side = closing ? closed_[size_t(i)] : 0;
    const std::string limit = side < 0 ? degrees(*s.min) : side > 0 ? degrees(*s.max) : "";
    return {t, closing ? EventKind::Touch : EventKind::Part, -1, -1,
            closing ? "'" + s.nameB + "' strikes its stop on '" + s.nameA + "' at " + limit
                    : "'" + s.nameB + "' leaves its stop on '" + s.nameA + "'"};
}

// A perfectly plastic impact at the stops `hits` (stop, side) with every
// other constraint active: the stops welded at their limits, then the same
// impact repeated while a stop's impulse would pull (it opens) or a free
// stop would be driven through its limit (it closes too).
std::vector<Event> PinStops::impact(World& w, Dynamics& d, double t, const std::vector<std::pair<int, int>>& hits,
                                    double* loss, double* heldWork, std::vector<int>& released) {
    std::vector<Event> events;
    const std::vector<Twist> before = w.partVelocities();
    const double keBefore = energy(w).kinetic;
    for (const auto& [i, side] : hits) {
        if (w.body(w.part(stop(i).a).body).kinematic && w.body(w.part(stop(i).b).body).kinematic) {
            if (error_.empty())
                error_ = "'" + stop(i).nameA + "' and '" + stop(i).nameB +
                         "' are both held and reach a stop: a stop between two hands is not modelled";
            return events;
        }
        close(w, i, side);
        events.push_back(event(t, i, true));
    }
    if (auto e = closePinGaps(w, "a stop's impact"); e && error_.empty()) error_ = e->message;
    Eigen::VectorXd impulses;
    bool settled = false;
    for (int guard = 0; guard < 4 * count() + 4 && !settled; ++guard) {
        w.setPartVelocities(before);
        projectVelocities(w, d, &impulses);
        if (auto pull = pulling(w, impulses, true)) {
            open(w, *pull);
            released.push_back(*pull);
            events.push_back(event(t, *pull, false));
            continue;
        }
        settled = true;
        for (int i = 0; i < count() && settled; ++i) {
            if (closed_[size_t(i)] != 0 || std::find(released.begin(), released.end(), i) != released.end()) continue;
            for (int side : {-1, 1})
                if (settled && touching(w, i, side, false)) {
                    close(w, i, side);
                    events.push_back(event(t, i, true));
                    settled = false;
                }
        }
        if (!settled)
            if (auto e = closePinGaps(w, "a stop's impact"); e && error_.empty()) error_ = e->message;
    }
    if (!settled && error_.empty()) error_ = "a stops' impact at t = " + std::to_string(t) + " s could not be settled";
    const double dissipated = jumpEnergy(w, before);
    *loss += dissipated;
    *heldWork += energy(w).kinetic - keBefore + dissipated;
    return events;
}

std::vector<Event> PinStops::settle(World& w, Dynamics& d, double t, double* impactLoss, double* heldWork) {
    std::vector<Event> events;
    std::vector<int> released;  // in this pass: free even at a limit
    bool unsettled = true;
    for (int guard = 0; guard < 8 * count() + 8 && error_.empty(); ++guard) {
        settled_ = d.evaluate(w, t);
        std::vector<std::pair<int, int>> hits;
        for (int i = 0; i < count(); ++i)
            if (closed_[size_t(i)] == 0 && std::find(released.begin(), released.end(), i) == released.end())
                for (int side : {-1, 1})
                    if (touching(w, i, side, true)) {
                        hits.emplace_back(i, side);
                        break;
                    }
        if (!hits.empty()) {
            for (Event& e : impact(w, d, t, hits, impactLoss, heldWork, released)) events.push_back(std::move(e));
            continue;
        }
        if (auto pull = pulling(w, d.pinForces(), false)) {
            open(w, *pull);
            released.push_back(*pull);
            events.push_back(event(t, *pull, false));
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
    return events;
}

}  // namespace jl
