// jladder validate: check scene files and list every problem as file:line:column: message.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"

#include <cstdio>
#include <string>
#include <vector>

namespace jl::cli {

namespace {

const char* kUsage =
    "usage: jladder validate SCENE...\n"
    "\n"
    "Checks each scene file against the format (docs/scene-format.md) and builds\n"
    "its world, without running it. Every problem is printed on stderr as\n"
    "file:line:column: message (or file: message, for what the engine finds).\n"
    "Exit status: 0 if every file is valid, 1 if any is not, 2 on a usage error.\n";

}  // namespace

int validate(const std::vector<std::string>& args) {
    std::vector<std::string> files;
    for (const std::string& arg : args) {
        if (arg == "--help" || arg == "-h") {
            return printHelp(kUsage);
        }
        if (arg.starts_with("-")) {
            std::fprintf(stderr, "jladder validate: unknown option '%s'\n", arg.c_str());
            std::fputs(kUsage, stderr);
            return 2;
        }
        files.push_back(arg);
    }
    if (files.empty()) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    int invalid = 0;
    for (const std::string& file : files) {
        const SceneLoad load = loadScene(file);
        for (const Diagnostic& d : load.errors) std::fprintf(stderr, "%s\n", d.format().c_str());
        if (!load.scene) {
            ++invalid;
            continue;
        }
        // What only the engine can tell (a pin whose points are apart at the
        // start, a ladder it cannot place): build the world, without running it.
        const Simulation::Built built = Simulation::build(*load.scene);
        for (const std::string& e : built.errors) std::fprintf(stderr, "%s: %s\n", file.c_str(), e.c_str());
        if (!built.simulation) ++invalid;
    }
    if (files.size() > 1)
        std::fprintf(invalid ? stderr : stdout, "%zu of %zu files valid\n", files.size() - invalid, files.size());
    return invalid ? 1 : 0;
}

}  // namespace jl::cli
