// The reduced ladder's model: the scene it covers, its hanging start, its
// kinematics in absolute block angles, the dense equations of motion with the
// closed hinges as rows of a KKT system, and the contact forces and impulses
// of docs/model.md section 8.3. The events are in reduced_ladder_events.cpp.
#include "jl/reference/reduced_ladder.h"

#include "jl/scene/ladder_blocks.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace jl {

namespace {
constexpr double kPi = std::numbers::pi;
}

const char* toString(ReducedEvent::Kind k) {
    switch (k) {
        case ReducedEvent::Kind::Lock:
            return "lock";
        case ReducedEvent::Kind::Unlock:
            return "unlock";
        case ReducedEvent::Kind::Fold:
            return "fold";
        case ReducedEvent::Kind::Unfold:
            return "unfold";
        case ReducedEvent::Kind::FlipFlop:
            return "flip";
    }
    return "?";
}

ReducedLadder::ReducedLadder(const Scene& scene, double step) : step_(step) {
    error_ = readScene(scene);
    if (!error_.empty()) return;
    hangInEquilibrium();
    evaluate(0);
    if (!resolve() && error_.empty()) error_ = "the start could not be settled";
}

// Only what this model covers; anything else is refused, not approximated.
std::string ReducedLadder::readScene(const Scene& scene) {
    if (!scene.ladder) return "no ladder";
    const LadderSpec& ladder = *scene.ladder;
    if (ladder.held != std::vector<int>{0}) return "only block 0 may be held";
    if (ladder.initial.kind != InitialState::Kind::Equilibrium) return "only the hanging start is covered";
    if (ladder.hinges.damping != 0 || ladder.hinges.restitution != 0)
        return "hinge damping and restitution not covered";
    if (scene.linearDamping != 0 || scene.angularDamping != 0) return "air damping not covered";
    if (!scene.bodies.empty() || !scene.particles.empty() || !scene.pins.empty() || !scene.springs.empty() ||
        !scene.drags.empty())
        return "only a ladder is covered";
    if (scene.solver.blockContact != BlockContact::Off) return "contact between blocks not covered";
    if (scene.floor) return "a floor not covered";
    for (const ScriptAction& a : scene.script) {
        if (a.kind != ScriptAction::Kind::Turn || a.block != 0) return "only turns of block 0 are covered";
        turns_.push_back({a.at, a.duration, a.angle});
        breaks_.push_back(a.at);
        breaks_.push_back(a.at + a.duration);
    }
    std::sort(breaks_.begin(), breaks_.end());
    n_ = ladder.blocks;
    if (n_ < 2) return "a ladder of at least two blocks";
    const std::vector<BlockSpec> blocks = ladderBlocks(ladder);
    length_ = ladder.block.length;
    double lightest = std::numeric_limits<double>::infinity();
    for (const BlockSpec& b : blocks) {
        const double m = massOf(b);
        mass_.push_back(m);
        thickness_.push_back(b.thickness);
        inertia_.push_back(m * (length_ * length_ + b.thickness * b.thickness) / 12);
        lightest = std::min(lightest, m);
    }
    gravity_ = Vec2(scene.gravity[0], scene.gravity[1]);
    // The scales of section 8.3 and the Zeno time of section 8.6.
    const double g = gravity_.norm() > 0 ? gravity_.norm() : 1.0, tau = std::sqrt(length_ / g);
    forceTolerance_ = 1e-8 * lightest * g;
    impulseTolerance_ = 5e-8 * lightest * g * tau;
    restingRate_ = 1e-10 / tau;
    zenoTime_ = 0.0125 * tau;
    minReboundSpeed_ = ladder.hinges.minReboundSpeed;
    return {};
}

// Section 2.3: bit 0 of k the end, bit 1 the side; odd blocks point down.
Vec2 ReducedLadder::cornerLocal(int i, int k) const {
    const double along = (i % 2 == 0 ? 1.0 : -1.0) * ((k & 1) ? 1.0 : -1.0) * length_ / 2;
    return {(k & 2) ? thickness_[size_t(i)] / 2 : -thickness_[size_t(i)] / 2, along};
}

// Section 2.5: each block turned so that its own centre of mass and the
// blocks below, a point mass at its lower hinge, hang straight below its
// upper hinge. Hinge j starts at corner 0 (j odd) or 3 (j even).
void ReducedLadder::hangInEquilibrium() {
    hinges_.assign(size_t(n_), Hinge{});
    for (int j = 1; j < n_; ++j) hinges_[size_t(j)].corner = j % 2 == 1 ? 0 : 3;
    theta_ = Eigen::VectorXd::Zero(n_);
    omega_ = Eigen::VectorXd::Zero(n_);
    const double down = std::atan2(gravity_.y(), gravity_.x());
    for (int i = 1; i < n_; ++i) {
        double below = 0;
        for (int l = i + 1; l < n_; ++l) below += mass_[size_t(l)];
        const Vec2 upper = cornerLocal(i, hinges_[size_t(i)].corner);
        Vec2 u = -mass_[size_t(i)] * upper;
        if (i + 1 < n_) u += below * (cornerLocal(i, hinges_[size_t(i + 1)].corner) - upper);
        theta_[i] = down - std::atan2(u.y(), u.x());
    }
}

// The hand turns block 0 about its centre (at the origin) along the smooth
// profile of section 10. The angle and rate are continuous; the
// acceleration is that of the piece holding `within`.
double ReducedLadder::hand(double t, double within, int order) const {
    double value = 0;
    for (const Turn& turn : turns_) {
        const double s = std::clamp((t - turn.at) / turn.duration, 0.0, 1.0), w = kPi / turn.duration;
        if (order == 0) value += turn.angle * (1 - std::cos(kPi * s)) / 2;
        if (order == 1) value += turn.angle * w / 2 * std::sin(kPi * s);
        if (order == 2 && within >= turn.at && within < turn.at + turn.duration)
            value += turn.angle * w * w / 2 * std::cos(kPi * (t - turn.at) / turn.duration);
    }
    return value;
}

// Centre i is sum over l <= i of R(theta_l) w_il, with w_il in block l's
// frame: from its upper hinge (none for block 0, held at its centre) to its
// lower hinge (l < i) or to its centre (l = i). arm[i n + l] = R(theta_l) w_il,
// so d centre_i / d theta_l = perp(arm[i n + l]).
void ReducedLadder::arms(const Eigen::VectorXd& theta, std::vector<Vec2>& arm) const {
    arm.assign(size_t(n_ * n_), Vec2::Zero());
    for (int l = 0; l < n_; ++l) {
        const Vec2 upper = l >= 1 ? cornerLocal(l, hinges_[size_t(l)].corner) : Vec2::Zero();
        const Vec2 toCentre = rotate(theta[l], -upper);
        const Vec2 toLower =
            l + 1 < n_ ? rotate(theta[l], cornerLocal(l, hinges_[size_t(l + 1)].corner) - upper) : Vec2::Zero();
        arm[size_t(l * n_ + l)] = toCentre;
        for (int i = l + 1; i < n_; ++i) arm[size_t(i * n_ + l)] = toLower;
    }
}

// Lagrange's equations in the angles of blocks 1..n-1 (the hand's angle is
// given): M alpha = f, with M_lk = sum_(i >= l, k) m_i arm_il . arm_ik + I_l
// delta_lk and f_l = sum_(i >= l) perp(arm_il) . m_i (g - the acceleration
// of centre i from the hand and the velocities), then the closed hinges.
Eigen::VectorXd ReducedLadder::accelerations(double t, double within, const Eigen::VectorXd& theta,
                                             const Eigen::VectorXd& omega) const {
    Eigen::VectorXd th = theta, om = omega;
    th[0] = hand(t, within, 0);
    om[0] = hand(t, within, 1);
    const double handAcceleration = hand(t, within, 2);
    std::vector<Vec2> arm;
    arms(th, arm);
    const int f = n_ - 1;
    Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(f, f);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(f);
    for (int i = 1; i < n_; ++i) {
        Vec2 known = perp(arm[size_t(i * n_)]) * handAcceleration;
        for (int l = 0; l <= i; ++l) known -= arm[size_t(i * n_ + l)] * om[l] * om[l];
        const Vec2 load = mass_[size_t(i)] * (gravity_ - known);
        for (int l = 1; l <= i; ++l) {
            rhs[l - 1] += perp(arm[size_t(i * n_ + l)]).dot(load);
            for (int k = 1; k <= i; ++k)
                mass(l - 1, k - 1) += mass_[size_t(i)] * arm[size_t(i * n_ + l)].dot(arm[size_t(i * n_ + k)]);
        }
    }
    for (int l = 1; l < n_; ++l) mass(l - 1, l - 1) += inertia_[size_t(l)];
    return solveClosed(mass, rhs, handAcceleration);
}

// Solves M x = rhs + G^T mu with the rows G x = gamma of the closed hinges:
// x_1 = the hand's value for hinge 1, x_j = x_(j-1) for hinge j > 1. The
// same system gives the accelerations and the plastic impact (rhs = M v-).
// Returns every block's value, the hand's first.
Eigen::VectorXd ReducedLadder::solveClosed(const Eigen::MatrixXd& mass, const Eigen::VectorXd& rhs,
                                           double handValue) const {
    const int f = n_ - 1;
    std::vector<int> closed;
    for (int j = 1; j < n_; ++j)
        if (hinges_[size_t(j)].mode != Mode::Free) closed.push_back(j);
    const int c = int(closed.size());
    Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(f + c, f + c);
    Eigen::VectorXd b(f + c);
    kkt.topLeftCorner(f, f) = mass;
    b.head(f) = rhs;
    for (int r = 0; r < c; ++r) {
        const int j = closed[size_t(r)];
        kkt(f + r, j - 1) = kkt(j - 1, f + r) = 1;
        if (j >= 2) kkt(f + r, j - 2) = kkt(j - 2, f + r) = -1;
        b[f + r] = j == 1 ? handValue : 0.0;
    }
    const Eigen::VectorXd x = kkt.partialPivLu().solve(b);
    Eigen::VectorXd out(n_);
    out[0] = handValue;
    out.tail(f) = x.head(f);
    return out;
}

// The centres' velocities and the blocks' rates as they stand.
ReducedLadder::Motion ReducedLadder::motion() const {
    Motion m{std::vector<Vec2>(size_t(n_), Vec2::Zero()), omega_};
    for (int i = 0; i < n_; ++i)
        for (int l = 0; l <= i; ++l) m.velocity[size_t(i)] += perp(arm_[size_t(i * n_ + l)]) * omega_[l];
    return m;
}

// Section 8.4: the plastic impact, the motion nearest to `before` in the
// kinetic-energy metric that meets every pin and closed hinge as they now
// stand (the hand's rate given). Its normal equations: M omega = the
// momentum of `before` along each free angle, sum_(i >= l) m_i (v_i minus
// the hand's part of it) . perp(arm_il) + I_l rate_l.
Eigen::VectorXd ReducedLadder::project(const Motion& before) const {
    const int f = n_ - 1;
    const double handRate = hand(t_, within_, 1);
    Eigen::MatrixXd mass = Eigen::MatrixXd::Zero(f, f);
    Eigen::VectorXd momentum = Eigen::VectorXd::Zero(f);
    for (int i = 1; i < n_; ++i) {
        const Vec2 own = before.velocity[size_t(i)] - perp(arm_[size_t(i * n_)]) * handRate;
        for (int l = 1; l <= i; ++l) {
            momentum[l - 1] += mass_[size_t(i)] * own.dot(perp(arm_[size_t(i * n_ + l)]));
            for (int k = 1; k <= i; ++k)
                mass(l - 1, k - 1) += mass_[size_t(i)] * arm_[size_t(i * n_ + l)].dot(arm_[size_t(i * n_ + k)]);
        }
    }
    for (int l = 1; l < n_; ++l) {
        mass(l - 1, l - 1) += inertia_[size_t(l)];
        momentum[l - 1] += inertia_[size_t(l)] * before.rate[l];
    }
    return solveClosed(mass, momentum, handRate);
}

// The state's places and accelerations, the hand's piece being the one that
// holds `within`.
void ReducedLadder::evaluate(double within) {
    within_ = within;
    theta_[0] = hand(t_, within, 0);
    omega_[0] = hand(t_, within, 1);
    place();
    alpha_ = accelerations(t_, within, theta_, omega_);
}

// The arms and centres of the angles and hinge corners as they stand.
void ReducedLadder::place() {
    arms(theta_, arm_);
    centres_.assign(size_t(n_), Vec2::Zero());
    for (int i = 0; i < n_; ++i)
        for (int l = 0; l <= i; ++l) centres_[size_t(i)] += arm_[size_t(i * n_ + l)];
}

Vec2 ReducedLadder::hingePoint(int j) const {
    return centres_[size_t(j)] + rotate(theta_[j], cornerLocal(j, hinges_[size_t(j)].corner));
}

// Section 7.1: d_a along block j-1 away from the hinge corner k, n_a across
// it into it.
void ReducedLadder::hingeFrame(int j, Vec2& da, Vec2& na) const {
    const int k = hinges_[size_t(j)].corner;
    da = rotate(theta_[j - 1], cornerLocal(j - 1, k ^ 1) - cornerLocal(j - 1, k)).normalized();
    na = rotate(theta_[j - 1], cornerLocal(j - 1, k ^ 2) - cornerLocal(j - 1, k)).normalized();
}

// phi = atan2(-n_a . d_b, -d_a . d_b), read in [-pi/2, 3 pi/2): the
// admissible [0, pi] with room on both sides, so no tracking is needed.
double ReducedLadder::foldAngleOf(int j, const Eigen::VectorXd& theta) const {
    const int k = hinges_[size_t(j)].corner;
    const Vec2 da = rotate(theta[j - 1], cornerLocal(j - 1, k ^ 1) - cornerLocal(j - 1, k)).normalized();
    const Vec2 na = rotate(theta[j - 1], cornerLocal(j - 1, k ^ 2) - cornerLocal(j - 1, k)).normalized();
    const Vec2 db = rotate(theta[j], cornerLocal(j, k ^ 1) - cornerLocal(j, k)).normalized();
    double phi = std::atan2(-na.dot(db), -da.dot(db));
    if (phi < -kPi / 2) phi += 2 * kPi;
    return phi;
}

double ReducedLadder::foldAngle(int j) const { return foldAngleOf(j, theta_); }

// Section 7.2: dphi/dt = sigma (omega_b - omega_a), sigma = d_a x n_a.
double ReducedLadder::foldRate(int j, const Eigen::VectorXd& rate) const {
    Vec2 da, na;
    hingeFrame(j, da, na);
    return cross(da, na) * (rate[j] - rate[j - 1]);
}

// What the side above hinge j exerts on blocks j.. below it, as a force and
// its moment about the hinge point, from each block's rate of change of
// momentum (`momentum`: m (a - g) for forces, m dv at an impact) and of
// spin (I alpha, or I domega). Blocks j.. are all that hangs from hinge j,
// so nothing else acts on them. Split as section 8.3 says.
ReducedLadder::Contact ReducedLadder::wrenchSplit(int j, const std::vector<Vec2>& momentum,
                                                  const Eigen::VectorXd& spin) const {
    const Vec2 p = hingePoint(j);
    Vec2 force = Vec2::Zero();
    double moment = 0;
    for (int i = j; i < n_; ++i) {
        force += momentum[size_t(i)];
        moment += inertia_[size_t(i)] * spin[i] + cross(centres_[size_t(i)] - p, momentum[size_t(i)]);
    }
    return split(j, force, moment);
}

// Section 8.3: N = sigma M / t for an open-locked pair; for a folded one
// N_far = -M / lever and N_near = (M - L (d_a x F)) / lever, lever = L sigma.
ReducedLadder::Contact ReducedLadder::split(int j, const Vec2& force, double moment) const {
    Vec2 da, na;
    hingeFrame(j, da, na);
    const double sigma = cross(da, na);
    Contact c;
    if (hinges_[size_t(j)].mode == Mode::Locked) {
        const double t = std::min(thickness_[size_t(j - 1)], thickness_[size_t(j)]);
        c.normal = sigma * moment / t;
        c.load = force.norm() + std::abs(c.normal);
    } else {
        const double lever = length_ * sigma;
        c.farEnd = -moment / lever;
        c.nearEnd = (moment - length_ * cross(da, force)) / lever;
        c.load = force.norm() + std::abs(c.nearEnd) + std::abs(c.farEnd);
    }
    return c;
}

// Section 8.3, "How small counts as zero": the ladder's threshold, or the
// same fraction of the contact's load where that is larger.
double ReducedLadder::threshold(const Contact& c, bool impulse) const {
    return impulse ? std::max(impulseTolerance_, 5e-8 * c.load) : std::max(forceTolerance_, 1e-8 * c.load);
}

ReducedLadder::Contact ReducedLadder::contactForce(int j) const {
    std::vector<Vec2> momentum(size_t(n_), Vec2::Zero());
    for (int i = j; i < n_; ++i) {
        Vec2 a = Vec2::Zero();
        for (int l = 0; l <= i; ++l) {
            const Vec2& arm = arm_[size_t(i * n_ + l)];
            a += perp(arm) * alpha_[l] - arm * omega_[l] * omega_[l];
        }
        momentum[size_t(i)] = mass_[size_t(i)] * (a - gravity_);
    }
    return wrenchSplit(j, momentum, alpha_);
}

// The impulse of the impact that took the blocks from `before` to now.
ReducedLadder::Contact ReducedLadder::contactImpulse(int j, const Motion& before) const {
    const Motion now = motion();
    std::vector<Vec2> momentum(size_t(n_), Vec2::Zero());
    for (int i = j; i < n_; ++i)
        momentum[size_t(i)] = mass_[size_t(i)] * (now.velocity[size_t(i)] - before.velocity[size_t(i)]);
    return wrenchSplit(j, momentum, now.rate - before.rate);
}

// Kinetic and potential energy of the blocks the hand does not hold.
double ReducedLadder::energy() const {
    double e = 0;
    for (int i = 1; i < n_; ++i) {
        Vec2 v = Vec2::Zero();
        for (int l = 0; l <= i; ++l) v += perp(arm_[size_t(i * n_ + l)]) * omega_[l];
        e += 0.5 * mass_[size_t(i)] * v.squaredNorm() + 0.5 * inertia_[size_t(i)] * omega_[i] * omega_[i] -
             mass_[size_t(i)] * gravity_.dot(centres_[size_t(i)]);
    }
    return e;
}

}  // namespace jl
