// jladder export: run a scene and write its poses, energies and events.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "app/jladder/recording.h"
#include "core/scene_io.h"

#include <cstdio>

namespace jl::cli {

int exportFrames(const std::vector<std::string>& args) {
    Options o = parse(args, {"--until", "--every", "--csv", "--energy", "--events"}, {"--help"});
    if (o.has("--help")) {
        std::fputs("usage: jladder export SCENE [--until T] [--every DT] [--csv POSES.csv] [--energy ENERGY.csv]\n"
                   "                      [--events EVENTS.json]\n"
                   "Runs SCENE headless (to T, default the scene's duration) and writes block poses\n"
                   "(t,block,x,y,theta), energies (kinetic, potential, total, work by the hand and\n"
                   "drags, losses, balance) every DT (default the scene's frame interval) and events.\n",
                   stdout);
        return 0;
    }
    if (o.error.empty() && o.positional.size() != 1) o.error = "give exactly one scene file";
    if (o.error.empty() && !o.get("--csv") && !o.get("--energy") && !o.get("--events"))
        o.error = "nothing to write: give --csv, --energy or --events";
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder export: %s\n", o.error.c_str());
        return 2;
    }
    SceneLoad load = loadScene(o.positional.front());
    for (const Diagnostic& d : load.errors) std::fprintf(stderr, "%s\n", d.format().c_str());
    if (!load.scene) return 1;
    const double until = o.get("--until") ? o.number("--until").value_or(0) : load.scene->duration;
    const double every = o.get("--every") ? o.number("--every").value_or(0) : load.scene->solver.frameInterval;
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder export: %s\n", o.error.c_str());
        return 2;
    }
    Simulation::Built built = Simulation::build(*load.scene);
    for (const std::string& e : built.errors) std::fprintf(stderr, "%s: %s\n", o.positional.front().c_str(), e.c_str());
    if (!built.simulation) return 1;
    const Recording r = record(*built.simulation, until, every, true);
    std::string error;
    bool ok = r.failure.empty();
    if (auto f = o.get("--csv")) ok = writePosesCsv(r, *f, error) && ok;
    if (auto f = o.get("--energy")) ok = writeEnergyCsv(r, *f, error) && ok;
    if (auto f = o.get("--events")) ok = writeEventsJson(r, *f, error) && ok;
    if (!error.empty()) std::fprintf(stderr, "jladder export: %s\n", error.c_str());
    if (!r.failure.empty()) std::fprintf(stderr, "the run failed %s\n", r.failure.c_str());
    return ok ? 0 : 1;
}

}  // namespace jl::cli
