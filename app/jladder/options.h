// Command-line options of the form --name value, and the solver overrides
// that run, export and bench share.
#pragma once

#include "jl/scene/bound.h"
#include "jl/scene/scene.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace jl::cli {

struct Options {
    std::vector<std::string> positional;
    std::map<std::string, std::string> named;  // "--until" -> "3"
    std::vector<std::string> flags;            // "--quick"
    std::string error;                         // non-empty: the arguments are wrong

    bool has(const std::string& flag) const;
    std::optional<std::string> get(const std::string& name) const;
    // A number within `bound` (jl/scene/scene_ranges.h: the same as the scene
    // file's), or an error message set and nullopt.
    std::optional<double> number(const std::string& name, Bound bound);
    // A whole number from `lo` to `hi`, written as one ("2x", "1e3" and
    // "2.0" are not), or an error message set and nullopt.
    std::optional<long long> count(const std::string& name, long long lo, long long hi);
};

// `valued` lists the options that take a value; anything else starting
// with -- is a flag if listed in `flags`, else an error.
Options parse(const std::vector<std::string>& args, const std::vector<std::string>& valued,
              const std::vector<std::string>& flags);

// Applies --integrator, --step, --tolerance, --event-policy to the scene.
bool applySolverOptions(Options& o, SolverSpec& solver);

// Two names for one file: the same file (through links and hard links), or,
// for files not made yet, the same name once links are followed; resolved
// as the writer resolves them (jl/base/output_name.h).
bool sameFile(const std::string& a, const std::string& b);
// Why the output `path` given to `option` is refused because no one can say
// which file it names (a chain of more than 40 links, a loop), or "".
std::string unresolvedOutput(const std::string& option, const std::string& path);

// The whole text as a decimal integer ("12", "-3"; not "12x", "1e3",
// "1.0", " 12"), or nullopt.
std::optional<long long> wholeNumber(const std::string& text);

// Help on stdout: 0, or 1 and a message when it could not be written (a
// full disk, a closed pipe); help that went nowhere is not a success.
int printHelp(const std::string& text);

}  // namespace jl::cli
