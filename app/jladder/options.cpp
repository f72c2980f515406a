#include "app/jladder/options.h"

#include "jl/base/output_name.h"
#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_ranges.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace jl::cli {

bool Options::has(const std::string& flag) const { return std::find(flags.begin(), flags.end(), flag) != flags.end(); }

std::optional<std::string> Options::get(const std::string& name) const {
    auto it = named.find(name);
    if (it == named.end()) return std::nullopt;
    return it->second;
}

std::optional<double> Options::number(const std::string& name, Bound bound) {
    const auto text = get(name);
    if (!text) return std::nullopt;
    const auto x = parseNumber(*text);
    if (x && bound.contains(*x)) return x;
    error = name + " needs " + bound.describe() + ", not '" + *text + "'";
    return std::nullopt;
}

std::optional<long long> Options::count(const std::string& name, long long lo, long long hi) {
    const auto text = get(name);
    if (!text) return std::nullopt;
    if (const auto n = wholeNumber(*text); n && *n >= lo && *n <= hi) return n;
    error = name + " takes a whole number from " + std::to_string(lo) + " to " + std::to_string(hi) + ", not '" +
            *text + "'";
    return std::nullopt;
}

std::optional<long long> wholeNumber(const std::string& text) {
    long long n = 0;
    const char* end = text.data() + text.size();
    const auto [at, error] = std::from_chars(text.data(), end, n);
    if (text.empty() || error != std::errc{} || at != end) return std::nullopt;
    return n;
}

Options parse(const std::vector<std::string>& args, const std::vector<std::string>& valued,
              const std::vector<std::string>& flags) {
    Options o;
    for (size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a.rfind("--", 0) != 0) {
            o.positional.push_back(a);
        } else if (std::find(valued.begin(), valued.end(), a) != valued.end()) {
            if (i + 1 >= args.size()) {
                o.error = a + " needs a value";
                return o;
            }
            o.named[a] = args[++i];
        } else if (std::find(flags.begin(), flags.end(), a) != flags.end()) {
            o.flags.push_back(a);
        } else {
            o.error = "unknown option " + a;
            return o;
        }
    }
    return o;
}

namespace {

// A word of the scene files' table (jl/scene/scene_fields.h); on the
// command line a dash may stand for an underscore (end-of-step).
template <class E>
bool chooseWord(Options& o, const char* option, const char* what, std::span<const Word<E>> words, E& out) {
    auto given = o.get(option);
    if (!given) return true;
    std::string word = *given;
    std::replace(word.begin(), word.end(), '-', '_');
    if (auto value = valueOf(words, word)) {
        out = *value;
        return true;
    }
    o.error = std::string("unknown ") + what + " '" + *given + "' (" + wordList(words) + ")";
    return false;
}

}  // namespace

bool applySolverOptions(Options& o, SolverSpec& solver) {
    if (!chooseWord<Integrator>(o, "--integrator", "integrator", kIntegrators, solver.integrator)) return false;
    if (!chooseWord<EventPolicy>(o, "--event-policy", "event policy", kEventPolicies, solver.events)) return false;
    if (auto h = o.number("--step", range::step)) solver.step = *h;
    if (auto tol = o.number("--tolerance", range::tolerance)) solver.tolerance = *tol;
    return o.error.empty();
}

int printHelp(const std::string& text) {
    if (std::fputs(text.c_str(), stdout) >= 0 && std::fflush(stdout) == 0) return 0;
    std::fprintf(stderr, "jladder: cannot write the help: %s\n", std::strerror(errno));
    return 1;
}

bool sameFile(const std::string& a, const std::string& b) {
    return sameOutput(resolveOutputName(a), resolveOutputName(b));
}

std::string unresolvedOutput(const std::string& option, const std::string& path) {
    const OutputName name = resolveOutputName(path);
    if (!name.error) return {};
    return option + " " + path + ": cannot tell which file this names (" + std::strerror(name.error) +
           "), so it is not written";
}

}  // namespace jl::cli
