#include "jl/design/ripple_reach.h"

#include "jl/sim/simulation.h"

#include <algorithm>
#include <map>
#include <numbers>

namespace jl {

Scene turnedLadder(int blocks, double thickness) {
    Scene s;
    LadderSpec l;
    l.blocks = blocks;
    l.block.thickness = thickness;
    s.ladder = l;
    ScriptAction turn;
    turn.at = 0.2;
    turn.angle = std::numbers::pi;
    turn.duration = 0.3;
    s.script.push_back(turn);
    return s;
}

double rippleRunTime(const Scene& scene) {
    double scriptEnd = 0;
    for (const ScriptAction& a : scene.script) scriptEnd = std::max(scriptEnd, a.at + std::max(0.0, a.duration));
    const int n = scene.ladder ? scene.ladder->blocks : 0;
    return scriptEnd + 0.5 + 0.2 * n;
}

namespace {

bool releases(EventKind k) {
    return k == EventKind::Unlock || k == EventKind::FlipFlop || k == EventKind::Unfold || k == EventKind::Bounce;
}

}  // namespace

int longestQuickRow(const std::vector<Event>& events) {
    constexpr double kWindow = 1e-3;  // s
    std::map<int, double> releasedAt;
    std::map<int, int> row;
    int longest = 0;
    for (const Event& e : events) {
        if (releases(e.kind)) releasedAt[e.hinge] = e.time;
        if (e.kind != EventKind::Lock && e.kind != EventKind::Fold) continue;
        const auto r = releasedAt.find(e.hinge);
        if (r != releasedAt.end() && e.time - r->second <= kWindow)
            longest = std::max(longest, ++row[e.hinge]);
        else
            row[e.hinge] = 0;
    }
    return longest;
}

namespace {

// The first ripple as the flips come: first[j] the first flip of hinge j
// (-1: none yet), reached and last the hinges 1..reached flipped in order
// and the last of those flips.
struct RippleSoFar {
    std::vector<double> first;
    int reached = 0;
    double last = 0;
    void extend() {
        for (int j = reached + 1; j < int(first.size()) && first[size_t(j)] >= last; ++j) {
            last = first[size_t(j)];
            ++reached;
        }
    }
    // Why the reach can no longer change, or RunEnd while it still can.
    RippleEnd settled(const Simulation& sim, ReachBarrier& barrier) const {
        const int next = reached + 1;
        if (next >= int(first.size())) return RippleEnd::Bottom;
        if (first[size_t(next)] >= 0) return RippleEnd::Order;  // flipped before hinge `reached`
        return barrier.cannotFold(sim, next) ? RippleEnd::Energy : RippleEnd::RunEnd;
    }
};

}  // namespace

RippleReach firstRippleReach(const Scene& scene, const std::atomic<bool>* cancel, double longest, RippleStop stop) {
    RippleReach r;
    if (!scene.ladder) {
        r.failure = "the scene has no ladder";
        return r;
    }
    const int n = scene.ladder->blocks;
    r.hinges = n - 1;
    r.until = std::min(rippleRunTime(scene), longest);
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        r.failure = built.errors.empty() ? "the scene does not build" : built.errors.front();
        return r;
    }
    Simulation& sim = *built.simulation;
    ReachBarrier barrier(scene, sim);
    RippleSoFar ripple{std::vector<double>(size_t(n), -1)};
    std::vector<Event> events;
    // Settled already (nothing to turn, a ladder at rest) or after a step.
    auto settled = [&] {
        if (stop == RippleStop::WholeRun) return false;
        r.end = ripple.settled(sim, barrier);
        return r.end != RippleEnd::RunEnd;
    };
    while (!settled() && sim.time() < r.until && sim.stepOnce()) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            r.cancelled = true;
            return r;
        }
        for (const Event& e : sim.takeEvents()) {
            if (e.hinge <= 0) continue;  // the script's own entries
            events.push_back(e);
            if (e.kind == EventKind::FlipFlop && ripple.first[size_t(e.hinge)] < 0)
                ripple.first[size_t(e.hinge)] = e.time;
        }
        ripple.extend();
    }
    if (r.end != RippleEnd::RunEnd)
        r.until = sim.time();
    else
        r.whole = r.until >= rippleRunTime(scene);
    r.failure = sim.failure();
    r.events = int(events.size());
    r.quickRow = longestQuickRow(events);
    r.reached = ripple.reached;
    for (int j = 1; j <= r.reached; ++j) r.flipTimes.push_back(ripple.first[size_t(j)]);
    for (int j = r.reached + 2; j < n; ++j) r.flipsElsewhere += ripple.first[size_t(j)] >= 0 ? 1 : 0;
    if (r.flipTimes.size() >= 2)
        r.meanTimeBetweenFlips = (r.flipTimes.back() - r.flipTimes.front()) / double(r.flipTimes.size() - 1);
    return r;
}

}  // namespace jl
