// The engine's time integrators, by name: the stepper runs them, the scene
// names one, the stability bounds know each one's limit. All are explicit
// but RosenbrockW, which is linearly implicit in the ladder's stiff part
// (docs/model.md section 6.4). A word the scene and the engine share, kept
// in base so that reading a scene does not link the engine.
#pragma once

namespace jl {

enum class Integrator { ExplicitEuler, SymplecticEuler, RK4, DormandPrince45, RosenbrockW, Verner65 };

// Methods that choose their own step from a local error tolerance.
constexpr bool isAdaptive(Integrator i) {
    return i == Integrator::DormandPrince45 || i == Integrator::Verner65 || i == Integrator::RosenbrockW;
}

}  // namespace jl
