// jladder export: run a scene and write its poses, energies and events.
#include "app/jladder/commands.h"
#include "app/jladder/interruption.h"
#include "app/jladder/options.h"
#include "app/jladder/recorded_run.h"
#include "jl/scene/scene_io.h"
#include "jl/scene/scene_ranges.h"

#include <cstdio>

namespace jl::cli {

int exportFrames(const std::vector<std::string>& args) {
    Options o = parse(args, {"--until", "--every", "--csv", "--energy", "--events"}, {"--help", "--quiet"});
    if (o.has("--help")) {
        return printHelp(
            "usage: jladder export SCENE [--until T] [--every DT] [--csv POSES.csv] [--energy ENERGY.csv]\n"
            "                      [--events EVENTS.json] [--quiet]\n"
            "Runs SCENE headless (to T, default the scene's duration) and writes block poses\n"
            "(t [s],block,x [m],y [m],angle [rad]), energies in J (kinetic, potential, total,\n"
            "work by the hand and drags, losses, balance) every DT (default the scene's\n"
            "frame interval) and events.\n"
            "Files are written as the run goes and replace the old ones only when it\n"
            "completes; a run that fails or is interrupted leaves them as they were and\n"
            "what it computed in FILE.partial (or, when that exists, in the temporary).\n"
            "No output may be the scene or another output. When stderr is a terminal, a\n"
            "line there shows the simulated time, the rate and the time left (not with\n"
            "--quiet); more than 1 GiB of frames to write is said before the run goes on.\n");
    }
    if (o.error.empty() && o.positional.size() != 1) o.error = "give exactly one scene file";
    RunOutputs outputs;
    if (auto f = o.get("--csv")) outputs.add(RunOutputs::Table::Poses, "--csv", *f);
    if (auto f = o.get("--energy")) outputs.add(RunOutputs::Table::Energy, "--energy", *f);
    if (auto f = o.get("--events")) outputs.add(RunOutputs::Table::Events, "--events", *f);
    if (o.error.empty() && !o.get("--csv") && !o.get("--energy") && !o.get("--events"))
        o.error = "nothing to write: give --csv, --energy or --events";
    if (o.error.empty()) o.error = outputs.clash(o.positional.front());
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder export: %s\n", o.error.c_str());
        return 2;
    }
    const std::string path = o.positional.front();
    SceneLoad load = loadScene(path);
    for (const Diagnostic& d : load.errors) std::fprintf(stderr, "%s\n", d.format().c_str());
    if (!load.scene) return 1;
    const double until = o.get("--until") ? o.number("--until", range::duration).value_or(0) : load.scene->duration;
    const double every =
        o.get("--every") ? o.number("--every", range::frameInterval).value_or(0) : load.scene->solver.frameInterval;
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder export: %s\n", o.error.c_str());
        return 2;
    }
    const auto recorded = recordRun(*load.scene, path, until, every, outputs, o.has("--quiet"), "jladder export");
    if (!recorded) return 1;
    const Recording& r = recorded->recording;
    const bool written = recorded->written;
    if (!r.failure.empty()) std::fprintf(stderr, "%s: the run failed %s\n", path.c_str(), r.failure.c_str());
    if (r.interrupted) endByInterruption();
    return r.complete() && written ? 0 : 1;
}

}  // namespace jl::cli
