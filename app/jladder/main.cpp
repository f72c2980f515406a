// jladder: the command-line tool. Headless: validate, run, bench, export.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace {

const char* kUsage =
    "usage: jladder <command> [options]\n"
    "\n"
    "commands:\n"
    "  validate SCENE...   check scene files; messages as file:line:column: text\n"
    "  run SCENE --until T simulate headless; JSON summary on stdout\n"
    "  bench [--quick]     measure speed against error; write tables and plots\n"
    "  export SCENE        write frames and events as CSV/JSON\n"
    "  reach               how far the first ripple travels, by ladder length\n"
    "\n"
    "'jladder <command> --help' describes each command's options.\n";

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::fputs(kUsage, stderr);
        return 2;
    }
    const std::string command = argv[1];
    const std::vector<std::string> args(argv + 2, argv + argc);
    if (command == "--help" || command == "-h" || command == "help") {
        return jl::cli::printHelp(kUsage);
    }
    if (command == "validate") return jl::cli::validate(args);
    if (command == "run") return jl::cli::run(args);
    if (command == "bench") return jl::cli::bench(args);
    if (command == "export") return jl::cli::exportFrames(args);
    if (command == "reach") return jl::cli::reach(args);
    std::fprintf(stderr, "jladder: unknown command '%s'\n", command.c_str());
    std::fputs(kUsage, stderr);
    return 2;
}
