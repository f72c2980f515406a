// The subcommands of the command-line tool; each returns the process exit code.
#pragma once

#include <string>
#include <vector>

namespace jl::cli {

int validate(const std::vector<std::string>& args);      // validate.cpp
int run(const std::vector<std::string>& args);           // run.cpp
int bench(const std::vector<std::string>& args);         // bench.cpp
int exportFrames(const std::vector<std::string>& args);  // export.cpp
int reach(const std::vector<std::string>& args);         // reach.cpp

}  // namespace jl::cli
