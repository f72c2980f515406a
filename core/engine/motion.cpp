#include "jl/engine/motion.h"

#include "jl/engine/world.h"

namespace jl {

MotionStep advanceAndProject(World& w, Dynamics& d, Stepper& s, double t, double h, Ledger& ledger,
                             double tolerance, bool exact, const Powers* atStart) {
    MotionStep m;
    const Ledger l0 = ledger;
    m.step = s.advance(w, d, t, h, ledger, exact, atStart);
    if (!m.step.finite) return m;
    m.projection = projectPositions(w, d.solver(), tolerance);
    if (m.projection.converged) {
        projectVelocities(w, d.solver());
        if (w.q.allFinite() && w.v.allFinite()) return m;
        m.step.finite = false;
    }
    // The stepper still holds the state it started from (no copy per step).
    w.q = s.startPositions();
    w.v = s.startVelocities();
    ledger = l0;
    w.updateKinematics(t);
    return m;
}

}  // namespace jl
