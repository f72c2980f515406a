// jladder bench: the stability limit of long ladders. The highest vibration
// frequency omega_max of the hanging ladder, from the engine's own linearised
// equations (Lanczos on the finite-difference stiffness) and from an
// independent reduced-coordinate model; the step limits it predicts for each
// integrator; and the largest RK4 step that actually runs, by bisection.
#pragma once

#include "bench/cases.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace jl::bench {

// omega_max^2 of the hanging ladder from the engine: Lanczos in the mass
// metric on K x = -(da/dq) x, x tangent to the pins (finite differences of
// Dynamics::evaluate about the equilibrium that Simulation::build makes).
struct EngineMode {
    double omega2 = 0;               // (rad/s)^2, largest Ritz value
    double residual = 0;             // ||K y - omega2 y||_M of its Ritz vector y (an eigenvalue lies this close)
    int iterations = 0;              // Lanczos steps (two evaluations each)
    double cpu = 0;                  // s
    Eigen::VectorXd q0, mode, mass;  // the equilibrium, y (unit in the mass metric), the mass metric
};
EngineMode engineOmega2(int blocks);

// The same from the reduced model: the ladder's dynamic blocks are uniform
// rods of length l = sqrt(L^2 + T^2) between their hinge corners, linearised
// about the vertical in the hinges' sideways positions (M and K tridiagonal);
// the largest eigenvalue by Sturm-sequence bisection. O(N), exact to rounding.
double referenceOmega2(int blocks);

// A known answer the method is checked on.
struct StabilityCheck {
    std::string what;
    double engine = 0, reference = 0, exact = 0;  // omega^2, (rad/s)^2
};

struct StabilityRow {
    int blocks = 0;
    EngineMode engine;
    double referenceOmega2 = 0;  // independent reduced model
    double handUpper = 0;        // sqrt(12 T_1 / (m l)): the most loaded link alone (rad/s)
    double handAiry = 0;         // the top-of-chain (Airy) estimate (rad/s)
    double omegaMax = 0;         // rad/s, from the engine
    double rk4Limit = 0;         // s, predicted: 2 sqrt(2) / omega_max
    double symplecticLimit = 0;  // s, 2 / omega_max
    double dopriLimit = 0;       // s, y_DP / omega_max: |R| <= 1 below it
    double horizon = 0;          // s, simulated time of each measured run
    // Turning the top block pulls on the chain: the tension, and omega_max^2
    // with it, scale up. handTension: (g + upward acceleration of hinge 1) / g
    // at its largest over the horizon, from the hand's path alone;
    // peakTension: the largest pin force of a turned-over run (RK4 at half
    // the predicted limit, every step) over the hanging one, at peakTime;
    // turnedPeakLimit: the RK4 limit at that tension.
    double handTension = 1, peakTension = 1, peakTime = 0, turnedPeakLimit = 0;
    // Largest RK4 step that ran `horizon` without failure, and the smallest
    // that failed (the bisection's bracket); NaN if not measured.
    double hangingPass = 0, hangingFail = 0;
    double turnedPass = 0, turnedFail = 0;
    // The linear limit itself: the hanging ladder started with its fastest
    // mode (velocity 1e-4 at most): the largest step at which that mode has
    // not grown after `horizon`, and the smallest at which it has.
    double seededPass = 0, seededFail = 0;
    double hangingCost = 0, turnedCost = 0;  // CPU s per simulated s of the run at *Pass
    std::string hangingWhy, turnedWhy;       // the failure at *Fail, as the run reported it
    // The adaptive method on the turned-over ladder over the same horizon.
    double dopriMeanStep = 0, dopriCost = 0;
    long long dopriSteps = 0, dopriRejected = 0;
    std::string dopriFailure;
    int runs = 0;           // simulations in the bisections
    double measureCpu = 0;  // s
};

struct StabilityStudy {
    double imaginaryRk4 = 0, imaginaryDopri = 0;  // stability limits on the imaginary axis
    std::vector<StabilityCheck> checks;
    std::vector<StabilityRow> rows;
};

StabilityStudy stabilityStudy(const BenchPlan& plan);

}  // namespace jl::bench
