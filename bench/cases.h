// The measurements of jladder bench: each returns rows of cost against error.
#pragma once

#include "jl/base/geometry.h"
#include "jl/scene/scene.h"

#include <string>
#include <vector>

namespace jl::bench {

// One measured configuration. cost: CPU seconds of one thread per simulated
// second; error: the study's error measure (see docs/performance.md).
struct BenchRow {
    std::string study;   // "pendulum", "chain10", "chain100", "ladder", "scaling", "peers..."
    std::string method;  // integrator (and event policy), or peer engine
    int blocks = 0;
    double parameter = 0;  // step (s) of fixed-step methods, tolerance of the adaptive one
    double cost = 0;
    double error = 0;
    bool finished = true;  // false: the run failed (reported, no NaN)
    std::string note;
};

struct BenchPlan {
    bool quick = false;
    double minSeconds = 0.02;  // each configuration repeated until it took this long
};

// Whether a row's method (its integrator's word, perhaps with more words)
// is an adaptive one, whose parameter is a tolerance rather than a step.
bool namesAdaptiveMethod(const std::string& method);

// The turn of the benchmark's ladders: block 0 turned half a turn
// counter-clockwise from `at` over 0.3 s.
ScriptAction halfTurn(double at);

std::vector<BenchRow> pendulumStudy(const BenchPlan& plan);
// Falling chain of n blocks against the reduced-coordinate reference
// (`independent`), or, where that dense reference is too slow (N = 1,000),
// against the engine itself with RK4 at dt = 20 us (its accuracy is shown
// by the same run at N = 100 against the independent reference).
std::vector<BenchRow> chainStudy(const BenchPlan& plan, int n, bool independent, std::vector<Vec2>& referenceOut);
// The classic cascade: event times and final poses against a tight run.
std::vector<BenchRow> ladderStudy(const BenchPlan& plan);
// Cost per block-step against N (error column: 0).
std::vector<BenchRow> scalingStudy(const BenchPlan& plan);
// A long ladder turned over with RK4 (real-time factor in the note).
std::vector<BenchRow> longLadderStudy(const BenchPlan& plan);

// The classic design with many blocks at the default settings, timed (no
// reference: an accurate run of it takes minutes); the quick form runs none.
struct LongClassicRun {
    int blocks = 0;
    double asked = 0, simulated = 0;  // s
    double cpu = 0;                   // s, the fastest of `runs`
    int runs = 0;
    long long steps = 0, evaluations = 0, rejected = 0;
    int halvings = 0;
    double books = 0;  // J, the energy books' imbalance at the end
    std::string failure;
};
LongClassicRun longClassicRun(const BenchPlan& plan);

}  // namespace jl::bench
