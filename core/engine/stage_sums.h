// Sums over the stages of one step, for the Runge-Kutta and Rosenbrock
// integrators: a stage's state (the start plus weighted stage vectors), the
// step's end, and the error estimate with its norm. Each is formed in one
// pass over memory, whatever the number of terms: on a long chain the stage
// vectors outgrow the cache, and a pass per term was what made the adaptive
// methods' cost per block rise with the chain's length.
#pragma once

#include <Eigen/Core>

#include <cstddef>

namespace jl {

// The terms scale * coefficient[j] * k[j] of a sum, those with a zero
// coefficient left out, in the order of j.
struct StageTerms {
    // Verner's 6(5) pair, the longest tableau, has 9 stages; a position
    // sum has one more term, the start's velocity.
    static constexpr size_t most = 10;
    double c[most] = {};
    const double* x[most] = {};
    size_t m = 0;

    StageTerms() = default;
    StageTerms(double scale, const double* coefficients, const Eigen::VectorXd* const* k, size_t count);
    // Appends c x, unless c is zero.
    void add(double coefficient, const Eigen::VectorXd& vector);
    // Zero terms on `vector` up to `count` terms (for sums run side by side).
    void padTo(size_t count, const double* vector);
};

// q = q0 + c_0 x_0 + c_1 x_1 + ... (the terms of q, added in that order:
// bit for bit what one axpy after another gives), and v likewise, in one
// pass over both: a stage's positions and velocities read the same stage
// vectors. q and v may not be among the terms.
void combineStages(Eigen::VectorXd& q, const Eigen::VectorXd& q0, const StageTerms& termsQ, Eigen::VectorXd& v,
                   const Eigen::VectorXd& v0, const StageTerms& termsV, Eigen::Index n);

// The RMS of a step's error estimate over the dynamic coordinates (inverse
// mass not zero: `parts` not zero), each scaled by tolerance (1 + max(|y0|, |y1|)). A body
// counts once for each of its parts: the mean is over the parts the scene
// has, however many of them move as one (a locked pair, a still tail's
// segment of hundreds of blocks), so that joining parts that move rigidly
// changes what the error control asks of the step in nothing. The estimate
// itself (errorQ, errorV: its terms, summed from zero in their order)
// is formed in the same pass and never stored.
struct ErrorNormInputs {
    double tolerance = 0;
    Eigen::Index n = 0;             // coordinates
    const double* parts = nullptr;  // per coordinate: its body's part count, 0 if it has no inverse mass
    const double *q0 = nullptr, *q1 = nullptr, *v0 = nullptr, *v1 = nullptr;
};
double errorNorm(const ErrorNormInputs& in, const StageTerms& errorQ, const StageTerms& errorV);

}  // namespace jl
