// The section "Folding chain" of docs/performance.md: every engine's runs of
// the folding chain (bench/folding_chain.h) against a reference, this
// engine's tightest run, itself checked against Siconos's.
#pragma once

#include "bench/folding_chain.h"

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace jl::bench {

// How far one run is from a reference, at each of folding::kSampleTimes.
struct FoldingError {
    using PerSample = std::array<double, folding::kSampleTimes.size()>;
    PerSample centre{};      // m, the largest block-centre distance; NaN without centres
    PerSample dissipated{};  // J, |dissipated - reference|
    // s, the largest |first closing - reference| over the hinges that both
    // close, one of them by the sample time; NaN if there is none.
    PerSample closing{};
    // By the sample time: hinges the reference closes and the run never does,
    // and the reverse.
    std::array<int, folding::kSampleTimes.size()> missing{}, extra{};
};

FoldingError foldingError(const FoldingRun& run, const FoldingRun& reference);

// One N's part of the section (Markdown): how far the references are from
// each other (siconosRef null: said missing), the speed-against-error charts
// (in `charts`, relative to the report) and every run's errors against oursRef.
std::string foldingPart(const std::vector<FoldingRun>& runs, const FoldingRun& oursRef, const FoldingRun* siconosRef,
                        const std::string& charts);

// DIR/foldingN_centre.svg, _dissipated.svg and _closing.svg: CPU s against
// the error at 1 s, one series per engine and method.
bool writeFoldingCharts(const std::vector<FoldingRun>& runs, const FoldingRun& oursRef,
                        const std::filesystem::path& dir);

// One N's rows of docs/bench/folding.csv (kFoldingColumns): every run's
// errors against oursRef.
std::string foldingCsvRows(const std::vector<FoldingRun>& runs, const FoldingRun& oursRef);

// The section from its parts (one foldingPart per N), its template filled.
std::string foldingSection(const std::string& parts, bool quick, bool& ok);
// The section alone, as `jladder bench --only folding` would write it.
bool writeFoldingReport(const std::string& parts, bool quick, const std::filesystem::path& report);

}  // namespace jl::bench
