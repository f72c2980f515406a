// One step of constrained motion: integrate, then project out the drift.
#pragma once

#include "jl/engine/projection.h"
#include "jl/engine/stepper.h"

namespace jl {

struct MotionStep {
    StepOutcome step;
    ProjectionResult projection;
    bool ok() const { return step.finite && projection.converged; }
};

// On failure (NaN, or a projection that does not converge) the world is left
// exactly as it was before the step. `atStart`: as for Stepper::advance.
MotionStep advanceAndProject(World& w, Dynamics& d, Stepper& s, double t, double h, Ledger& ledger, double tolerance,
                             bool exact = false, const Powers* atStart = nullptr);

}  // namespace jl
