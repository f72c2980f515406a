// Time integration of a world's bodies and energy ledger: explicit Euler (the
// paper's), symplectic Euler, classical RK4, adaptive Dormand-Prince 5(4) and
// Verner 6(5), and the adaptive, linearly implicit Rosenbrock-W method ROS34PW2.
#pragma once

#include "jl/base/integrator.h"
#include "jl/engine/dynamics.h"
#include "jl/engine/fresh.h"
#include "jl/engine/projection.h"

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace jl {

class World;
struct StageTerms;  // the engine's own (core/engine/stage_sums.h)

// Energy that entered or left through held blocks, drags and damping (J),
// integrated with the same method as the motion so the balance holds to its order.
struct Ledger {
    double held = 0, user = 0, damping = 0;
};

struct StepOutcome {
    double taken = 0;    // s, the step actually made (adaptive: <= asked)
    int rejected = 0;    // adaptive trials thrown away
    bool finite = true;  // false: a NaN or inf appeared; the world was restored
    // Dormand-Prince or Verner asked to project (Stepper::advance's
    // projectionTolerance): their last stage is the end of the step
    // projected onto the pins, so the world holds the projected end, w.a
    // and the dynamics' forces its evaluation, these its powers, and this
    // how the projection went.
    bool endEvaluated = false;
    Powers endPowers;
    ProjectionResult projection;
};

class Stepper {
public:
    explicit Stepper(Integrator kind = Integrator::RK4, double tolerance = 1e-8);

    // Advances w from time t. Fixed-step methods take exactly h; the adaptive
    // method takes at most h, choosing its own step to meet the tolerance.
    // `exact`: the adaptive method takes exactly h too (to re-run part of an
    // accepted step when locating an event). `atStart`: w.a already holds
    // the accelerations at (t, w.q, w.v) and these are their powers, so the
    // first stage needs no evaluation (KeptEvaluation). `projectionTolerance`
    // > 0: Dormand-Prince and Verner project the end of each trial onto the pins
    // before its last stage (first same as last, on the pins: the caller's
    // projection and evaluation of the end are that stage); the other
    // methods leave the projection to the caller.
    StepOutcome advance(World& w, Dynamics& d, double t, double h, Ledger& ledger, bool exact = false,
                        const Powers* atStart = nullptr, double projectionTolerance = 0);

    Integrator kind() const { return kind_; }
    // The last stage is the end of the step (first same as last): it can be
    // the projected end, and the next step's first stage.
    bool lastStageIsEnd() const { return kind_ == Integrator::DormandPrince45 || kind_ == Integrator::Verner65; }
    int order() const;
    double nextStep() const { return next_; }  // adaptive: its next trial step
    // The state at the start of the last advance, to undo a step without a copy.
    const Eigen::VectorXd& startPositions() const { return q0_; }
    const Eigen::VectorXd& startVelocities() const { return v0_; }
    void setNextStep(double h) { next_ = h; }

    // What it holds on the heap (jl/base/heap_bytes.h): what a copy takes.
    std::size_t heapBytes() const;

private:
    struct Tableau {
        std::vector<double> c, b, e;         // e = b - b_embedded (adaptive only)
        std::vector<std::vector<double>> a;  // lower triangle
    };
    // Derived from a tableau for its Nystrom form (Stepper::attempt):
    // sum_j a_ij, (a a)_ik; (b a)_k and sum b; (e a)_k and sum e; the same
    // over all stages but the last.
    struct Nystrom {
        std::vector<double> rowSum;
        std::vector<std::vector<double>> aa;
        std::vector<double> ba, ea, eaHead;
        double bSum = 0, eSum = 0, eHeadSum = 0;
    };
    static Nystrom nystromOf(const Tableau& r);
    // The linearly implicit method (linearly_implicit.cpp), in the
    // transformed form of Hairer and Wanner: stage increments u_i solve
    // (I/(h gamma) - W) u_i = F(Y_i) + sum_j c_ij u_j / h.
    struct Rosenbrock {
        static constexpr int stages = 4;
        double gamma = 0;
        double a[4][4] = {}, c[4][4] = {}, alpha[4] = {}, m[4] = {}, e[4] = {};
    };
    static Rosenbrock rosenbrockTableau();
    // `firstKnown`: the first stage (the step's start) is already in
    // kv_[0] and kl_[0].
    double attempt(World& w, Dynamics& d, double t, double h, Ledger& ledger, bool firstKnown,
                   double projectionTolerance);
    double rosenbrockAttempt(World& w, Dynamics& d, double t, double h, Ledger& ledger);
    void stiffMass(const World& w, Dynamics& d, double s);
    void rosenbrockStage(World& w, int i, double h);
    void symplecticEuler(World& w, Dynamics& d, double t, double h, Ledger& ledger, const Powers* atStart);
    double errorNorm(const World& w, const StageTerms& errorQ, const StageTerms& errorV) const;

    Integrator kind_;
    double tolerance_;
    double next_ = 0;
    Tableau tableau_;
    Nystrom nystrom_;
    std::vector<Eigen::VectorXd> kv_;  // stage accelerations
    std::vector<Eigen::Vector3d> kl_;  // stage ledger rates
    Powers endPowers_;                 // of the last stage, when it is the projected end
    ProjectionResult endProjection_;
    Eigen::VectorXd q0_, v0_;
    // Rosenbrock: the tableau, stage increments and the step's matrix.
    Rosenbrock ros_;
    std::vector<Eigen::VectorXd> uq_, uv_;
    std::vector<Eigen::Vector3d> ul_;
    Eigen::VectorXd rq_, mask_, keep_, kept_, rest_, mu_, jmu_;
    std::uint64_t maskRevision_ = 0;             // the World::revision mask_ was made for
    std::vector<double> stiffness_;              // d(moment)/d(angle) per body, N m/rad
    std::vector<Eigen::Vector2d> stiffInverse_;  // (1/m', 1/I') per body
    Fresh<PinSolver> stiff_;                     // assembled at the start of every step
};

}  // namespace jl
