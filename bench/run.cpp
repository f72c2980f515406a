#include "bench/run.h"

#include "bench/cases.h"
#include "bench/chart.h"
#include "bench/contacts_report.h"
#include "bench/csv_columns.h"
#include "bench/events.h"
#include "bench/examples.h"
#include "bench/folding_study.h"
#include "bench/models.h"
#include "bench/peers.h"
#include "bench/report.h"
#include "bench/save_text.h"
#include "bench/stability.h"
#include "jl/base/csv_writer.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>

namespace jl::bench {

namespace {

// `columns`: the study's header (its error's unit), bench/csv_columns.h.
bool writeCsv(const std::vector<BenchRow>& rows, const std::filesystem::path& path,
              const char* columns = kWorkPrecisionColumns) {
    std::ostringstream f;
    f << columns << '\n';
    CsvWriter csv(f, 6);
    for (const BenchRow& r : rows)
        csv.row(r.study, r.method, r.blocks, r.parameter, r.cost, r.error, r.finished, r.note);
    return saveText(path, f.str());
}

bool writeEventCostCsv(const std::vector<EventCostRow>& rows, const std::filesystem::path& path) {
    std::ostringstream f;
    f << kEventCostColumns << '\n';
    CsvWriter csv(f, 6);
    for (const EventCostRow& r : rows)
        csv.row(r.blocks, r.from, r.to, r.steps, r.meanStep, r.events, r.instants, r.kinds, r.runCpu, r.runRepetitions,
                r.repeatable, r.plainStep, r.plainSteps, r.plainRepetitions, r.plainEvents, r.plainStepCpu,
                r.runCpu - double(r.steps) * r.plainStepCpu, r.perEvent, r.perInstant, r.eventShare,
                r.perEvent / r.plainStepCpu, r.controlSteps, r.controlEvents, r.controlStepCpu, r.perEventControl,
                r.eventfulSteps, r.eventfulCpu, r.perEventInStep, r.failure);
    return saveText(path, f.str());
}

bool writeExamplesCsv(const ExamplesStudy& s, const std::filesystem::path& path) {
    std::ostringstream f;
    f << kExamplesColumns << '\n';
    CsvWriter csv(f, 6);
    for (const ExampleRow& r : s.rows)
        csv.row(r.scene, r.blocks, r.asked, r.simulated, r.cpu, r.perSimulated(),
                r.simulated > 0 && r.perSimulated() <= 1, r.steps, r.integrator, r.adaptive, r.tolerance,
                r.automaticStep, r.smallestStep, r.largestStep, r.stepHalvings, r.hingeEvents, r.failure);
    return saveText(path, f.str());
}

bool writeStabilityCsv(const StabilityStudy& s, const std::filesystem::path& path) {
    std::ostringstream f;
    f << kStabilityColumns << '\n';
    CsvWriter csv(f, 8);
    for (const StabilityRow& r : s.rows)
        csv.row(r.blocks, r.omegaMax, std::sqrt(r.referenceOmega2), r.handUpper, r.handAiry, r.engine.iterations,
                r.engine.residual, r.rk4Limit, r.symplecticLimit, r.dopriLimit, r.horizon, r.seededPass, r.seededFail,
                r.hangingPass, r.hangingFail, r.turnedPass, r.turnedFail, r.hangingCost, r.turnedCost, r.handTension,
                r.peakTension, r.peakTime, r.turnedPeakLimit, r.dopriSteps, r.dopriRejected, r.dopriMeanStep,
                r.dopriCost);
    return saveText(path, f.str());
}

// One series per method: cost against error.
Chart workPrecision(const std::string& title, const std::string& errorLabel, const std::vector<BenchRow>& rows) {
    Chart c{title, "CPU seconds per simulated second", errorLabel, {}};
    std::map<std::string, size_t> index;
    for (const BenchRow& r : rows) {
        if (!r.finished) continue;
        if (!index.count(r.method)) {
            index[r.method] = c.series.size();
            c.series.push_back({r.method, {}, r.method.find("end-of-step") != std::string::npos});
        }
        c.series[index[r.method]].points.push_back({r.cost, r.error});
    }
    return c;
}

bool writeLongLadderChart(const std::vector<BenchRow>& rows, const std::filesystem::path& out) {
    std::vector<BenchRow> shown;
    for (const BenchRow& r : rows)
        if (r.error > 0) {  // not the reference itself
            shown.push_back(r);
            shown.back().method += ", N = " + std::to_string(r.blocks);
        }
    return writeChart(
        workPrecision("Long ladder turned over from t = 0, t = 0.5 s (reference: Dormand-Prince at 1e-10)",
                      "largest block-centre error (m)", shown),
        out, "long_ladder");
}

}  // namespace

bool runBench(const BenchRequest& request) {
    const std::string& only = request.only;
    const bool onlyStability = only == "stability", onlyModels = only == "models", onlyEvents = only == "events";
    const bool onlyExamples = only == "examples", onlyContacts = only == "contacts";
    const std::filesystem::path& examplesDir = request.examples;
    const std::filesystem::path& out = request.out;
    const std::filesystem::path& report = request.report;
    BenchPlan plan;
    plan.quick = request.quick;
    plan.minSeconds = plan.quick ? 0.005 : 0.05;
    const std::vector<int> chainSizes = plan.quick ? std::vector<int>{10, 100} : std::vector<int>{10, 100, 1000};
    const int studies = only.empty() ? 9 + int(chainSizes.size()) : 1;
    int started = 0;
    const auto starts = [&](const std::string& study) {
        if (request.studyStarts)
            request.studyStarts(study, started, studies);
        else
            std::fprintf(stderr, "%s\n", study.c_str());
        ++started;
    };
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (!ec && report.has_parent_path()) std::filesystem::create_directories(report.parent_path(), ec);
    if (ec) {
        std::fprintf(stderr, "jladder bench: cannot create %s: %s\n", out.c_str(), ec.message().c_str());
        return false;
    }
    if (onlyStability) {
        starts("stability limit");
        const StabilityStudy study = stabilityStudy(plan);
        return (writeStabilityCsv(study, out / "stability.csv") && writeStabilityReport(study, plan.quick, report));
    }
    if (onlyModels) {
        starts("rigid pairs: merged or welded");
        const std::vector<BenchRow> rows = rigidPairModelStudy(plan);
        return (writeCsv(rows, out / "models.csv") && writeModelsReport(rows, plan.quick, report));
    }
    if (onlyEvents) {
        starts("cost of an event");
        const std::vector<EventCostRow> rows = eventCostStudy(plan);
        return (writeEventCostCsv(rows, out / "events.csv") && writeEventCostReport(rows, plan.quick, report));
    }

    if (onlyExamples) {
        starts("examples at default settings");
        const ExamplesStudy study = examplesStudy(plan, examplesDir);
        return (writeExamplesCsv(study, out / "examples.csv") && writeExamplesReport(study, plan.quick, report) &&
                study.error.empty());
    }
    if (only == "folding") {
        starts("folding chain: stops, against the peers");
        return runFoldingStudy(plan, out, report);
    }
    if (only == "long_ladder") {
        starts("long ladder");
        const std::vector<BenchRow> rows = longLadderStudy(plan);
        const LongClassicRun classic = longClassicRun(plan);
        return writeCsv(rows, out / "long_ladder.csv") && writeLongLadderChart(rows, out) &&
               writeLongLadderReport(rows, classic, plan.quick, out, report);
    }
    if (onlyContacts) {
        starts("block contacts");
        const ContactsStudy study = contactsStudy(plan, examplesDir);
        return writeContactsCsv(study, out) && writeContactsReport(study, plan.quick, report) && study.error.empty();
    }

    BenchResults results;
    results.quick = plan.quick;
    starts("pendulum");
    results.pendulum = pendulumStudy(plan);
    const std::vector<double> peerSteps =
        plan.quick ? std::vector<double>{1e-3, 1e-4} : std::vector<double>{1e-3, 5e-4, 2.5e-4, 1e-4};
    for (int n : chainSizes) {
        starts("falling chain N=" + std::to_string(n));
        std::vector<Vec2> reference;
        std::vector<BenchRow> rows = chainStudy(plan, n, n <= 100, reference);
        for (const PeerRun& p : measurePeers(n, peerSteps, 0.5, reference, plan.minSeconds))
            rows.push_back({"chain" + std::to_string(n), p.engine, n, p.step, p.cost, p.error, p.finished, ""});
        results.chains[n] = rows;
    }
    starts("ladder cascade");
    results.ladder = ladderStudy(plan);
    starts("scaling");
    results.scaling = scalingStudy(plan);
    starts("long ladder");
    results.longLadder = longLadderStudy(plan);
    results.longClassic = longClassicRun(plan);
    starts("stability limit");
    results.stability = stabilityStudy(plan);
    starts("rigid pairs: merged or welded");
    results.models = rigidPairModelStudy(plan);
    starts("cost of an event");
    results.eventCost = eventCostStudy(plan);
    starts("examples at default settings");
    results.examples = examplesStudy(plan, examplesDir);
    starts("block contacts");
    results.contacts = contactsStudy(plan, examplesDir);
    results.peers = peerVersions();

    bool ok = writeCsv(results.pendulum, out / "pendulum.csv", kWorkPrecisionPendulumColumns) &&
              writeCsv(results.ladder, out / "ladder.csv") &&
              writeCsv(results.scaling, out / "scaling.csv", kScalingColumns) &&
              writeCsv(results.longLadder, out / "long_ladder.csv") &&
              writeStabilityCsv(results.stability, out / "stability.csv") &&
              writeCsv(results.models, out / "models.csv") &&
              writeEventCostCsv(results.eventCost, out / "events.csv") &&
              writeExamplesCsv(results.examples, out / "examples.csv") && writeContactsCsv(results.contacts, out);
    ok = writeChart(
             workPrecision("Physical pendulum, one exact period (theta0 = 2 rad)", "error (rad)", results.pendulum),
             out, "pendulum") &&
         ok;
    for (const auto& [n, rows] : results.chains) {
        const std::string name = "chain" + std::to_string(n);
        ok = writeCsv(rows, out / (name + ".csv")) && ok;
        ok = writeChart(workPrecision("Falling chain, N = " + std::to_string(n) + ", t = 0.5 s",
                                      "largest block-centre error (m)", rows),
                        out, name) &&
             ok;
    }
    ok = writeChart(
             workPrecision("Ladder cascade, 6 blocks, t = 1.2 s", "largest block-centre error (m)", results.ladder),
             out, "ladder") &&
         ok;
    ok = writeLongLadderChart(results.longLadder, out) && ok;
    Chart scaling{"Cost per block-step, falling chain (dt = 1 ms; the Euler methods 0.1 ms)",
                  "blocks N",
                  "ns per block-step (CPU)",
                  {}};
    std::map<std::string, size_t> index;
    for (const BenchRow& r : results.scaling) {
        if (!index.count(r.method)) {
            index[r.method] = scaling.series.size();
            scaling.series.push_back({r.method, {}, false});
        }
        scaling.series[index[r.method]].points.push_back({double(r.blocks), r.error});
    }
    ok = writeChart(scaling, out, "scaling") && ok;
    ok = writeReport(results, out, report) && ok;
    return (ok);
}

}  // namespace jl::bench
