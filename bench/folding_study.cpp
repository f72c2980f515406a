#include "bench/folding_study.h"

#include "bench/csv_columns.h"
#include "bench/folding_chain.h"
#include "bench/folding_peers.h"
#include "bench/folding_report.h"
#include "bench/folding_siconos.h"
#include "bench/report_text.h"
#include "bench/save_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace jl::bench {

namespace {

// Siconos's tightest event-driven run: the second reference (one that
// stopped is compared up to where it got, and the report says so).
const FoldingRun* siconosReference(const std::vector<FoldingRun>& runs) {
    const FoldingRun* best = nullptr;
    for (const FoldingRun& r : runs)
        if (r.method.find("event-driven") != std::string::npos) best = &r;  // tightest last
    return best;
}

// The targets: at each peer run's cost, this engine's smallest block-centre
// error at 1 s among its runs that cost no more, and the ratio (the target
// asks for 100).
std::string targetsTable(const std::vector<FoldingRun>& runs, const FoldingRun& reference) {
    std::ostringstream md;
    md << "Targets at N = " << reference.blocks
       << ": at each peer run's CPU time, this engine's smallest block-centre error at 1 s among its runs that cost "
          "no more (the target: 100 times smaller).\n\n"
       << "| peer run | its CPU s | its error (m) | this engine at no more CPU | error (m) | ratio | met |\n"
       << "|---|---:|---:|---|---:|---:|---|\n";
    const size_t last = folding::kSampleTimes.size() - 1;
    for (const FoldingRun& p : runs) {
        if (p.engine == "jladder" || !p.finished) continue;
        const double theirs = foldingError(p, reference).centre[last];
        const FoldingRun* best = nullptr;
        double ours = INFINITY;
        for (const FoldingRun& r : runs) {
            if (r.engine != "jladder" || !r.finished || r.cpuSeconds > p.cpuSeconds) continue;
            const double e = foldingError(r, reference).centre[last];
            if (e < ours) ours = e, best = &r;
        }
        md << "| " << p.engine << " " << p.method << ", " << p.setting << " | " << sig(p.cpuSeconds, 3) << " | "
           << sig(theirs, 2) << " | ";
        if (!best) {
            md << "none that cheap | | | no |\n";
            continue;
        }
        const double ratio = ours > 0 ? theirs / ours : INFINITY;
        md << best->method << ", " << best->setting << " | " << sig(ours, 2) << " | " << sig(ratio, 2) << " | "
           << (ratio >= 100 ? "yes" : "no") << " |\n";
    }
    return md.str() + "\n";
}

// Where the time goes: RK4 at 1e-4 s with every event located against the
// same run with events at the ends of steps; the difference is the share
// of the located events (their location and settling). Each is the least
// of three runs, the two kinds taken in turn, so that the machine's other
// work (a few per cent either way) does not decide the difference.
std::string timeTable() {
    std::ostringstream md;
    md << "Where the time goes: RK4 at dt = 1e-4 s with located events against the same run with events at the "
          "ends of steps (both settle every event; only locating differs); each CPU time the least of three runs, "
          "taken in turn.\n\n"
       << "| N | stops closed by 1 s | CPU s, located | CPU s, end of step | located events' share |\n"
       << "|---:|---:|---:|---:|---:|\n";
    for (int n : {10, 100, 1000}) {
        FoldingRun located = runFoldingSetting(n, "rk4", true, 1e-4);
        FoldingRun ends = runFoldingSetting(n, "rk4", false, 1e-4);
        for (int again = 0; again < 2; ++again) {
            located.cpuSeconds = std::min(located.cpuSeconds, runFoldingSetting(n, "rk4", true, 1e-4).cpuSeconds);
            ends.cpuSeconds = std::min(ends.cpuSeconds, runFoldingSetting(n, "rk4", false, 1e-4).cpuSeconds);
        }
        const long closed = std::count_if(located.firstClosing.begin(), located.firstClosing.end(),
                                          [](double t) { return std::isfinite(t); });
        md << "| " << n << " | " << closed << " | " << sig(located.cpuSeconds, 3) << " | " << sig(ends.cpuSeconds, 3)
           << " | " << sig(100 * (1 - ends.cpuSeconds / located.cpuSeconds), 2) << " % |\n";
    }
    return md.str() + "\n";
}

}  // namespace

bool runFoldingStudy(const BenchPlan& plan, const std::filesystem::path& out, const std::filesystem::path& report) {
    // The charts go with the CSV tables (`out`), linked from the report's directory.
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    const std::string link = std::filesystem::absolute(out)
                                 .lexically_relative(std::filesystem::absolute(report).parent_path())
                                 .generic_string();
    std::string parts, csv = std::string(kFoldingColumns) + "\n";
    bool ok = true;
    for (int n : {10, 100}) {
        std::fprintf(stderr, "folding chain, N = %d\n", n);
        // The reference: Dormand-Prince at 1e-12, every event located.
        const FoldingRun reference = runFoldingReference(n, 1e-12);
        std::vector<FoldingRun> runs = runFoldingOurs(n, plan.minSeconds);
        const std::vector<FoldingRun> siconos = runFoldingSiconos(n, plan.minSeconds);
        runs.insert(runs.end(), siconos.begin(), siconos.end());
        const std::vector<FoldingRun> peers = runFoldingPeers(n, plan.minSeconds);
        runs.insert(runs.end(), peers.begin(), peers.end());
        parts += foldingPart(runs, reference, siconosReference(siconos), link);
        parts += targetsTable(runs, reference);
        ok = writeFoldingCharts(runs, reference, out) && ok;
        csv += foldingCsvRows(runs, reference);
    }
    ok = saveText(out / "folding.csv", csv) && ok;
    parts += timeTable();
    return writeFoldingReport(parts, plan.quick, report) && ok;
}

}  // namespace jl::bench
