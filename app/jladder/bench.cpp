// jladder bench: the command of the benchmark (bench/run.h): its options,
// and the JSON line it ends with.
#include "app/jladder/commands.h"
#include "app/jladder/json_text.h"
#include "app/jladder/options.h"
#include "app/jladder/progress.h"
#include "bench/run.h"

#include <cstdio>

namespace jl::cli {

namespace {

const char* kHelp =
    "usage: jladder bench [--quick] [--out DIR] [--report FILE] [--examples DIR]\n"
    "                     [--only stability|models|events|examples|contacts|folding|long_ladder] [--quiet]\n"
    "Measures cost (CPU seconds per simulated second) against error for every\n"
    "integrator and event policy on the physical pendulum, the falling chain\n"
    "(N = 10, 100, 1,000; against an independent reduced-coordinate reference)\n"
    "and the ladder cascade; cost per block-step for N = 10 .. 100,000; a long\n"
    "ladder (1,000, 10,000 and 100,000 blocks) with RK4, the linearly\n"
    "implicit Rosenbrock-W and Verner's pair, and the classic design with\n"
    "10,000 blocks for 3 s (not in --quick); the stability limit of long\n"
    "ladders (omega_max of the hanging ladder, the step limit it predicts,\n"
    "the largest RK4 step that runs); cascades with locked pairs merged into\n"
    "one body against welded pairs; the CPU cost of an event on ladders of\n"
    "12 .. 10,000 thin blocks;\n"
    "every scene of --examples DIR (default: examples, relative to the current\n"
    "directory) at its own settings for 3 s (quick: 1 s), and long-ladder.yaml\n"
    "with 1,000 blocks (not in --quick); block contacts: the broad phase per\n"
    "block on 12 .. 100,000 blocks and every example with contact off and on;\n"
    "and, if built with -DJL_BENCH_PEERS=ON, MuJoCo, Box2D and\n"
    "Bullet on the same chains. Writes DIR/*.csv, DIR/*.svg\n"
    "(default DIR: docs/bench) and FILE (default docs/performance.md).\n"
    "--quick: fewer sizes and steps; fits in CI (under a minute).\n"
    "--only stability|models|events|examples|contacts|folding|long_ladder:\n"
    "that study alone; FILE (default DIR/NAME.md: DIR/stability.md and so on)\n"
    "gets its section only.\n"
    "Each study's name goes to stderr as it starts; when stderr is a terminal,\n"
    "with how many studies are done and the time so far (not with --quiet).\n";

}  // namespace

int bench(const std::vector<std::string>& args) {
    Options o = parse(args, {"--out", "--report", "--only", "--examples"}, {"--quick", "--help", "--quiet"});
    if (o.has("--help")) {
        return printHelp(kHelp);
    }
    const std::string only = o.get("--only").value_or("");
    if (o.error.empty() && !only.empty() && only != "stability" && only != "models" && only != "events" &&
        only != "examples" && only != "contacts" && only != "folding" && only != "long_ladder")
        o.error =
            "--only takes 'stability', 'models', 'events', 'examples', 'contacts', 'folding' or 'long_ladder', not '" +
            only + "'";
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder bench: %s\n", o.error.c_str());
        return 2;
    }
    bench::BenchRequest request;
    request.quick = o.has("--quick");
    request.only = only;
    request.out = o.get("--out").value_or("docs/bench");
    request.report =
        o.get("--report")
            .value_or(!only.empty() ? (request.out / (only + ".md")).string() : std::string("docs/performance.md"));
    request.examples = o.get("--examples").value_or("examples");
    // On a terminal each study's name comes with how far the benchmark is.
    ProgressLine progress(!o.has("--quiet"));
    if (progress.shown())
        request.studyStarts = [&](const std::string& study, int done, int total) {
            progress.stage(study, done, total);
        };
    const bool ok = bench::runBench(request);
    const Json line{{"out", request.out.string()}, {"report", request.report.string()}, {"ok", ok}};
    std::printf("%s\n", jsonText(line).c_str());
    return ok ? 0 : 1;
}

}  // namespace jl::cli
