// jladder reach: how far the first ripple travels down ladders of several
// lengths and block thicknesses (docs/model.md section 15), as a Markdown table.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "core/simulation.h"

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace jl::cli {

namespace {

struct Reach {
    int hinges = 0;          // flipped in order 1, 2, ..., k
    std::vector<double> at;  // first flip time of hinges 1..k
    int flipsElsewhere = 0;  // other hinges that flipped meanwhile (e.g. the bottom one whipping)
    std::string failure;
};

// Holds block 0 of an n-block ladder (blocks 60 mm x T x 45 mm, density 600)
// in its hanging equilibrium, turns it half a turn counter-clockwise from
// t = 0.2 s over 0.3 s, and follows the first flips. The ripple has reached
// hinge k when hinges 1..k each flipped, each after the one above it.
Reach measure(int n, double thickness, double until) {
    Scene s;
    LadderSpec l;
    l.blocks = n;
    l.block.thickness = thickness;
    s.ladder = l;
    ScriptAction turn;
    turn.at = 0.2;
    turn.angle = 3.14159265358979323846;
    turn.duration = 0.3;
    s.script.push_back(turn);
    Reach r;
    auto sim = Simulation::build(s).simulation;
    std::vector<double> first(size_t(n), -1);
    while (sim->time() < until && sim->stepOnce())
        for (const Event& e : sim->frame().events)
            if (e.kind == EventKind::FlipFlop && first[size_t(e.hinge)] < 0) first[size_t(e.hinge)] = e.time;
    r.failure = sim->failure();
    double last = 0;
    for (int j = 1; j < n && first[size_t(j)] >= last; ++j) {
        r.at.push_back(first[size_t(j)]);
        last = first[size_t(j)];
        ++r.hinges;
    }
    for (int j = r.hinges + 2; j < n; ++j) r.flipsElsewhere += first[size_t(j)] >= 0 ? 1 : 0;
    return r;
}

std::string row(int n, double thickness, const Reach& r) {
    std::ostringstream s;
    s.precision(3);
    s << "| " << n << " | " << thickness * 1000 << " | " << r.hinges << " of " << n - 1 << " | ";
    if (r.at.size() >= 2) s << (r.at.back() - r.at.front()) / double(r.at.size() - 1) << " s";
    s << " | " << r.flipsElsewhere << " | " << (r.failure.empty() ? "" : r.failure) << " |\n";
    return s.str();
}

}  // namespace

int reach(const std::vector<std::string>& args) {
    Options o = parse(args, {"--out"}, {"--help"});
    if (o.has("--help")) {
        std::fputs("usage: jladder reach [--out FILE]\n"
                   "Turns the top block of ladders of 6, 8, 12, 25 and 50 blocks (60 x 12 mm) and\n"
                   "of the thinner designs docs/model.md section 15 quotes, and tabulates how many\n"
                   "hinges the first ripple flips, in Markdown (stdout, or FILE).\n",
                   stdout);
        return 0;
    }
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder reach: %s\n", o.error.c_str());
        return 2;
    }
    struct Case {
        int n;
        double t;
    };
    const std::vector<Case> cases = {{6, 0.012}, {8, 0.012}, {12, 0.012}, {25, 0.012}, {50, 0.012},
                                     {12, 0.006}, {25, 0.004}, {25, 0.003}};
    std::string table =
        "| blocks | thickness (mm) | hinges the first ripple flips | mean time between flips | other hinges flipped | failure |\n"
        "|---:|---:|---|---:|---:|---|\n";
    for (const Case& c : cases) {
        const double until = 1.0 + 0.2 * c.n;
        const std::string r = row(c.n, c.t, measure(c.n, c.t, until));
        std::fputs(r.c_str(), stderr);
        table += r;
    }
    if (auto file = o.get("--out")) {
        std::ofstream out(*file);
        out << table;
        return out ? 0 : 1;
    }
    std::fputs(table.c_str(), stdout);
    return 0;
}

}  // namespace jl::cli
