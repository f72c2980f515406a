// The benchmark: speed against error, measured and published. Runs every
// study (cases.h, stability.h, models.h, events.h, examples.h, and the peer
// engines if built in), writes their CSV tables and SVG charts and the report
// (docs/performance.md) from its template. `jladder bench` is its command.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

namespace jl::bench {

struct BenchRequest {
    bool quick = false;                        // fewer sizes and steps: fits in CI
    std::string only;                          // "", or one study: stability, models, events, examples
    std::filesystem::path out = "docs/bench";  // CSV and SVG
    std::filesystem::path report = "docs/performance.md";
    std::filesystem::path examples = "examples";  // the scenes of the examples study
    // Told as each study starts (its name, how many are done, of how many);
    // without it the name is a line on stderr.
    std::function<void(const std::string& study, int done, int total)> studyStarts;
};

// False if a study failed or a file could not be written (said on stderr).
bool runBench(const BenchRequest& request);

}  // namespace jl::bench
