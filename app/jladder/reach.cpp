// jladder reach: how far the first ripple travels down ladders of several
// lengths and block thicknesses (docs/model.md section 15), as a Markdown table.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace jl::cli {

namespace {

struct Reach {
    int hinges = 0;          // flipped in order 1, 2, ..., k
    std::vector<double> at;  // first flip time of hinges 1..k
    int flipsElsewhere = 0;  // other hinges that flipped meanwhile (e.g. the bottom one whipping)
    int events = 0;          // every hinge event of the run (lock, unlock, fold, unfold, flip, bounce)
    int quickRow = 0;        // chatter: the most quick cycles of one hinge in a row
    double until = 0;        // s, the length of the run
    std::string failure;
};

bool releases(EventKind k) {
    return k == EventKind::Unlock || k == EventKind::FlipFlop || k == EventKind::Unfold || k == EventKind::Bounce;
}

// The chatter measure of docs/model.md section 8.6: a release of a hinge
// (unlock, flip, unfold, bounce) followed by a close of the same hinge (lock,
// fold) within 1 ms is a quick cycle; a slower close ends that hinge's row.
// The most quick cycles of one hinge in a row.
int longestQuickRow(const std::vector<Event>& events) {
    constexpr double kWindow = 1e-3;  // s
    std::map<int, double> releasedAt;
    std::map<int, int> row;
    int longest = 0;
    for (const Event& e : events) {
        if (releases(e.kind)) releasedAt[e.hinge] = e.time;
        if (e.kind != EventKind::Lock && e.kind != EventKind::Fold) continue;
        const auto r = releasedAt.find(e.hinge);
        if (r != releasedAt.end() && e.time - r->second <= kWindow) longest = std::max(longest, ++row[e.hinge]);
        else row[e.hinge] = 0;
    }
    return longest;
}

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
    r.until = until;
    auto sim = Simulation::build(s).simulation;
    std::vector<double> first(size_t(n), -1);
    std::vector<Event> events;
    while (sim->time() < until && sim->stepOnce())
        for (const Event& e : sim->takeEvents()) {
            if (e.hinge <= 0) continue;  // the script's own entries
            events.push_back(e);
            if (e.kind == EventKind::FlipFlop && first[size_t(e.hinge)] < 0) first[size_t(e.hinge)] = e.time;
        }
    r.failure = sim->failure();
    r.events = int(events.size());
    r.quickRow = longestQuickRow(events);
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
    s << " | " << r.flipsElsewhere << " | " << r.events << " in " << r.until << " s | " << r.quickRow << " | "
      << (r.failure.empty() ? "" : r.failure) << " |\n";
    return s.str();
}

}  // namespace

int reach(const std::vector<std::string>& args) {
    Options o = parse(args, {"--out"}, {"--help"});
    if (o.has("--help")) {
        std::fputs("usage: jladder reach [--out FILE]\n"
                   "Turns the top block of ladders of 6, 8, 12, 25 and 50 blocks (60 x 12 mm) and\n"
                   "of the thinner designs docs/model.md section 15 quotes, and tabulates how many\n"
                   "hinges the first ripple flips, every hinge event of the run, and the chatter\n"
                   "measure (the most quick cycles of one hinge in a row: a release and a close\n"
                   "within 1 ms), in Markdown (stdout, or FILE).\n",
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
        "| blocks | thickness (mm) | hinges the first ripple flips | mean time between flips | other hinges flipped | "
        "hinge events | most quick cycles of one hinge in a row | failure |\n"
        "|---:|---:|---|---:|---:|---:|---:|---|\n";
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
