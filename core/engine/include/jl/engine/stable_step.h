// The step an explicit integrator can take on the scene as it is now: the
// fastest vibration bounded from the pin forces, and each method's stability
// limit on an undamped oscillation (docs/model.md section 6.3).
#pragma once

#include "jl/base/integrator.h"
#include "jl/engine/world.h"

#include <Eigen/Core>

namespace jl {

// An upper bound on the angular frequency (rad/s) of the fastest small
// vibration: a body pulled by pin forces F_p at arms r_p from its centre
// rocks about it at most as fast as sqrt(sum |F_p| |r_p| / I). For a block
// hung between two diagonal corners under tension T this is 12 T / (m l),
// the rocking zigzag that is the fastest mode of a hanging ladder. Bodies
// without rotational inertia (particles) do not count; 0 if nothing pulls.
double fastestVibration(const World& w, const Eigen::VectorXd& pinForces);

// The same bound for the springs: a point mass or a body on springs of
// stiffness k vibrates at most at sqrt(sum k / m_eff) (a Gershgorin bound on
// the mass-scaled stiffness, with the rotational inertia at each spring's
// arm); 0 without springs. Springs and pins add: their squares bound the
// square of the whole.
double fastestSpringVibration(const World& w);

// The fastest any body turns, held ones included (rad/s). A step resolves a
// turn only in small pieces: a hand spinning the top block at 100 turns a
// second forces the ladder at that rate, stable step or not.
double fastestTurn(const World& w);

// The largest omega * dt for which the integrator does not amplify an
// undamped oscillation (on the imaginary axis of its stability region):
// 2 sqrt 2 for RK4, 2 for symplectic Euler, 0.9972 for Dormand-Prince 5(4)
// (its error control must do the rest). Explicit Euler amplifies every
// oscillation at any step; it is given symplectic Euler's limit, so that its
// growth per step stays bounded by sqrt(1 + 4).
double imaginaryStabilityLimit(Integrator integrator);

// The step the engine takes when the scene names none: at most `cap`, and
// at most `safety` of the stability limit for the fastest vibration (the
// safety leaves room for the tension to grow within a step, for instance
// while the hand turns the top block).
double automaticStep(Integrator integrator, double omega, double cap);

}  // namespace jl
