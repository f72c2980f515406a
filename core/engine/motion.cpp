#include "jl/engine/motion.h"

#include "jl/engine/world.h"

namespace jl {

MotionStep advanceAndProject(World& w, Dynamics& d, Stepper& s, double t, double h, Ledger& ledger, double tolerance,
                             bool exact, const Powers* atStart) {
    MotionStep m;
    const Ledger l0 = ledger;
    m.step = s.advance(w, d, t, h, ledger, exact, atStart, tolerance);
    if (!m.step.finite) return m;
    // Dormand-Prince has projected its end already (its last stage).
    const bool projected = m.step.endEvaluated || !m.step.projection.converged;
    m.projection = projected ? m.step.projection : projectPositions(w, d, tolerance);
    if (m.projection.converged) {
        // A projected end was checked by the stepper, after its projection.
        if (projected) return m;
        projectVelocities(w, d, nullptr, ContactRule::Hold);
        if (w.q.allFinite() && w.v.allFinite()) return m;
        m.step.finite = false;
        m.step.endEvaluated = false;
    }
    // The stepper still holds the state it started from (no copy per step).
    w.q = s.startPositions();
    w.v = s.startVelocities();
    ledger = l0;
    w.updateKinematics(t);
    return m;
}

}  // namespace jl
