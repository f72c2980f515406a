// The folding chain (bench/folding_chain.h) in Siconos, the reference
// library for nonsmooth mechanics: the chain in minimal coordinates (one
// absolute angle per block), each stop a unilateral constraint with Newton's
// impact law (e = 0), run by Moreau-Jean time stepping and by the
// event-driven scheme that locates every impact. Built when JL_BENCH_PEERS
// is on; otherwise the functions measure nothing.
#pragma once

#include "bench/folding_chain.h"

#include <cstdio>
#include <string>
#include <vector>

namespace jl::bench {

// One Siconos run of the folding chain.
struct SiconosFolding {
    bool eventDriven = false;  // false: Moreau-Jean time stepping
    double theta = 0.5;        // Moreau-Jean's theta
    double step = 1e-4;        // s, Moreau-Jean's step
    double tolerance = 1e-8;   // event-driven: Lsodar's relative and absolute tolerance
    bool stops = true;         // false: the smooth falling chain, for checking
    // Event-driven: stop the run when it has taken this many events (a Zeno
    // accumulation of impacts) or this much CPU time.
    long maxEvents = 2000000;
    double maxCpuSeconds = 600;
    // When set: "t phi_1 .. phi_{N-1} energy" every traceEvery seconds.
    std::FILE* trace = nullptr;
    double traceEvery = 0.01;
};

FoldingRun runFoldingSiconos(int n, const SiconosFolding& how);

// The settings of the study at n blocks (each run repeated until it took
// minSeconds of CPU, the time of one run reported).
std::vector<FoldingRun> runFoldingSiconos(int n, double minSeconds);

// "Siconos 4.4.0 ..." or why it is not measured.
std::string siconosVersion();

}  // namespace jl::bench
