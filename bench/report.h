// docs/performance.md from the benchmark's measurements: tables, charts,
// the machine, and each target of docs/model.md section 16.2 checked against
// the numbers.
#pragma once

#include "bench/cases.h"
#include "bench/contacts.h"
#include "bench/events.h"
#include "bench/examples.h"
#include "bench/stability.h"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace jl::bench {

struct BenchResults {
    bool quick = false;
    std::vector<BenchRow> pendulum, ladder, scaling, longLadder;
    LongClassicRun longClassic;
    std::map<int, std::vector<BenchRow>> chains;  // by N; peers' rows included
    std::string peers;                            // versions, or why not measured
    StabilityStudy stability;
    std::vector<BenchRow> models;  // rigidPairModelStudy
    std::vector<EventCostRow> eventCost;
    ExamplesStudy examples;
    ContactsStudy contacts;
};

bool writeReport(const BenchResults& r, const std::filesystem::path& plots, const std::filesystem::path& report);
// The section "A long ladder turned over" and its targets alone (jladder
// bench --only long_ladder); `plots` holds its chart.
bool writeLongLadderReport(const std::vector<BenchRow>& rows, const LongClassicRun& classic, bool quick,
                           const std::filesystem::path& plots, const std::filesystem::path& report);
// The section "Stability limit of long ladders" alone (jladder bench --only stability).
bool writeStabilityReport(const StabilityStudy& s, bool quick, const std::filesystem::path& report);
// The section "Model only what a scene needs" alone (jladder bench --only models).
bool writeModelsReport(const std::vector<BenchRow>& rows, bool quick, const std::filesystem::path& report);
// The section "Cost of an event" alone (jladder bench --only events).
bool writeEventCostReport(const std::vector<EventCostRow>& rows, bool quick, const std::filesystem::path& report);
// The section "Examples at default settings" alone (jladder bench --only examples).
bool writeExamplesReport(const ExamplesStudy& s, bool quick, const std::filesystem::path& report);

}  // namespace jl::bench
