// jladder run: simulate a scene headless and report in JSON.
#include "app/jladder/commands.h"
#include "app/jladder/interruption.h"
#include "app/jladder/options.h"
#include "app/jladder/recorded_run.h"
#include "app/jladder/summary.h"
#include "jl/scene/scene_io.h"
#include "jl/scene/scene_ranges.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>

namespace jl::cli {

namespace {

const char* kRunHelp =
    "usage: jladder run SCENE --until T [options]\n"
    "\n"
    "Simulates SCENE from t = 0 to T seconds without a display and prints a JSON\n"
    "summary on stdout: simulated time, steps, events, energy at start and end,\n"
    "the worst energy-balance error, the largest constraint residual, wall time.\n"
    "\n"
    "options:\n"
    "  --events FILE        write the events as JSON [{\"t\",\"hinge\",\"event\",\"corner\"}]\n"
    "  --frames FILE        write block centres as CSV \"t [s],block,x [m],y [m],angle [rad]\"\n"
    "  --every DT           interval of --frames rows (default: the scene's frame interval)\n"
    "  --integrator NAME    explicit_euler | symplectic_euler | rk4 | dormand_prince45 | verner65 |\n"
    "                       rosenbrock_w\n"
    "  --step DT            fixed step (s)\n"
    "  --tolerance TOL      adaptive integrator's tolerance\n"
    "  --event-policy P     located | end-of-step\n"
    "  --quiet              no progress line: when stderr is a terminal, the run shows\n"
    "                       there its simulated time, rate and the time it has left\n"
    "\n"
    "A run that will write more than 1 GiB of frames says so before it goes on; one\n"
    "that will take far longer than the time it simulates says so a few seconds in,\n"
    "with its step and the stiffest mode of the motion that sets it.\n"
    "Files are written as the run goes, through a temporary beside each, and replace\n"
    "the old ones only when the run completes; a run that fails or is interrupted\n"
    "(Ctrl-C) leaves them as they were and what it computed in FILE.partial, or,\n"
    "when a file of that name exists, in the temporary FILE.partial-XXXXXX. No\n"
    "output may be the scene file or another output, and a name that cannot be\n"
    "resolved (a loop or chain of more than 40 symbolic links) is refused.\n"
    "exit status: 0 on success, 1 if the scene is invalid, the run failed or an output\n"
    "could not be written, 2 on bad arguments; killed by the signal if interrupted\n";

}  // namespace

int run(const std::vector<std::string>& args) {
    Options o = parse(
        args, {"--until", "--events", "--frames", "--every", "--integrator", "--step", "--tolerance", "--event-policy"},
        {"--help", "--quiet"});
    if (o.has("--help")) {
        return printHelp(kRunHelp);
    }
    const auto until = o.number("--until", range::duration);
    if (o.error.empty() && o.positional.size() != 1) o.error = "give exactly one scene file";
    if (o.error.empty() && !until) o.error = "--until T is required";
    RunOutputs outputs;
    if (auto f = o.get("--events")) outputs.add(RunOutputs::Table::Events, "--events", *f);
    if (auto f = o.get("--frames")) outputs.add(RunOutputs::Table::Poses, "--frames", *f);
    if (o.error.empty()) o.error = outputs.clash(o.positional.front());
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder run: %s\n", o.error.c_str());
        return 2;
    }
    const std::string path = o.positional.front();
    SceneLoad load = loadScene(path);
    for (const Diagnostic& d : load.errors) std::fprintf(stderr, "%s\n", d.format().c_str());
    if (!load.scene) return 1;
    if (!applySolverOptions(o, load.scene->solver)) {
        std::fprintf(stderr, "jladder run: %s\n", o.error.c_str());
        return 2;
    }
    const double every =
        o.get("--every") ? o.number("--every", range::frameInterval).value_or(0) : load.scene->solver.frameInterval;
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder run: %s\n", o.error.c_str());
        return 2;
    }
    const auto recorded = recordRun(*load.scene, path, *until, every, outputs, o.has("--quiet"), "jladder run");
    if (!recorded) return 1;
    const Recording& r = recorded->recording;
    const bool written = recorded->written;
    std::cout << summaryJson(r, path) << '\n';
    std::cout.flush();
    const bool summaryWritten = std::cout.good() && std::fflush(stdout) == 0;
    if (!summaryWritten) std::fprintf(stderr, "jladder run: cannot write the summary: %s\n", std::strerror(errno));
    if (!r.failure.empty()) std::fprintf(stderr, "%s: the run failed %s\n", path.c_str(), r.failure.c_str());
    if (r.interrupted) endByInterruption();
    return r.complete() && written && summaryWritten ? 0 : 1;
}

}  // namespace jl::cli
