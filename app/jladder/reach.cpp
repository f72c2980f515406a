// jladder reach: how far the first ripple travels (docs/model.md section 15).
// Without axes, the fixed table of designs that section quotes; with one or
// two axes (--blocks 6:50:2 --thickness 2mm:12mm:1mm ...), a design map over
// them (jl/design/ripple_map.h), as CSV and an SVG heat map.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "app/jladder/progress.h"
#include "jl/base/decimal.h"
#include "jl/base/output_file.h"
#include "jl/base/xml_text.h"
#include "jl/design/design_check.h"
#include "jl/design/map_share.h"
#include "jl/design/ripple_map.h"
#include "jl/scene/scene_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace jl::cli {

namespace {

// All the files or none: each is written to its temporary first, and only
// when every one has all its bytes are they renamed into place (a full disk
// shows at the writes, so a failed second file leaves the first as it was).
bool saveAll(const std::vector<std::pair<std::string, std::string>>& files) {
    std::vector<OutputFile> out(files.size());
    auto failed = [&](std::size_t i) {
        std::fprintf(stderr, "jladder reach: %s: %s\n", files[i].first.c_str(), out[i].error().c_str());
        return false;
    };
    for (std::size_t i = 0; i < files.size(); ++i)
        if (!out[i].open(files[i].first) || !out[i].write(files[i].second) || !out[i].flush()) return failed(i);
    for (std::size_t i = 0; i < files.size(); ++i)
        if (!out[i].commit()) return failed(i);
    return true;
}

bool save(const std::string& path, const std::string& text) {
    const std::string error = writeWholeFile(path, text);
    if (error.empty()) return true;
    std::fprintf(stderr, "jladder reach: %s: %s\n", path.c_str(), error.c_str());
    return false;
}

const char* kHelp =
    "usage: jladder reach [--out FILE] [--whole-runs]\n"
    "       jladder reach --PARAMETER FROM:TO:STEP [--PARAMETER FROM:TO:STEP] [--scene BASE.yaml]\n"
    "                     [--jobs N] [--cells K/N] [--csv FILE] [--svg FILE] [--title TEXT] [--quiet]\n"
    "                     [--whole-runs]\n"
    "       jladder reach --merge SHARE.csv... [--csv FILE] [--svg FILE] [--title TEXT]\n"
    "Without axes: turns the top block of ladders of 6, 8, 12, 25 and 50 blocks (60 x 12 mm)\n"
    "and of the thinner designs docs/model.md section 15 quotes, and tabulates how many\n"
    "hinges the first ripple flips, every hinge event of the run, and the chatter measure\n"
    "(the most quick cycles of one hinge in a row: a release and a close within 1 ms), in\n"
    "Markdown (stdout, or FILE).\n"
    "With axes: a design map. PARAMETER is one of blocks, thickness, length, width (lengths\n"
    "in m, or with mm or cm), density (kg/m^3), hinge_damping (N m s), turn_duration\n"
    "(s, or ms); one axis gives a line, two a map. An axis has at most 200 values, each\n"
    "within the range a scene file allows for it (docs/scene-format.md; blocks: a whole\n"
    "number from 2 to 100000; turn_duration: 1 ms to 1e5 s), and each design must be a\n"
    "valid scene; else nothing runs (exit 2). Every cell is a simulation of the first\n"
    "ripple on BASE (default: 6 blocks of 60 x 12 x 45 mm, density 600, block 0 held and\n"
    "turned half a turn from 0.2 s over 0.3 s), run on N threads (default: every core).\n"
    "A run stops as soon as its reach is settled (docs/ripple-reach.md): its other counts\n"
    "(flips elsewhere, events, chatter) count up to that instant, which the CSV gives\n"
    "with why it stopped. --whole-runs runs every design for its whole time instead.\n"
    "Writes CSV (stdout, or --csv FILE) and an SVG heat map (--svg FILE); the same command\n"
    "gives the same bytes whatever N. Files are replaced only once both are written whole;\n"
    "neither may be the --scene file. When stderr is a terminal, a line there shows the\n"
    "cells done and the time left (not with --quiet).\n"
    "--cells K/N computes only the K-th of N equal shares of the cells (for N machines)\n"
    "and writes them as CSV naming the map; --merge joins every share of one map into the\n"
    "CSV and SVG the whole map gives on one machine, byte for byte, and refuses shares of\n"
    "different maps and a share missing or given twice.\n";

// Standard output written and flushed, or a message: a full disk or a closed
// pipe is a failed run, not a silent one.
bool print(const std::string& text) {
    if (std::fputs(text.c_str(), stdout) >= 0 && std::fflush(stdout) == 0) return true;
    std::fprintf(stderr, "jladder reach: cannot write to standard output: %s\n", std::strerror(errno));
    return false;
}

// The fixed table of the designs docs/model.md section 15 quotes.
int table(const std::optional<std::string>& out, RippleStop stop) {
    struct Case {
        int n;
        double t;
    };
    const std::vector<Case> cases = {{6, 0.012},  {8, 0.012},  {12, 0.012}, {25, 0.012},
                                     {50, 0.012}, {12, 0.006}, {25, 0.004}, {25, 0.003}};
    std::string text =
        "| blocks | thickness (mm) | hinges the first ripple flips | mean time between flips | other hinges flipped | "
        "hinge events | most quick cycles of one hinge in a row | failure |\n"
        "|---:|---:|---|---:|---:|---:|---:|---|\n";
    for (const Case& c : cases) {
        const RippleReach r =
            firstRippleReach(turnedLadder(c.n, c.t), nullptr, std::numeric_limits<double>::infinity(), stop);
        std::ostringstream s;
        s.precision(3);
        s << "| " << c.n << " | " << c.t * 1000 << " | " << r.reached << " of " << r.hinges << " | ";
        if (r.flipTimes.size() >= 2) s << r.meanTimeBetweenFlips << " s";
        s << " | " << r.flipsElsewhere << " | " << r.events << " in " << r.until << " s | " << r.quickRow << " | "
          << r.failure << " |\n";
        std::fputs(s.str().c_str(), stderr);
        text += s.str();
    }
    if (!out) return print(text) ? 0 : 1;
    return save(*out, text) ? 0 : 1;
}

// "12mm" -> 0.012: a number, then the unit the parameter allows (none: SI).
// The unit shifts the number's decimal point (jl/base/decimal.h): 9mm is
// the 0.009 a scene file holds, where 9 * 0.001 is 0.009000000000000001.
std::optional<double> quantity(const std::string& text, DesignParameter p, std::string& error) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    const std::string unit(end);
    std::optional<int> power;  // of ten
    const bool length = p == DesignParameter::Thickness || p == DesignParameter::Length || p == DesignParameter::Width;
    if (unit.empty())
        power = 0;
    else if (length && unit == "mm")
        power = -3;
    else if (length && unit == "cm")
        power = -2;
    else if (length && unit == "m")
        power = 0;
    else if (p == DesignParameter::TurnDuration && unit == "ms")
        power = -3;
    else if (p == DesignParameter::TurnDuration && unit == "s")
        power = 0;
    const std::optional<Decimal> typed = shortestDecimal(v);
    if (end == text.c_str() || !power || !typed) {
        error = "'" + text + "' is not a value of " + std::string(describe(p).word);
        return std::nullopt;
    }
    return nearestDouble({typed->digits, typed->exponent + *power});
}

// "6:50:2" -> an axis, as written; its values are checked against the
// scene format's ranges once the base scene is known (jl/design/design_check.h).
std::optional<DesignAxis> axis(const std::string& text, DesignParameter p, std::string& error) {
    const size_t a = text.find(':'), b = a == std::string::npos ? a : text.find(':', a + 1);
    if (b == std::string::npos || text.find(':', b + 1) != std::string::npos) {
        error = "--" + std::string(describe(p).word) + " takes FROM:TO:STEP, not '" + text + "'";
        return std::nullopt;
    }
    const auto from = quantity(text.substr(0, a), p, error);
    const auto to = from ? quantity(text.substr(a + 1, b - a - 1), p, error) : std::nullopt;
    const auto step = to ? quantity(text.substr(b + 1), p, error) : std::nullopt;
    if (!step) return std::nullopt;
    return DesignAxis{p, *from, *to, *step};
}

// "2/4" -> share 2 of 4: whole numbers, 1 <= K <= N.
std::optional<std::pair<int, int>> shareOption(const std::string& text) {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) return std::nullopt;
    const auto k = wholeNumber(text.substr(0, slash)), n = wholeNumber(text.substr(slash + 1));
    if (!k || !n || *k < 1 || *n < 1 || *k > *n || *n > 100000) return std::nullopt;
    return std::pair{int(*k), int(*n)};
}

// Why the outputs cannot be written as asked: a name no one can resolve, an
// input (the base scene, a share) named as an output, or both outputs one
// file; "" when they can.
std::string outputsProblem(const Options& o, const std::vector<std::pair<std::string, std::string>>& inputs) {
    const auto csvPath = o.get("--csv"), svgPath = o.get("--svg");
    for (const auto& [option, path] :
         {std::pair{"--csv", csvPath}, std::pair{"--svg", svgPath}, std::pair{"--out", o.get("--out")}})
        if (path)
            if (std::string why = unresolvedOutput(option, *path); !why.empty()) return why;
    for (const auto& [option, path] : {std::pair{"--csv", csvPath}, std::pair{"--svg", svgPath}})
        for (const auto& [what, input] : inputs)
            if (path && sameFile(*path, input))
                return std::string(option) + " " + *path + " is the " + what + " " + input +
                       "; writing it would destroy the " + (what == "share" ? "share" : "scene");
    if (csvPath && svgPath && sameFile(*csvPath, *svgPath) && !(writtenDirectly(*csvPath) && writtenDirectly(*svgPath)))
        return "--csv and --svg name the same file (" + *csvPath +
               "); one would overwrite the other, give each its own";
    // A title XML cannot hold (a control character, bytes not UTF-8) is
    // refused before the map is computed, not written as a broken SVG.
    if (auto title = o.get("--title"))
        if (const std::string why = xmlTextProblem(*title); !why.empty())
            return "--title cannot be written in the SVG: " + why;
    return {};
}

// The CSV to --csv (or stdout) and the SVG of `map` to --svg, all or none.
int writeMap(const Options& o, const std::string& csv, const RippleMap* map) {
    std::vector<std::pair<std::string, std::string>> files;
    if (auto path = o.get("--csv"))
        files.emplace_back(*path, csv);
    else if (!print(csv))
        return 1;
    if (auto path = o.get("--svg"); path && map)
        files.emplace_back(*path, rippleMapSvg(*map, o.get("--title").value_or("How far the first ripple travels")));
    return saveAll(files) ? 0 : 1;
}

// The base scene of a map: --scene's ladder, or the classic one; nullopt
// (said on stderr) when the file is not a scene with a ladder.
std::optional<Scene> baseScene(const Options& o) {
    const auto path = o.get("--scene");
    if (!path) return turnedLadder(6, 0.012);
    SceneLoad load = loadScene(*path);
    for (const Diagnostic& d : load.errors) std::fprintf(stderr, "%s\n", d.format().c_str());
    if (load.scene && !load.scene->ladder) std::fprintf(stderr, "jladder reach: %s has no ladder\n", path->c_str());
    if (!load.scene || !load.scene->ladder) return std::nullopt;
    return load.scene;
}

// A map (or with --cells K/N, its K-th share) over one or two axes.
int designMap(const Options& o, std::vector<DesignAxis> axes, int jobs, RippleStop stop) {
    const auto base = baseScene(o);
    if (!base) return 1;
    // The axes' values as a scene file would have to hold them.
    for (const DesignAxis& a : axes)
        if (const std::string why = axisProblem(*base, a, kMostAxisValues); !why.empty()) {
            const std::string word(describe(a.parameter).word);
            std::fprintf(stderr, "jladder reach: --%s %s: %s\n", word.c_str(), o.get("--" + word)->c_str(),
                         why.c_str());
            return 2;
        }
    // One axis: a line, the second axis the base's own blocks count.
    if (axes.size() == 1) {
        const DesignParameter other =
            axes[0].parameter == DesignParameter::Blocks ? DesignParameter::Thickness : DesignParameter::Blocks;
        const double value = parameterValue(*base, other);
        axes.push_back({other, value, value, 1});
    }
    const auto share = o.get("--cells") ? shareOption(*o.get("--cells")) : std::pair{1, 1};
    const std::size_t total = axisValues(axes[0]).size() * axisValues(axes[1]).size();
    if (share->second > int(total)) {
        std::fprintf(stderr, "jladder reach: --cells %s: the map has only %zu cells, give at most %zu shares\n",
                     o.get("--cells")->c_str(), total, total);
        return 2;
    }
    ProgressLine progress(!o.has("--quiet"));
    const RippleMap map = computeRippleMap(
        *base, axes[0], axes[1], jobs, nullptr, [&](int done, int all) { progress.cells(done, all); },
        shareCells(total, share->first, share->second), stop);
    progress.clear();
    if (o.get("--cells"))
        return writeMap(o, rippleShareCsv(map, mapName(*base, axes[0], axes[1], stop), share->first, share->second),
                        nullptr);
    return writeMap(o, rippleMapCsv(map), &map);
}

// The shares (positional files) joined into their map.
int mergeShares(const Options& o) {
    std::vector<std::pair<std::string, std::string>> shares;
    for (const std::string& file : o.positional) {
        std::ifstream in(file, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        if (!in.good() && !in.eof()) {
            std::fprintf(stderr, "jladder reach: %s: cannot read it: %s\n", file.c_str(), std::strerror(errno));
            return 1;
        }
        shares.emplace_back(file, text.str());
    }
    const JoinedMap joined = joinRippleShares(shares);
    if (!joined.map) {
        std::fprintf(stderr, "jladder reach: --merge: %s\n", joined.error.c_str());
        return 1;
    }
    return writeMap(o, rippleMapCsv(*joined.map), &*joined.map);
}

// The arguments' error as a map or a merge sees them, or "".
std::string argumentsProblem(const Options& o, const std::vector<DesignAxis>& axes) {
    const bool merge = o.has("--merge");
    if (merge && (!axes.empty() || o.get("--scene") || o.get("--jobs") || o.get("--cells") || o.get("--out") ||
                  o.has("--whole-runs")))
        return "--merge joins shares already computed: give it the share files, --csv, --svg and --title only";
    if (merge && o.positional.empty()) return "--merge needs the share files (reach --cells K/N wrote them)";
    if (!merge && !o.positional.empty()) return "unexpected argument '" + o.positional.front() + "'";
    if (axes.size() > 2) return "give at most two axes";
    if (!merge && axes.empty() && (o.get("--csv") || o.get("--svg") || o.get("--scene") || o.get("--cells")))
        return "--csv, --svg, --scene and --cells make a map: give one or two axes (--blocks 4:12:2 ...)";
    if (auto cells = o.get("--cells"); cells && !shareOption(*cells))
        return "--cells takes K/N, whole numbers with 1 <= K <= N, not '" + *cells + "'";
    if (o.get("--cells") && o.get("--svg"))
        return "a share (--cells) has no map to draw: give --svg to --merge, which joins the shares";
    std::vector<std::pair<std::string, std::string>> inputs;
    if (auto scene = o.get("--scene")) inputs.emplace_back("scene file", *scene);
    for (const std::string& file : o.positional) inputs.emplace_back("share", file);
    return outputsProblem(o, inputs);
}

}  // namespace

int reach(const std::vector<std::string>& args) {
    std::vector<std::string> valued{"--out", "--scene", "--jobs", "--csv", "--svg", "--title", "--cells"};
    for (const DesignParameterWord& w : kDesignParameters) valued.push_back("--" + std::string(w.word));
    Options o = parse(args, valued, {"--help", "--quiet", "--merge", "--whole-runs"});
    if (o.has("--help")) return printHelp(kHelp);
    std::vector<DesignAxis> axes;
    for (const DesignParameterWord& w : kDesignParameters)
        if (auto text = o.get("--" + std::string(w.word)); text && o.error.empty())
            if (auto a = axis(*text, w.value, o.error)) axes.push_back(*a);
    const int jobs = int(o.count("--jobs", 1, 256).value_or(0));
    if (o.error.empty()) o.error = argumentsProblem(o, axes);
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder reach: %s\n", o.error.c_str());
        return 2;
    }
    if (o.has("--merge")) return mergeShares(o);
    const RippleStop stop = o.has("--whole-runs") ? RippleStop::WholeRun : RippleStop::WhenSettled;
    if (axes.empty()) return table(o.get("--out"), stop);
    return designMap(o, axes, jobs, stop);
}

}  // namespace jl::cli
