// jladder reach: how far the first ripple travels (docs/model.md section 15).
// Without axes, the fixed table of designs that section quotes; with one or
// two axes (--blocks 6:50:2 --thickness 2mm:12mm:1mm ...), a design map over
// them (jl/design/ripple_map.h), as CSV and an SVG heat map.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "jl/base/output_file.h"
#include "jl/base/xml_text.h"
#include "jl/design/ripple_map.h"
#include "jl/scene/scene_io.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
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
    "usage: jladder reach [--out FILE]\n"
    "       jladder reach --PARAMETER FROM:TO:STEP [--PARAMETER FROM:TO:STEP] [--scene BASE.yaml]\n"
    "                     [--jobs N] [--csv FILE] [--svg FILE] [--title TEXT]\n"
    "Without axes: turns the top block of ladders of 6, 8, 12, 25 and 50 blocks (60 x 12 mm)\n"
    "and of the thinner designs docs/model.md section 15 quotes, and tabulates how many\n"
    "hinges the first ripple flips, every hinge event of the run, and the chatter measure\n"
    "(the most quick cycles of one hinge in a row: a release and a close within 1 ms), in\n"
    "Markdown (stdout, or FILE).\n"
    "With axes: a design map. PARAMETER is one of blocks, thickness, length, width (lengths\n"
    "in m, or with mm or cm), density (kg/m^3), hinge_damping (N m s), turn_duration\n"
    "(s, or ms); one axis gives a line, two a map. Every cell is a full simulation of the\n"
    "first ripple on BASE (default: 6 blocks of 60 x 12 x 45 mm, density 600, block 0 held\n"
    "and turned half a turn from 0.2 s over 0.3 s), run on N threads (default: every core).\n"
    "Writes CSV (stdout, or --csv FILE) and an SVG heat map (--svg FILE); the same command\n"
    "gives the same bytes whatever N. Files are replaced only once both are written whole;\n"
    "neither may be the --scene file.\n";

// Standard output written and flushed, or a message: a full disk or a closed
// pipe is a failed run, not a silent one.
bool print(const std::string& text) {
    if (std::fputs(text.c_str(), stdout) >= 0 && std::fflush(stdout) == 0) return true;
    std::fprintf(stderr, "jladder reach: cannot write to standard output: %s\n", std::strerror(errno));
    return false;
}

// The fixed table of the designs docs/model.md section 15 quotes.
int table(const std::optional<std::string>& out) {
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
        const RippleReach r = firstRippleReach(turnedLadder(c.n, c.t));
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
std::optional<double> quantity(const std::string& text, DesignParameter p, std::string& error) {
    char* end = nullptr;
    const double v = std::strtod(text.c_str(), &end);
    const std::string unit(end);
    double scale = 0;
    const bool length = p == DesignParameter::Thickness || p == DesignParameter::Length || p == DesignParameter::Width;
    if (unit.empty())
        scale = 1;
    else if (length && unit == "mm")
        scale = 1e-3;
    else if (length && unit == "cm")
        scale = 1e-2;
    else if (length && unit == "m")
        scale = 1;
    else if (p == DesignParameter::TurnDuration && unit == "ms")
        scale = 1e-3;
    else if (p == DesignParameter::TurnDuration && unit == "s")
        scale = 1;
    if (end == text.c_str() || !(scale > 0) || !std::isfinite(v)) {
        error = "'" + text + "' is not a value of " + std::string(describe(p).word);
        return std::nullopt;
    }
    return v * scale;
}

// "6:50:2" -> an axis; checked for a count of cells a map can show.
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
    DesignAxis x{p, *from, *to, *step};
    const size_t n = axisValues(x).size();
    if (n == 0 || n > 200) {
        error = "--" + std::string(describe(p).word) + " " + text + " gives " + (n ? "more than 200" : "no") +
                " values (FROM <= TO, STEP > 0)";
        return std::nullopt;
    }
    return x;
}

}  // namespace

int reach(const std::vector<std::string>& args) {
    std::vector<std::string> valued{"--out", "--scene", "--jobs", "--csv", "--svg", "--title"};
    for (const DesignParameterWord& w : kDesignParameters) valued.push_back("--" + std::string(w.word));
    Options o = parse(args, valued, {"--help"});
    if (o.has("--help")) {
        return printHelp(kHelp);
    }
    std::vector<DesignAxis> axes;
    for (const DesignParameterWord& w : kDesignParameters)
        if (auto text = o.get("--" + std::string(w.word)); text && o.error.empty())
            if (auto a = axis(*text, w.value, o.error)) axes.push_back(*a);
    if (o.error.empty() && axes.size() > 2) o.error = "give at most two axes";
    if (o.error.empty() && axes.empty() && (o.get("--csv") || o.get("--svg") || o.get("--scene")))
        o.error = "--csv, --svg and --scene make a map: give one or two axes (--blocks 4:12:2 ...)";
    int jobs = 0;
    if (auto j = o.get("--jobs"); j && o.error.empty()) {
        jobs = std::atoi(j->c_str());
        if (jobs < 1 || jobs > 256) o.error = "--jobs takes a whole number from 1 to 256";
    }
    // An output may not be the base scene, nor both outputs one file.
    const auto csvPath = o.get("--csv"), svgPath = o.get("--svg"), scenePath = o.get("--scene");
    for (const auto& [option, path] :
         {std::pair{"--csv", csvPath}, std::pair{"--svg", svgPath}, std::pair{"--out", o.get("--out")}})
        if (o.error.empty() && path) o.error = unresolvedOutput(option, *path);
    for (const auto& [option, path] : {std::pair{"--csv", csvPath}, std::pair{"--svg", svgPath}})
        if (o.error.empty() && path && scenePath && sameFile(*path, *scenePath))
            o.error = std::string(option) + " " + *path + " is the scene file " + *scenePath +
                      "; writing it would destroy the scene";
    if (o.error.empty() && csvPath && svgPath && sameFile(*csvPath, *svgPath) &&
        !(writtenDirectly(*csvPath) && writtenDirectly(*svgPath)))
        o.error =
            "--csv and --svg name the same file (" + *csvPath + "); one would overwrite the other, give each its own";
    // A title XML cannot hold (a control character, bytes not UTF-8) is
    // refused before the map is computed, not written as a broken SVG.
    if (auto title = o.get("--title"); title && o.error.empty())
        if (const std::string why = xmlTextProblem(*title); !why.empty())
            o.error = "--title cannot be written in the SVG: " + why;
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder reach: %s\n", o.error.c_str());
        return 2;
    }
    if (axes.empty()) return table(o.get("--out"));

    Scene base = turnedLadder(6, 0.012);
    if (auto path = o.get("--scene")) {
        SceneLoad load = loadScene(*path);
        for (const Diagnostic& d : load.errors) std::fprintf(stderr, "%s\n", d.format().c_str());
        if (!load.scene) return 1;
        if (!load.scene->ladder) {
            std::fprintf(stderr, "jladder reach: %s has no ladder\n", path->c_str());
            return 1;
        }
        base = *load.scene;
    }
    // One axis: a line, the second axis the base's own blocks count.
    if (axes.size() == 1) {
        const DesignParameter other =
            axes[0].parameter == DesignParameter::Blocks ? DesignParameter::Thickness : DesignParameter::Blocks;
        const double value = other == DesignParameter::Blocks ? base.ladder->blocks : base.ladder->block.thickness;
        axes.push_back({other, value, value, 1});
    }
    const RippleMap map = computeRippleMap(base, axes[0], axes[1], jobs, nullptr, [](int done, int total) {
        std::fprintf(stderr, "\r%d of %d designs", done, total);
    });
    std::fputc('\n', stderr);
    const std::string csv = rippleMapCsv(map);
    const std::string title = o.get("--title").value_or("How far the first ripple travels");
    std::vector<std::pair<std::string, std::string>> files;
    if (auto path = o.get("--csv"))
        files.emplace_back(*path, csv);
    else if (!print(csv))
        return 1;
    if (auto path = o.get("--svg")) files.emplace_back(*path, rippleMapSvg(map, title));
    return saveAll(files) ? 0 : 1;
}

}  // namespace jl::cli
