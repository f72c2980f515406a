// jladder bench: every scene of examples/ run headless at its own settings
// (and the long ladder with 1,000 blocks), against the targets that a
// scene plays at 1x on one core.
#pragma once

#include "bench/cases.h"

#include <filesystem>
#include <string>
#include <vector>

namespace jl::bench {

struct ExampleRow {
    std::string scene;     // file name, e.g. "long-ladder.yaml" ("... x 1,000 blocks" for the long design)
    int blocks = 0;        // ladder blocks, or boxes and particles of a general scene
    double asked = 0;      // s, simulated time asked for (3 s, 1 s quick, or the scene's duration if shorter)
    double simulated = 0;  // s, reached
    double cpu = 0;        // CPU s of the thread (bench_clock.h), build included
    long long steps = 0;
    std::string integrator;  // "RK4", ...
    bool adaptive = false;   // Dormand-Prince: the step follows its tolerance
    double tolerance = 0;
    bool automaticStep = false;                // the engine chose the step (scene's step 0)
    double smallestStep = 0, largestStep = 0;  // s
    int stepHalvings = 0;
    int hingeEvents = 0;
    std::string failure;
    double perSimulated() const { return simulated > 0 ? cpu / simulated : 0; }
};

struct ExamplesStudy {
    std::filesystem::path dir;  // where the scenes were read
    std::vector<ExampleRow> rows;
    std::string error;  // the directory could not be read
};

// Every *.yaml in `dir` (sorted by name); not quick: also long-ladder.yaml
// with 1,000 blocks.
ExamplesStudy examplesStudy(const BenchPlan& plan, const std::filesystem::path& dir);

}  // namespace jl::bench
