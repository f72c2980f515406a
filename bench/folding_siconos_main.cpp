// The folding chain in Siconos by hand (JL_BENCH_PEERS builds only):
//   folding_siconos study N            the study's runs at N blocks, compared
//                                      with its tightest event-driven run
//   folding_siconos free N             no stops: energy kept, centres at 0.5 s
//   folding_siconos trace N TOL        event-driven, phi of each hinge every 0.01 s
//   folding_siconos ed N TOL           one event-driven run
//   folding_siconos mj N THETA STEP    one Moreau-Jean run
#include "bench/folding_siconos.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

using namespace jl::bench;

namespace {

// Largest block-centre distance (m) between two runs over the sample times.
double distance(const FoldingRun& a, const FoldingRun& b) {
    double d = 0;
    for (size_t s = 0; s < a.centres.size(); ++s) {
        if (a.centres[s].size() != b.centres[s].size() || a.centres[s].empty()) return NAN;
        for (size_t i = 0; i < a.centres[s].size(); ++i) d = std::max(d, (a.centres[s][i] - b.centres[s][i]).norm());
    }
    return d;
}

void print(const FoldingRun& r, const FoldingRun* reference) {
    std::printf("%s %s, %s, N = %d: %.3f s CPU, %s%s\n", r.engine.c_str(), r.method.c_str(), r.setting.c_str(),
                r.blocks, r.cpuSeconds, r.finished ? "finished " : "FAILED: ", r.why.c_str());
    std::printf("  dissipated (J) at 0.25/0.5/1 s: %.6e %.6e %.6e\n", r.dissipated[0], r.dissipated[1],
                r.dissipated[2]);
    std::printf("  first closing (s) per hinge:");
    for (double t : r.firstClosing) std::printf(" %.6f", t);
    std::printf("\n");
    for (size_t s = 0; s < r.centres.size(); ++s)
        if (!r.centres[s].empty())
            std::printf("  tip centre at %.2f s: (%.6f, %.6f)\n", folding::kSampleTimes[s], r.centres[s].back().x(),
                        r.centres[s].back().y());
    if (reference) {
        double closing = 0;
        int unmatched = 0;  // hinges that close in one run only
        for (size_t i = 0; i < r.firstClosing.size(); ++i)
            if (std::isnan(r.firstClosing[i]) != std::isnan(reference->firstClosing[i]))
                ++unmatched;
            else if (!std::isnan(r.firstClosing[i]))
                closing = std::max(closing, std::abs(r.firstClosing[i] - reference->firstClosing[i]));
        std::printf(
            "  from the reference: centres %.3e m, first closings %.3e s (%d hinges close in one run only), "
            "dissipated at 1 s %.3e J\n",
            distance(r, *reference), closing, unmatched, r.dissipated[2] - reference->dissipated[2]);
    }
}

}  // namespace

int main(int argc, char** argv) {
    const std::string mode = argc > 2 ? argv[1] : "";
    const int n = argc > 2 ? std::atoi(argv[2]) : 0;
    std::printf("%s\n", siconosVersion().c_str());
    SiconosFolding how;
    if (mode == "study" && n > 1) {
        const std::vector<FoldingRun> runs = runFoldingSiconos(n, 0.05);
        const FoldingRun* reference = nullptr;
        for (const FoldingRun& r : runs)
            if (r.finished && r.method.rfind("event-driven", 0) == 0) reference = &r;  // the tightest
        if (reference) std::printf("reference: %s\n", reference->setting.c_str());
        for (const FoldingRun& r : runs) print(r, reference);
        return 0;
    }
    if (mode == "free" && n > 1) {
        how.stops = false;
        how.eventDriven = true;
        how.tolerance = 1e-10;
        const FoldingRun ed = runFoldingSiconos(n, how);
        print(ed, nullptr);
        how.eventDriven = false;
        how.step = 1e-4;
        print(runFoldingSiconos(n, how), &ed);
        for (const jl::Vec2& c : ed.centres[1]) std::printf("%.9f %.9f\n", c.x(), c.y());
        return 0;
    }
    if ((mode == "trace" || mode == "ed") && n > 1 && argc > 3) {
        how.eventDriven = true;
        how.tolerance = std::atof(argv[3]);
        if (mode == "trace") how.trace = stdout;
        print(runFoldingSiconos(n, how), nullptr);
        return 0;
    }
    if (mode == "mj" && n > 1 && argc > 4) {
        how.theta = std::atof(argv[3]);
        how.step = std::atof(argv[4]);
        print(runFoldingSiconos(n, how), nullptr);
        return 0;
    }
    std::fprintf(stderr, "usage: folding_siconos study N | free N | trace N TOL | ed N TOL | mj N THETA STEP\n");
    return 2;
}
