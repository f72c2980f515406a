// When the first ripple's reach can no longer change, so that its run may
// stop (docs/ripple-reach.md, "When a cell stops"). The ripple has reached
// hinge r; hinge r + 1 has not flipped. After the hand has stopped, the
// ladder's mechanical energy E = K + V only falls (no work comes in; hinge
// and air damping and impacts with restitution below 1 only take it). A
// flip of hinge j needs a fold of it, and folded it holds block j at least
// ownLift_j and every block below hinge j + 1 at least lift_j above the
// lowest the chain allows: E >= V0 + barrier_j, with barrier_j =
// |g| (ownLift_j m_j + lift_j (mass below hinge j + 1)). So once
// E - V0 < barrier_j, hinge j never folds again: the reach is settled.
// Applies only to scenes where that argument holds (see applies()).
#pragma once

#include "jl/scene/scene.h"

#include <string>
#include <vector>

namespace jl {

class Simulation;

// Why a run of the first ripple ended.
enum class RippleEnd {
    RunEnd,  // it ran for its whole time (rippleRunTime, or the first look's)
    Bottom,  // every hinge flipped in order: nothing further to reach
    Order,   // hinge r + 1 flipped before hinge r: nothing later mends the order
    Energy,  // too little energy left for hinge r + 1 to fold
};

// The word the map's CSV writes for it: "end", "bottom", "order", "energy".
const char* rippleEndWord(RippleEnd e);

class ReachBarrier {
public:
    // From the scene and its simulation as built (block masses and corners).
    ReachBarrier(const Scene& scene, const Simulation& sim);

    // Whether the energy argument holds for this scene: a ladder held by
    // block 0 alone, moved only by Turn and Move actions of block 0 (no
    // drags, pushes, cuts, joins or releases), nothing but the ladder (no
    // bodies, particles, pins or springs), no table, gravity not zero,
    // damping not negative, restitution below 1 (contact between blocks
    // only takes energy too).
    bool applies() const { return applies_; }
    // s: the end of the hand's last motion; from then on E only falls.
    double handStops() const { return handStops_; }
    // Whether hinge j (1..N-1), not folded now, can never fold from now on,
    // by the energy of `sim` now; false before the hand stops or when the
    // argument does not apply.
    bool cannotFold(const Simulation& sim, int j);

    // m: how much higher than the lowest the chain allows a fold of hinge
    // j holds the blocks below hinge j + 1, and block j's centre (block 0
    // as it is now held).
    double lift(const Simulation& sim, int j) const;
    double ownLift(const Simulation& sim, int j) const;
    // J: the least energy above lowestPotential that a fold of hinge j needs.
    double barrier(const Simulation& sim, int j) const;
    // J: the least potential energy the ladder can have with block 0 as held
    // now, the hanging equilibrium's when hinge 1 sits at block 0's lowest corner.
    double lowestPotential(const Simulation& sim) const;

private:
    bool applies_ = false;
    double handStops_ = 0;
    std::vector<double> diagonal_;   // m, each block's corner to opposite corner
    std::vector<double> thickness_;  // m
    std::vector<double> massBelow_;  // kg, [j]: blocks j+1..N-1 (below hinge j + 1)
    double length_ = 0;              // m, every block's
    double lowest_ = 0;              // J, lowestPotential once the hand has stopped
    bool lowestKnown_ = false;
};

}  // namespace jl
