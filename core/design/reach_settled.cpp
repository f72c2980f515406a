#include "jl/design/reach_settled.h"

#include "jl/engine/energy.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace jl {

const char* rippleEndWord(RippleEnd e) {
    switch (e) {
        case RippleEnd::Bottom:
            return "bottom";
        case RippleEnd::Order:
            return "order";
        case RippleEnd::Energy:
            return "energy";
        case RippleEnd::RunEnd:
            break;
    }
    return "end";
}

namespace {

// The integrator keeps the energy books to 1e-5 of the run's energy scale
// (docs/model.md section 12.4), so a run's energy may rise a little where
// the model's only falls: a cell stops only with this share of the barrier
// to spare. On the 400 designs of docs/ripple-reach.md ("What a map
// costs"), run whole, the energy after the instant it first fell below a
// barrier rose above its value then by at most 1.1e-6 of that barrier.
// The Euler methods drift by O(h) and get no energy stop at all.
constexpr double kSpare = 1e-3;

bool handAlone(const Scene& s) {
    const LadderSpec& l = *s.ladder;
    if (l.held != std::vector<int>{0} || !s.bodies.empty() || !s.particles.empty() || !s.pins.empty() ||
        !s.springs.empty() || !s.drags.empty())
        return false;
    for (const ScriptAction& a : s.script)
        if ((a.kind != ScriptAction::Kind::Turn && a.kind != ScriptAction::Kind::Move) || a.block != 0) return false;
    return true;
}

// Only losses: no negative damping, restitution below 1, an integrator
// that keeps the books, and no table (its contacts are not part of the
// argument checked here). Contact between blocks is: frictionless, a
// resting contact does no work (the two corners move alike along its
// normal, and the held block is still once the hand stops), and its
// impacts are plastic or take the hinges' restitution, so they only take
// energy; run whole with it on, the 400 designs of docs/ripple-reach.md
// ("When a cell stops") rose by at most 1.7e-5 of a barrier they had
// fallen below.
bool onlyLosses(const Scene& s) {
    const HingeOptions& h = s.ladder->hinges;
    const Integrator i = s.solver.integrator;
    return !s.floor && h.damping >= 0 && h.restitution >= 0 && h.restitution < 1 && s.linearDamping >= 0 &&
           s.angularDamping >= 0 && i != Integrator::ExplicitEuler && i != Integrator::SymplecticEuler;
}

Vec2 up(const Simulation& sim) { return -sim.world().gravity.normalized(); }

// The lowest height (along up) of a box of half sizes (across, along)
// placed as block 0 is now.
double lowestOfBox(const Simulation& sim, double across, double along) {
    const Pose p = sim.world().partPose(sim.blockPart(0));
    double lowest = std::numeric_limits<double>::infinity();
    for (const double x : {-across, across})
        for (const double y : {-along, along}) lowest = std::min(lowest, up(sim).dot(p.apply(Vec2(x, y))));
    return lowest;
}

}  // namespace

ReachBarrier::ReachBarrier(const Scene& scene, const Simulation& sim) {
    const Ladder* ladder = sim.ladder();
    if (!scene.ladder || !ladder || sim.world().gravity.norm() <= 0) return;
    applies_ = handAlone(scene) && onlyLosses(scene);
    for (const ScriptAction& a : scene.script) handStops_ = std::max(handStops_, a.at + std::max(0.0, a.duration));
    const int n = ladder->blockCount();
    length_ = ladder->length();
    for (int i = 0; i < n; ++i) {
        // Corners 0 and 3 are diagonally opposite, 0 and 2 across the thickness.
        diagonal_.push_back((ladder->cornerLocal(i, 3) - ladder->cornerLocal(i, 0)).norm());
        thickness_.push_back((ladder->cornerLocal(i, 2) - ladder->cornerLocal(i, 0)).norm());
    }
    massBelow_.assign(size_t(n) + 1, 0.0);
    for (int i = n - 1; i >= 1; --i)
        massBelow_[size_t(i - 1)] = massBelow_[size_t(i)] + sim.world().part(sim.blockPart(i)).mass;
}

// The chain's lowest: hinge 1 is a corner of block 0, so no lower than its
// lowest corner a; hinge k + 1 is a corner of block k, so at most its
// diagonal D_k below hinge k; block k's centre is the middle of a box, at
// most D_k / 2 below any of its corners (hinge k among them). So block k's
// centre is at least a - D_1 - ... - D_(k-1) - D_k / 2 high, as in the
// hanging equilibrium with every diagonal vertical (docs/model.md 2.5).
double ReachBarrier::lowestPotential(const Simulation& sim) const {
    const int n = int(diagonal_.size());
    double hinge = lowestOfBox(sim, thickness_[0] / 2, length_ / 2), v = 0;
    for (int k = 1; k < n; ++k) {
        v += sim.world().part(sim.blockPart(k)).mass * (hinge - diagonal_[size_t(k)] / 2);
        hinge -= diagonal_[size_t(k)];
    }
    return sim.world().gravity.norm() * v;
}

// Folded, hinge j lays blocks j-1 and j face to face: one box L long and
// T_(j-1) + T_j thick. Hinges j-1 and j+1 are corners of it, at most
// S = sqrt(L^2 + (T_(j-1) + T_j)^2) apart, where the chain above allowed
// D_(j-1) + D_j: hinge j+1, and with it every block below, is at least
// D_(j-1) + D_j - S higher than the lowest (for equal blocks
// 2 sqrt(L^2 + T^2) - sqrt(L^2 + 4 T^2): 60.0 mm at L = 60, T = 1 mm, 56.6 mm
// at 15 mm). Hinge 1 has no hinge 0: folded, block 1 lies beside block 0
// (held), inside the box of block 0 widened by T_1 on each side, so hinge 2
// is no lower than that box's lowest corner instead of D_1 below block 0's.
double ReachBarrier::lift(const Simulation& sim, int j) const {
    const double l = length_;
    if (j >= 2) {
        const double ta = thickness_[size_t(j - 1)], tb = thickness_[size_t(j)];
        return diagonal_[size_t(j - 1)] + diagonal_[size_t(j)] - std::hypot(l, ta + tb);
    }
    const double t0 = thickness_[0], t1 = thickness_[1];
    return lowestOfBox(sim, t0 / 2 + t1, l / 2) - (lowestOfBox(sim, t0 / 2, l / 2) - diagonal_[1]);
}

// Block j itself, folded onto block j-1, has its centre (T_(j-1) + T_j) / 2
// across from block j-1's: at most sqrt(L^2 / 4 + (T_(j-1) + T_j / 2)^2)
// from hinge j-1 (a corner of block j-1), where the chain allowed
// D_(j-1) + D_j / 2 (for equal blocks 1.5 sqrt(L^2 + T^2) -
// sqrt(L^2 / 4 + 2.25 T^2): 60.0 mm at 1 mm, 55.3 mm at 15 mm). Beside
// block 0 (hinge 1) its centre is on block 0's cross line, (T_0 + T_1) / 2
// to either side of block 0's centre, instead of D_1 / 2 below block 0's
// lowest corner.
double ReachBarrier::ownLift(const Simulation& sim, int j) const {
    const double l = length_, tb = thickness_[size_t(j)];
    if (j >= 2) {
        const double ta = thickness_[size_t(j - 1)];
        return diagonal_[size_t(j - 1)] + diagonal_[size_t(j)] / 2 - std::hypot(l / 2, ta + tb / 2);
    }
    const double t0 = thickness_[0];
    return lowestOfBox(sim, (t0 + tb) / 2, 0) - (lowestOfBox(sim, t0 / 2, l / 2) - diagonal_[1] / 2);
}

double ReachBarrier::barrier(const Simulation& sim, int j) const {
    const double own = sim.world().part(sim.blockPart(j)).mass;
    return sim.world().gravity.norm() * (lift(sim, j) * massBelow_[size_t(j)] + ownLift(sim, j) * own);
}

bool ReachBarrier::cannotFold(const Simulation& sim, int j) {
    if (!applies_ || sim.time() < handStops_ || j < 1 || j >= int(diagonal_.size())) return false;
    // Block 0 stays where the hand left it: its lowest once is its lowest.
    if (!lowestKnown_) {
        lowest_ = lowestPotential(sim);
        lowestKnown_ = true;
    }
    return energy(sim.world()).total() - lowest_ < (1 - kSpare) * barrier(sim, j);
}

}  // namespace jl
