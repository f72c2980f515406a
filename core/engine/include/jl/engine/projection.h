// Removes drift: mass-weighted projection of positions (Newton-Raphson with
// line backtracking, the paper's solver) and of velocities onto the pins.
#pragma once

#include "jl/engine/pin_solver.h"

#include <Eigen/Core>

namespace jl {

class World;

struct ProjectionResult {
    bool converged = true;
    int iterations = 0;
    double residual = 0;  // m, largest pin gap after the projection
};

// Largest distance between the two sides of any pin, or by which a weld's
// second shared point is off (m).
double pinResidual(const World& w);
// Largest relative velocity across any pin (m/s).
double pinVelocityResidual(const World& w, PinSolver& solver);

// Moves dynamic bodies the least (in the mass metric) so every pin closes.
// The world's resting contacts are closed too, unless `contacts` is false:
// a change of structure closes its pins to rounding, and leaves the
// contacts (closed by every step's projection) as they are.
ProjectionResult projectPositions(World& w, PinSolver& solver, double tolerance, int maxIterations = 25,
                                  bool contacts = true);

// The plastic impulse: v+ = v- + W J^T P with J v+ = 0. Held bodies have
// infinite mass. If `impulses` is given it receives P (2 per pin, on body A, then one
// per weld).
// The world's resting contacts (World::contacts) are held too: at an
// impact `PushOnly`, each pushing only as much as keeps its gap from
// closing (a contact that would have to pull is left to part); after a
// step `Hold`, each kept at zero rate like a pin, since a resting contact
// opens only where its force crosses zero (docs/model.md section 17.3).
enum class ContactRule { PushOnly, Hold };
void projectVelocities(World& w, PinSolver& solver, Eigen::VectorXd* impulses = nullptr,
                       ContactRule contacts = ContactRule::PushOnly);

// A bounce after a plastic impact, the world at its plastic velocities
// (restructured as the bounce leaves it): Newton's law from the part
// velocities `before` the impact, v +
// (1 + e)(v_plastic - v), then projected onto the constraints that stay
// closed (a hinge too slow to rebound, one the impact locked): that is a
// second, plastic jump. Returns what the whole impact dissipates, (1 - e^2)
// of the plastic jump's energy and all of the second's (docs/model.md
// section 12.3).
double bounce(World& w, PinSolver& solver, const std::vector<Twist>& before, double e);

// Both, after a change of structure (combine, separate, hold), with the
// caller's solver: reset first, so nothing but its capacity carries over.
ProjectionResult makeConsistent(World& w, PinSolver& solver, double tolerance, bool contacts = true);

}  // namespace jl
