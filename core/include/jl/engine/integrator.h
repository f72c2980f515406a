// The engine's time integrators, by name: the stepper runs them, the scene
// names one, the stability bounds know each one's limit.
#pragma once

namespace jl {

enum class Integrator { ExplicitEuler, SymplecticEuler, RK4, DormandPrince45 };

}  // namespace jl
