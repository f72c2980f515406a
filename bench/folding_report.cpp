// The section "Folding chain" of docs/performance.md, from the runs of
// every engine and the two references.
#include "bench/folding_report.h"

#include "bench/chart.h"
#include "bench/folding_peers.h"
#include "bench/folding_siconos.h"
#include "bench/report_text.h"
#include "jl/base/csv_writer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace jl::bench {

namespace {

using folding::kSampleTimes;

// The largest distance between the same block's centres; NaN if the two do
// not hold the same blocks.
double centreDistance(const std::vector<Vec2>& a, const std::vector<Vec2>& b) {
    if (a.empty() || a.size() != b.size()) return NAN;
    double d = 0;
    for (size_t i = 0; i < a.size(); ++i) d = std::max(d, (a[i] - b[i]).norm());
    return d;
}

// "t = 0.25 / 0.5 / 1 s"-style cells: one value a sample time.
std::string perSample(const FoldingError::PerSample& v, int digits) {
    std::string s;
    for (size_t k = 0; k < v.size(); ++k) s += (k ? " / " : "") + sig(v[k], digits);
    return s;
}

std::string closingCell(const FoldingError& e) {
    std::string s;
    for (size_t k = 0; k < kSampleTimes.size(); ++k) {
        s += (k ? " / " : "") + sig(e.closing[k], 2);
        if (e.missing[k] || e.extra[k])
            s += " (" + (e.missing[k] ? std::to_string(e.missing[k]) + " missing" : std::string()) +
                 (e.missing[k] && e.extra[k] ? ", " : "") +
                 (e.extra[k] ? std::to_string(e.extra[k]) + " extra" : std::string()) + ")";
    }
    return s;
}

std::string times() {
    std::string s;
    for (size_t k = 0; k < kSampleTimes.size(); ++k) s += (k ? " / " : "") + sig(kSampleTimes[k], 3);
    return s + " s";
}

// A peer's failure in a line: Siconos's exceptions carry their message
// after "message*] = ".
std::string shortReason(const std::string& why) {
    const std::string key = "message*] = ";
    const size_t at = why.find(key);
    std::string s = at == std::string::npos ? why : why.substr(at + key.size());
    const size_t close = s.find("  )");
    if (close != std::string::npos) s.erase(close, 3);
    return s.size() > 240 ? s.substr(0, 240) + "..." : s;
}

std::string describe(const FoldingRun& r) { return r.engine + ", " + r.method + ", " + r.setting; }

// What the reference itself shows: its energy and when its hinges close.
std::string referenceValues(const FoldingRun& r) {
    std::ostringstream md;
    md << "dissipated " << perSample(r.dissipated, 3) << " J at " << times() << "; first closings (hinge: s):";
    std::vector<std::pair<double, size_t>> closed;
    for (size_t i = 0; i < r.firstClosing.size(); ++i)
        if (std::isfinite(r.firstClosing[i])) closed.push_back({r.firstClosing[i], i + 1});
    std::sort(closed.begin(), closed.end());
    for (auto [t, hinge] : closed) md << " " << hinge << ": " << sig(t, 5) << ";";
    if (closed.empty()) md << " none;";
    md << " " << r.firstClosing.size() - closed.size() << " of " << r.firstClosing.size() << " hinges never close";
    return md.str();
}

std::string referencesPart(const FoldingRun& ours, const FoldingRun* siconos) {
    std::ostringstream md;
    md << "**Reference**: " << describe(ours) << ": " << referenceValues(ours) << ".\n\n";
    if (!siconos) {
        md << "**Check of the reference**: the Siconos runs are missing from this report, so nothing independent "
              "checks it; the errors below are against this engine alone.\n\n";
        return md.str();
    }
    const FoldingError e = foldingError(*siconos, ours);
    md << "**Check of the reference** against " << describe(*siconos) << ": " << referenceValues(*siconos);
    if (!siconos->finished)
        md << " (it stopped before 1 s: " << shortReason(siconos->why) << "; a dash is a time it did not reach)";
    md << ". Between the two, at " << times() << ": largest block-centre distance " << perSample(e.centre, 2)
       << " m; dissipated energy differs by " << perSample(e.dissipated, 2) << " J; first closings differ by at most "
       << closingCell(e) << " s.\n\n";
    return md.str();
}

std::string runsTable(const std::vector<FoldingRun>& runs, const FoldingRun& ours) {
    std::ostringstream md;
    md << "| engine | method | stop model | setting | CPU s | block centres (m) | dissipated energy (J) | first "
          "closings (s) |\n"
       << "|---|---|---|---|---:|---|---|---|\n";
    std::string previous;
    for (const FoldingRun& r : runs) {
        // A series' stop model once, in its first row.
        const std::string series = r.engine + r.method;
        md << "| " << r.engine << " | " << r.method << " | " << (series == previous ? "" : r.stopModel) << " | "
           << r.setting << " | " << sig(r.cpuSeconds, 3) << " | ";
        previous = series;
        if (!r.finished) {
            md << "failed: " << shortReason(r.why) << " | | |\n";
            continue;
        }
        const FoldingError e = foldingError(r, ours);
        md << perSample(e.centre, 2) << " | " << perSample(e.dissipated, 2) << " | " << closingCell(e) << " |\n";
    }
    return md.str();
}

}  // namespace

FoldingError foldingError(const FoldingRun& run, const FoldingRun& reference) {
    FoldingError e;
    for (size_t k = 0; k < kSampleTimes.size(); ++k) {
        e.centre[k] = centreDistance(run.centres[k], reference.centres[k]);
        e.dissipated[k] = std::abs(run.dissipated[k] - reference.dissipated[k]);
        e.closing[k] = NAN;
        const size_t hinges = std::min(run.firstClosing.size(), reference.firstClosing.size());
        for (size_t i = 0; i < hinges; ++i) {
            const double a = run.firstClosing[i], b = reference.firstClosing[i];
            if (std::isfinite(a) && std::isfinite(b)) {
                if (std::min(a, b) <= kSampleTimes[k])
                    e.closing[k] = std::isnan(e.closing[k]) ? std::abs(a - b) : std::max(e.closing[k], std::abs(a - b));
            } else if (std::isfinite(b) && b <= kSampleTimes[k]) {
                ++e.missing[k];
            } else if (std::isfinite(a) && a <= kSampleTimes[k]) {
                ++e.extra[k];
            }
        }
    }
    return e;
}

std::string foldingPart(const std::vector<FoldingRun>& runs, const FoldingRun& oursRef, const FoldingRun* siconosRef,
                        const std::string& charts) {
    const std::string name =
        (charts.empty() || charts == "." ? "" : charts + "/") + "folding" + std::to_string(oursRef.blocks);
    std::ostringstream md;
    md << "### Folding chain, N = " << oursRef.blocks << "\n\n"
       << referencesPart(oursRef, siconosRef) << "![block centres at 1 s](" << name << "_centre.svg)\n\n"
       << "![dissipated energy at 1 s](" << name << "_dissipated.svg)\n\n"
       << "![first closings](" << name << "_closing.svg)\n\n"
       << "Errors against the reference at " << times()
       << "; first closings: the largest difference over the hinges that both close, one of them by that time "
          "(missing: the reference closes the hinge and the run never does; extra: the reverse).\n\n"
       << runsTable(runs, oursRef) << "\n";
    return md.str();
}

std::string foldingCsvRows(const std::vector<FoldingRun>& runs, const FoldingRun& oursRef) {
    std::ostringstream csv;
    CsvWriter w(csv, 6);
    for (const FoldingRun& r : runs) {
        const FoldingError e = foldingError(r, oursRef);
        const size_t last = kSampleTimes.size() - 1;
        w.row(r.blocks, r.engine, r.method, r.setting, r.stopModel, r.cpuSeconds, r.finished ? 1 : 0, e.centre[0],
              e.centre[1], e.centre[2], e.dissipated[0], e.dissipated[1], e.dissipated[2], e.closing[0], e.closing[1],
              e.closing[2], e.missing[last], e.extra[last], r.why);
    }
    return csv.str();
}

bool writeFoldingCharts(const std::vector<FoldingRun>& runs, const FoldingRun& oursRef,
                        const std::filesystem::path& dir) {
    const std::string n = std::to_string(oursRef.blocks);
    const std::string x = "CPU seconds for the run to 1 s";
    Chart centre{"Folding chain, N = " + n + ": block centres at t = 1 s", x, "largest block-centre error (m)", {}};
    Chart energy{"Folding chain, N = " + n + ": energy dissipated by t = 1 s", x, "|dissipated - reference| (J)", {}};
    Chart closing{
        "Folding chain, N = " + n + ": first closing of each hinge", x, "largest first-closing error (s)", {}};
    std::map<std::string, size_t> index;
    const size_t last = kSampleTimes.size() - 1;
    for (const FoldingRun& r : runs) {
        if (!r.finished) continue;
        const std::string series = r.engine + " " + r.method;
        if (!index.count(series)) {
            index[series] = centre.series.size();
            for (Chart* c : {&centre, &energy, &closing}) c->series.push_back({series, {}, false});
        }
        const FoldingError e = foldingError(r, oursRef);
        const size_t s = index[series];
        centre.series[s].points.push_back({r.cpuSeconds, e.centre[last]});
        energy.series[s].points.push_back({r.cpuSeconds, e.dissipated[last]});
        closing.series[s].points.push_back({r.cpuSeconds, e.closing[last]});
    }
    const std::string name = "folding" + n;
    const bool a = writeChart(centre, dir, name + "_centre"), b = writeChart(energy, dir, name + "_dissipated");
    return writeChart(closing, dir, name + "_closing") && a && b;
}

std::string foldingSection(const std::string& parts, bool quick, bool& ok) {
    return filled("folding",
                  {{"min_time", quick ? "5 ms" : "50 ms"},
                   {"peers", foldingPeerNote() + "; " + siconosVersion()},
                   {"parts", parts}},
                  ok);
}

bool writeFoldingReport(const std::string& parts, bool quick, const std::filesystem::path& report) {
    bool ok = true;
    const std::string text = foldingSection(parts, quick, ok);
    return writeSection("folding", quick, report, text, ok);
}

}  // namespace jl::bench
