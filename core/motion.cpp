#include "core/motion.h"

#include "core/world.h"

namespace jl {

MotionStep advanceAndProject(World& w, Dynamics& d, Stepper& s, double t, double h, Ledger& ledger,
                             double tolerance, bool exact) {
    MotionStep m;
    const Eigen::VectorXd q0 = w.q, v0 = w.v;
    const Ledger l0 = ledger;
    m.step = s.advance(w, d, t, h, ledger, exact);
    if (!m.step.finite) return m;
    m.projection = projectPositions(w, d.solver(), tolerance);
    if (m.projection.converged) {
        projectVelocities(w, d.solver());
        if (w.q.allFinite() && w.v.allFinite()) return m;
        m.step.finite = false;
    }
    w.q = q0;
    w.v = v0;
    ledger = l0;
    w.updateKinematics(t);
    return m;
}

}  // namespace jl
