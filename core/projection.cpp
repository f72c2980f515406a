#include "core/projection.h"

#include "core/world.h"

#include <algorithm>
#include <cmath>

namespace jl {

namespace {

// Gap of every pin (2 per pin): point on A minus point on B.
void pinGaps(const World& w, Eigen::VectorXd& gap) {
    const std::vector<Pin>& pins = w.pins();
    gap.resize(2 * Eigen::Index(pins.size()));
    for (size_t i = 0; i < pins.size(); ++i) {
        const Pin& p = pins[i];
        const Vec2 xa = w.bodyPose(p.bodyA).apply(p.localA);
        const Vec2 xb = w.bodyPose(p.bodyB).apply(p.localB);
        gap.segment<2>(2 * Eigen::Index(i)) = xa - xb;
    }
}

double largestPair(const Eigen::VectorXd& x) {
    double m = 0;
    for (Eigen::Index i = 0; i + 1 < x.size(); i += 2) m = std::max(m, std::hypot(x[i], x[i + 1]));
    return m;
}

}  // namespace

double pinResidual(const World& w) {
    Eigen::VectorXd gap;
    pinGaps(w, gap);
    return largestPair(gap);
}

double pinVelocityResidual(const World& w, PinSolver& solver) {
    solver.assemble(w);
    Eigen::VectorXd jv;
    solver.multiplyJ(w.v, jv);
    return largestPair(jv);
}

ProjectionResult projectPositions(World& w, PinSolver& solver, double tolerance, int maxIterations) {
    ProjectionResult r;
    Eigen::VectorXd gap, x, dq, q0;
    pinGaps(w, gap);
    double size = gap.norm();
    r.residual = largestPair(gap);
    while (r.residual > tolerance) {
        if (r.iterations == maxIterations) {
            r.converged = false;
            return r;
        }
        ++r.iterations;
        // Newton step: J dq = -C with dq = W J^T x.
        solver.assemble(w);
        solver.solve(-gap, x);
        dq.setZero(w.q.size());
        solver.addJTranspose(x, dq);
        dq.array() *= w.invMassDiag.array();
        q0 = w.q;
        // Backtrack until the gap shrinks; the full step nearly always does.
        double step = 1.0;
        for (int halving = 0;; ++halving) {
            w.q = q0 + step * dq;
            pinGaps(w, gap);
            const double trial = gap.norm();
            if (trial < size || halving == 30) {
                if (!(trial < size)) {
                    w.q = q0;
                    r.converged = false;
                    return r;
                }
                size = trial;
                break;
            }
            step *= 0.5;
        }
        r.residual = largestPair(gap);
    }
    return r;
}

void projectVelocities(World& w, PinSolver& solver, Eigen::VectorXd* impulses) {
    Eigen::VectorXd jv, x, dv;
    solver.assemble(w);
    solver.multiplyJ(w.v, jv);
    solver.solve(-jv, x);
    dv.setZero(w.v.size());
    solver.addJTranspose(x, dv);
    w.v.array() += dv.array() * w.invMassDiag.array();
    if (impulses) *impulses = x;
}

ProjectionResult makeConsistent(World& w, double tolerance) {
    PinSolver solver;
    ProjectionResult r = projectPositions(w, solver, tolerance);
    projectVelocities(w, solver);
    return r;
}

}  // namespace jl
