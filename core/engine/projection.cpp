#include "jl/engine/projection.h"

#include "jl/engine/dynamics.h"
#include "jl/engine/energy.h"
#include "jl/engine/world.h"
#include "pin_solver.h"
#include "scratch.h"
#include "turns.h"

#include <algorithm>
#include <cmath>

namespace jl {

namespace {

// Gap of every pin (2 per pin): point on A minus point on B, with each
// body's (cos, sin) in `rotation`: one sincos per body rather than two per
// pin.
void pinGaps(const World& w, Eigen::VectorXd& gap, const std::vector<Eigen::Vector2d>& rotation) {
    auto point = [&](int body, const Vec2& r) {
        const Eigen::Vector2d& cs = rotation[size_t(body)];
        return Vec2(w.q[3 * body] + cs[0] * r.x() - cs[1] * r.y(), w.q[3 * body + 1] + cs[1] * r.x() + cs[0] * r.y());
    };
    const std::vector<Pin>& pins = w.pins();
    const std::vector<Weld>& welds = w.welds();
    const Eigen::Index weldRows = 2 * Eigen::Index(pins.size());
    gap.resize(weldRows + Eigen::Index(welds.size()));
    for (size_t i = 0; i < pins.size(); ++i) {
        const Pin& p = pins[i];
        gap.segment<2>(2 * Eigen::Index(i)) = point(p.bodyA, p.localA) - point(p.bodyB, p.localB);
    }
    // A weld's gap: how far its second shared point is off, arm * angle.
    for (size_t i = 0; i < welds.size(); ++i) {
        const Pin& p = pins[size_t(welds[i].pin)];
        gap[weldRows + Eigen::Index(i)] = welds[i].arm * (w.q[3 * p.bodyA + 2] - w.q[3 * p.bodyB + 2] - welds[i].angle);
    }
}

// The largest gap: a pin's two rows are one distance, a weld's row another.
double largestGap(const World& w, const Eigen::VectorXd& x) {
    const Eigen::Index weldRows = 2 * Eigen::Index(w.pins().size());
    // The largest square, then one root: std::hypot guards against an
    // overflow that gaps of metres cannot reach, at some 20 ns a pin (5 %
    // of the 10,000-block classic's run).
    double squared = 0;
    for (Eigen::Index i = 0; i + 1 < weldRows; i += 2) squared = std::max(squared, x[i] * x[i] + x[i + 1] * x[i + 1]);
    double m = std::sqrt(squared);
    for (Eigen::Index i = weldRows; i < x.size(); ++i) m = std::max(m, std::abs(x[i]));
    return m;
}

}  // namespace

double pinResidual(const World& w) {
    Eigen::VectorXd gap;
    std::vector<Eigen::Vector2d> rotation(size_t(w.bodyCount()));
    cosSinOf(w.q.data() + 2, 3, rotation.size(), rotation.data());
    pinGaps(w, gap, rotation);
    return largestGap(w, gap);
}

double pinVelocityResidual(const World& w) {
    PinSolver& solver = w.scratch().pins;
    solver.assemble(w);
    Eigen::VectorXd jv;
    solver.multiplyJ(w.v, jv);
    return largestGap(w, jv);
}

namespace {

// Newton's method on the gaps, each step dq = W J^T x with (J W J^T) x = -C.
// The first steps take J from the factorisation in hand when it is of these
// pins (after a step of the integrator: its last stage, a few micrometres
// away): a gap of 1e-9 m shrinks by the ratio of that move to a block's
// length, some 1e-4, so one step closes it as a fresh factorisation would,
// and the step's end then factorises once, for the velocities, instead of
// twice. A step that does not shrink the gaps tenfold is taken again with J
// at the current positions, and so is every step after it.
ProjectionResult closePins(World& w, PinSolver& solver, double tolerance, int maxIterations) {
    constexpr double kHeldRate = 0.1;  // the least shrinking a step with the held J must give
    ProjectionResult r;
    PinSolver::Scratch& s = solver.scratch;
    Eigen::VectorXd &gap = s.gap, &x = s.x, &dq = s.dq, &q0 = s.q0;
    pinGaps(w, gap, solver.turns(w));
    double size = gap.norm();
    r.residual = largestGap(w, gap);
    bool held = solver.holdsFactorisationFor(w);
    while (r.residual > tolerance) {
        if (r.iterations == maxIterations) {
            r.converged = false;
            return r;
        }
        ++r.iterations;
        gap = -gap;
        if (held)
            solver.solve(gap, x);
        else
            solver.solvePrepared(w, solver.prepare(w), gap, x);
        dq.setZero(w.q.size());
        solver.addJTranspose(x, dq);
        dq.array() *= w.invMassDiag.array();
        q0 = w.q;
        if (held) {
            w.q = q0 + dq;
            pinGaps(w, gap, solver.turns(w));
            const double trial = gap.norm();
            if (trial < kHeldRate * size) {
                size = trial;
                r.residual = largestGap(w, gap);
                continue;
            }
            // Too far from where J was taken: this step again, with J here.
            held = false;
            --r.iterations;
            w.q = q0;
            pinGaps(w, gap, solver.turns(w));
            continue;
        }
        // Backtrack until the gap shrinks; the full step nearly always does.
        double step = 1.0;
        for (int halving = 0;; ++halving) {
            w.q = q0 + step * dq;
            pinGaps(w, gap, solver.turns(w));
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
        r.residual = largestGap(w, gap);
    }
    return r;
}

double largestContactGap(const World& w) {
    double m = 0;
    for (const Contact& c : w.contacts()) m = std::max(m, std::abs(contactGap(w, c)));
    return m;
}

// The pins first; then each resting contact's gap is closed by the least
// move that keeps the pins (linearised: q += sum s_i u_i with K s = -gap,
// the same Schur complement as the dynamics'), and the pins closed again,
// until both are within the tolerance (docs/model.md section 17.2).
ProjectionResult projectPositions(World& w, PinSolver& solver, double tolerance, int maxIterations, bool contacts) {
    ProjectionResult r = closePins(w, solver, tolerance, maxIterations);
    if (!contacts || w.contacts().empty() || !r.converged) return r;
    ContactResponse& response = w.scratch().contacts;
    for (int round = 0; round < maxIterations; ++round) {
        if (largestContactGap(w) <= tolerance) break;
        response.build(w, solver, solver.prepare(w));
        const size_t k = w.contacts().size();
        Eigen::VectorXd rhs(Eigen::Index(k), 1);
        for (size_t i = 0; i < k; ++i) rhs[Eigen::Index(i)] = -contactGap(w, w.contacts()[i]);
        const Eigen::VectorXd s = response.solve(rhs, std::vector<char>(k, 1));
        for (size_t i = 0; i < k; ++i) w.q += s[Eigen::Index(i)] * response.response[i];
        const int used = r.iterations;
        r = closePins(w, solver, tolerance, maxIterations);
        r.iterations += used;
        if (!r.converged) return r;
        if (round + 1 == maxIterations) r.converged = largestContactGap(w) <= tolerance;
    }
    r.residual = std::max(r.residual, largestContactGap(w));
    return r;
}

void projectVelocities(World& w, PinSolver& solver, Eigen::VectorXd* impulses, ContactRule rule) {
    Eigen::VectorXd& x = solver.scratch.x;
    solver.removeVelocityDrift(w, x);
    if (w.contacts().empty()) {
        if (impulses) *impulses = x;
        return;
    }
    // The resting contacts, unilaterally: each pushes (s_i >= 0) only as
    // much as keeps its gap from closing, G (v + sum s_j u_j) >= 0, and a
    // contact that would have to pull is left to part (docs/model.md
    // section 17.3). The impulses follow the pins' in `impulses`.
    ContactResponse& response = w.scratch().contacts;
    response.build(w, solver, false);
    const size_t k = w.contacts().size();
    Eigen::VectorXd rhs(Eigen::Index(k), 1);
    for (size_t i = 0; i < k; ++i) rhs[Eigen::Index(i)] = -rowTimes(response.rows[i], w.v);
    const Eigen::VectorXd push =
        rule == ContactRule::PushOnly ? response.solvePushing(rhs) : response.solve(rhs, std::vector<char>(k, 1));
    for (size_t i = 0; i < k; ++i) {
        w.v += push[Eigen::Index(i)] * response.response[i];
        if (response.pinForces[i].size() == x.size()) x += push[Eigen::Index(i)] * response.pinForces[i];
    }
    if (impulses) {
        impulses->resize(x.size() + push.size());
        impulses->head(x.size()) = x;
        impulses->tail(push.size()) = push;
    }
}

// A gap left beyond this after a change of structure is a failed projection.
std::optional<WorldError> pinsLeftOpen(const char* operation, const ProjectionResult& r) {
    constexpr double kFailedGap = 1e-9;  // m
    if (r.converged || r.residual <= kFailedGap) return std::nullopt;
    return WorldError{std::string(operation) + ": the pins could not be closed after the change of structure (gap " +
                      std::to_string(r.residual) + " m after " + std::to_string(r.iterations) + " iterations)"};
}

}  // namespace

ProjectionResult projectPositions(World& w, Dynamics& d, double tolerance, int maxIterations, bool contacts) {
    return projectPositions(w, d.solver(), tolerance, maxIterations, contacts);
}

void projectVelocities(World& w, Dynamics& d, Eigen::VectorXd* impulses, ContactRule rule) {
    projectVelocities(w, d.solver(), impulses, rule);
}

void projectVelocities(World& w) { projectVelocities(w, w.scratch().pins, nullptr, ContactRule::PushOnly); }

double bounce(World& w, Dynamics& d, const std::vector<Twist>& before, double e) {
    const double plasticJump = jumpEnergy(w, before);
    const std::vector<Twist> bouncing = bounced(before, w.partVelocities(), e);
    w.setPartVelocities(bouncing);
    projectVelocities(w, d);
    return (1 - e * e) * plasticJump + jumpEnergy(w, bouncing);
}

ProjectionResult makeConsistent(World& w, double tolerance, bool contacts) {
    PinSolver& solver = w.scratch().pins;
    solver.reset();
    ProjectionResult r = projectPositions(w, solver, tolerance, 25, contacts);
    projectVelocities(w, solver, nullptr, ContactRule::PushOnly);
    return r;
}

std::optional<WorldError> makeConsistentAfter(World& w, const char* operation) {
    return pinsLeftOpen(operation, makeConsistent(w, w.restructureTolerance, false));
}

std::optional<WorldError> closePinGaps(World& w, const char* operation) {
    PinSolver& solver = w.scratch().pins;
    solver.reset();
    return pinsLeftOpen(operation, projectPositions(w, solver, w.restructureTolerance, 25, false));
}

}  // namespace jl
