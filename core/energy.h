// Mechanical energy of everything but the held blocks and the ground.
#pragma once

namespace jl {

class World;

struct Energy {
    double kinetic = 0;    // J
    double potential = 0;  // J, gravity (zero at the origin's height) and springs
    double total() const { return kinetic + potential; }
};

Energy energy(const World& w);

}  // namespace jl
