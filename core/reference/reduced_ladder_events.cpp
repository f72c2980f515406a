// The reduced ladder's stepping and events: fixed-step RK4 that lands on
// every jump of the hand's acceleration, events located by bisection on
// re-run steps, and the rules of docs/model.md sections 8.2 to 8.6 (settling
// an instant, plastic impacts with an active set, the slow-release rule and held contacts).
#include "jl/reference/reduced_ladder.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace jl {

namespace {
constexpr double kPi = std::numbers::pi;
constexpr double kAngleTolerance = 1e-12;   // rad: the rounding of phi (section 9.2)
constexpr double kTouch = 1e-7;             // rad: this close to a limit touches it (section 9.2)
constexpr double kLocateTolerance = 1e-13;  // s: how closely an event is bracketed

bool contains(const std::vector<int>& list, int j) { return std::find(list.begin(), list.end(), j) != list.end(); }
}  // namespace

// Classic RK4; every stage takes the hand's piece that holds the step's
// midpoint (docs/model.md section 10). Entry 0 (the hand) is overwritten by
// the caller.
void ReducedLadder::rk4(double t, double h, Eigen::VectorXd& theta, Eigen::VectorXd& omega) const {
    const double within = t + h / 2;
    const Eigen::VectorXd a1 = accelerations(t, within, theta, omega);
    const Eigen::VectorXd t2 = theta + h / 2 * omega, w2 = omega + h / 2 * a1;
    const Eigen::VectorXd a2 = accelerations(t + h / 2, within, t2, w2);
    const Eigen::VectorXd t3 = theta + h / 2 * w2, w3 = omega + h / 2 * a2;
    const Eigen::VectorXd a3 = accelerations(t + h / 2, within, t3, w3);
    const Eigen::VectorXd t4 = theta + h * w3, w4 = omega + h * a3;
    const Eigen::VectorXd a4 = accelerations(t + h, within, t4, w4);
    theta += h / 6 * (omega + 2 * w2 + 2 * w3 + w4);
    omega += h / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
}

// A closed hinge holds its relative angle exactly: RK4 keeps linear
// invariants to rounding, and the hand's angle is given, so this only
// removes rounding (and RK4's error in following the hand).
void ReducedLadder::keepClosed(bool velocities) {
    theta_[0] = hand(t_, within_, 0);
    omega_[0] = hand(t_, within_, 1);
    for (int j = 1; j < n_; ++j) {
        if (hinges_[size_t(j)].mode == Mode::Free) continue;
        theta_[j] = theta_[j - 1] + hinges_[size_t(j)].offset;
        if (velocities) omega_[j] = omega_[j - 1];
    }
}

// The state a step of length h from (theta0, omega0) at t reaches, with its
// accelerations on the step's piece of the hand's path.
void ReducedLadder::moveTo(double t, double h, const Eigen::VectorXd& theta0, const Eigen::VectorXd& omega0) {
    theta_ = theta0;
    omega_ = omega0;
    rk4(t, h, theta_, omega_);
    t_ = t + h;
    within_ = t + h / 2;
    keepClosed(true);
    evaluate(t + h / 2);
}

// Section 9.1: two functions per hinge, >= 0 while its mode may stand.
std::vector<double> ReducedLadder::eventFunctions() const {
    std::vector<double> f;
    for (int j = 1; j < n_; ++j) {
        const Mode mode = hinges_[size_t(j)].mode;
        if (mode == Mode::Free) {
            const double phi = foldAngle(j);
            f.push_back(phi + kAngleTolerance);
            f.push_back(kPi - phi + kAngleTolerance);
            continue;
        }
        const Contact c = contactForce(j);
        const double tolerance = threshold(c, false);
        f.push_back((mode == Mode::Locked ? c.normal : c.nearEnd) + tolerance);
        f.push_back(mode == Mode::Locked ? 1.0 : c.farEnd + tolerance);
    }
    return f;
}

bool ReducedLadder::crossed(const std::vector<double>& start) const {
    const std::vector<double> now = eventFunctions();
    for (size_t i = 0; i < now.size(); ++i)
        if (start[i] >= 0 && now[i] < 0) return true;
    return false;
}

// The first instant in the step at which a function turns negative, by
// bisection, each trial a fresh RK4 step from the step's start: the state
// there is as accurate as at the step's end. Left just after it.
void ReducedLadder::locate(double h, const Eigen::VectorXd& theta0, const Eigen::VectorXd& omega0,
                           const std::vector<double>& start) {
    const double t0 = t_ - h;
    double lo = 0, hi = h;
    while (hi - lo > kLocateTolerance) {
        const double mid = (lo + hi) / 2;
        moveTo(t0, mid, theta0, omega0);
        (crossed(start) ? hi : lo) = mid;
    }
    moveTo(t0, hi, theta0, omega0);
}

bool ReducedLadder::advanceTo(double tEnd) {
    while (error_.empty() && t_ < tEnd) {
        double next = std::numeric_limits<double>::infinity();
        for (double b : breaks_)
            if (b > t_) next = std::min(next, b);
        const bool landing = next - t_ <= step_;
        const double h = landing ? next - t_ : step_;
        const std::vector<double> start = eventFunctions();
        const Eigen::VectorXd theta0 = theta_, omega0 = omega_;
        moveTo(t_, h, theta0, omega0);
        if (crossed(start)) {
            locate(h, theta0, omega0, start);
            if (!resolve()) return false;
        } else if (landing) {
            t_ = next;  // exactly: the instant belongs to the piece that starts there (section 10)
            if (!resolve()) return false;
        }
    }
    return error_.empty();
}

// A free hinge at a limit (within kTouch) that it moves into, or rests on
// with its acceleration into it; one deeper past the limit is hit anyway.
bool ReducedLadder::touching(int j, bool folded, bool resting) const {
    const double phi = foldAngle(j);
    const double gap = folded ? kPi - phi : phi;
    if (gap < -kTouch) return true;
    if (gap > kTouch) return false;
    const double sign = folded ? -1.0 : 1.0;
    const double rate = sign * foldRate(j, omega_);
    if (rate < -restingRate_) return true;
    return resting && rate <= restingRate_ && sign * foldRate(j, alpha_) < 0;
}

// Section 8.4 step 2 and 8.5 step 3: the most negative contact force (or
// impulse, against the velocities `before` the impact) and what releasing
// it means. A pair that could tip over both ends tips over the far one.
int ReducedLadder::pulling(bool impulse, const Motion& before, const std::vector<int>& keep, bool spareHeld,
                           ReducedEvent::Kind& kind) const {
    double most = std::numeric_limits<double>::infinity();
    int worst = 0;
    for (int j = 1; j < n_; ++j) {
        const Hinge& h = hinges_[size_t(j)];
        if (h.mode == Mode::Free || (spareHeld && h.held) || contains(keep, j)) continue;
        const Contact c = impulse ? contactImpulse(j, before) : contactForce(j);
        const double tolerance = threshold(c, impulse);
        if (h.mode == Mode::Locked && c.normal < -tolerance && c.normal < most) {
            most = c.normal;
            worst = j;
            kind = ReducedEvent::Kind::Unlock;
        }
        if (h.mode != Mode::Folded) continue;
        if (c.nearEnd < -tolerance && c.nearEnd < most) {
            most = c.nearEnd;
            worst = j;
            kind = ReducedEvent::Kind::FlipFlop;
        } else if (c.farEnd < -tolerance && c.farEnd < most && c.nearEnd >= -tolerance) {
            most = c.farEnd;
            worst = j;
            kind = ReducedEvent::Kind::Unfold;
        }
    }
    return worst;
}

// The slow-release rule (section 8.6): released from the velocities before the impact,
// would the pair part slower than v_min with its acceleration turning it
// back into the limit? Tried on a copy.
bool ReducedLadder::wouldChatter(int j, ReducedEvent::Kind kind, const Motion& before) const {
    ReducedLadder trial = *this;
    trial.release(j, kind, -1);
    trial.omega_ = trial.project(before);
    trial.evaluate(within_);
    const double away = kind == ReducedEvent::Kind::Unlock ? 1.0 : -1.0;
    return away * trial.foldRate(j, trial.omega_) < minReboundSpeed_ && away * trial.foldRate(j, trial.alpha_) < 0;
}

// LOCK or FOLD (section 8.2): snapped to the limit exactly by turning
// everything below the hinge about it (all of it, so that no other fold
// angle moves: turning block j alone would move hinge j + 1's angle by the
// snap, and could leave it a hair past a limit it then never crosses), the
// relative angle kept from then on.
void ReducedLadder::close(int j, bool folded) {
    Vec2 da, na;
    hingeFrame(j, da, na);
    const double snap = cross(da, na) * ((folded ? kPi : 0.0) - foldAngle(j));
    for (int i = j; i < n_; ++i) theta_[i] += snap;
    Hinge& h = hinges_[size_t(j)];
    h.mode = folded ? Mode::Folded : Mode::Locked;
    h.offset = theta_[j] - theta_[j - 1];
    place();
    events_.push_back({t_, folded ? ReducedEvent::Kind::Fold : ReducedEvent::Kind::Lock, j});
}

// UNLOCK, UNFOLD or FLIP-FLOP (the hinge moves to corner k ^ 1, where the
// far corners of the folded pair meet). No velocity changes.
void ReducedLadder::release(int j, ReducedEvent::Kind kind, double launchedBy) {
    Hinge& h = hinges_[size_t(j)];
    h.mode = Mode::Free;
    if (kind == ReducedEvent::Kind::FlipFlop) h.corner ^= 1;
    h.releasedAt = t_;
    h.launchedBy = launchedBy;
    h.held = false;
    place();
}

// Section 8.6, held contacts: a close that ends a rebound shorter than the
// Zeno time and than the rebound that launched it.
bool ReducedLadder::noteClose(int j) {
    Hinge& h = hinges_[size_t(j)];
    const double open = t_ - h.releasedAt;
    h.lastRebound = h.launchedBy >= 0 ? open : 0;
    h.held = h.launchedBy > 0 && open <= zenoTime_ && open < h.launchedBy;
    return h.held;
}

// Section 8.4: close the hinges hit, then repeat the plastic impact from the
// velocities before it while a contact impulse would pull (release it,
// unless the slow-release rule keeps it) or a free hinge is driven into a limit (close it).
void ReducedLadder::impact(const std::vector<int>& hits, std::vector<int>& released) {
    const Motion before = motion();
    double rebound = 0;  // the shortest rebound this impact ends: it launches what it releases
    bool accumulating = false;
    const auto closeNoted = [&](int j, bool folded) {
        close(j, folded);
        accumulating = noteClose(j) || accumulating;
        const double r = hinges_[size_t(j)].lastRebound;
        if (r > 0 && (rebound == 0 || r < rebound)) rebound = r;
    };
    for (int j : hits) closeNoted(j, foldAngle(j) > kPi / 2);
    std::vector<int> kept;
    for (int guard = 0; guard < 4 * n_ + 4; ++guard) {
        omega_ = project(before);
        ReducedEvent::Kind kind = ReducedEvent::Kind::Unlock;
        if (const int j = pulling(true, before, kept, accumulating, kind)) {
            if (wouldChatter(j, kind, before)) {
                kept.push_back(j);
                continue;
            }
            release(j, kind, rebound);
            released.push_back(j);
            events_.push_back({t_, kind, j});
            continue;
        }
        bool driven = false;
        for (int j = 1; j < n_ && !driven; ++j) {
            if (hinges_[size_t(j)].mode != Mode::Free || contains(released, j)) continue;
            for (bool folded : {false, true})
                if (!driven && touching(j, folded, false)) {
                    closeNoted(j, folded);
                    driven = true;
                }
        }
        if (!driven) return;
    }
    error_ = "an impact at t = " + std::to_string(t_) + " s could not be settled";
}

// Section 8.5: settle the instant t_. A hinge released here stays free for
// the rest of the instant.
bool ReducedLadder::resolve() {
    std::vector<int> released;
    for (int guard = 0; guard < 8 * n_ + 8 && error_.empty(); ++guard) {
        evaluate(t_);
        std::vector<int> hits;
        for (int j = 1; j < n_; ++j)
            if (hinges_[size_t(j)].mode == Mode::Free && !contains(released, j) &&
                (touching(j, false, true) || touching(j, true, true)))
                hits.push_back(j);
        if (!hits.empty()) {
            impact(hits, released);
            continue;
        }
        ReducedEvent::Kind kind = ReducedEvent::Kind::Unlock;
        if (const int j = pulling(false, motion(), {}, false, kind)) {
            released.push_back(j);
            release(j, kind, -1);
            events_.push_back({t_, kind, j});
            continue;
        }
        return true;
    }
    if (error_.empty()) error_ = "the instant t = " + std::to_string(t_) + " s could not be settled";
    return false;
}

}  // namespace jl
