// Mechanical energy of everything but the held blocks and the ground.
#pragma once

#include "jl/base/geometry.h"

#include <vector>

namespace jl {

class World;

struct Energy {
    double kinetic = 0;    // J
    double potential = 0;  // J, gravity (zero at the origin's height) and springs
    double total() const { return kinetic + potential; }
};

Energy energy(const World& w);

// Kinetic energy relative to the held body when exactly one body is held,
// else the plain kinetic energy: in that frame a plastic impact never
// creates energy (docs/model.md section 12.3), so impacts book their loss by it.
double heldFrameKinetic(const World& w);

// The energy of the jump from the part velocities `before` to the world's,
// in the mass metric (held parts left out): what a plastic impact
// dissipates, whatever is held.
double jumpEnergy(const World& w, const std::vector<Twist>& before);

// Newton's law of restitution on a jump: from the velocities `before` an
// impact and the plastic ones `plastic` after it, the velocities of a
// bounce, v + (1 + e)(v_plastic - v). It keeps e^2 of the plastic jump's
// energy (docs/model.md section 12.3).
std::vector<Twist> bounced(const std::vector<Twist>& before, const std::vector<Twist>& plastic, double e);

}  // namespace jl
