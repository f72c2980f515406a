// Mechanical energy of the free (non-held) part of a world.
#pragma once

namespace jl {

class World;

struct Energy {
    double kinetic = 0;    // J
    double potential = 0;  // J, gravity (zero at y = 0 for g along -y) and springs
    double total() const { return kinetic + potential; }
};

Energy energy(const World& w);

}  // namespace jl
