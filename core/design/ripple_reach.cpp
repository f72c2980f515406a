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

RippleReach firstRippleReach(const Scene& scene, const std::atomic<bool>* cancel, double longest) {
    RippleReach r;
    if (!scene.ladder) {
        r.failure = "the scene has no ladder";
        return r;
    }
    const int n = scene.ladder->blocks;
    r.hinges = n - 1;
    r.until = rippleRunTime(scene);
    if (longest < r.until) {
        r.until = longest;
        r.whole = false;
    }
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        r.failure = built.errors.empty() ? "the scene does not build" : built.errors.front();
        return r;
    }
    Simulation& sim = *built.simulation;
    std::vector<double> first(size_t(n), -1);
    std::vector<Event> events;
    while (sim.time() < r.until && sim.stepOnce()) {
        if (cancel && cancel->load(std::memory_order_relaxed)) {
            r.cancelled = true;
            return r;
        }
        for (const Event& e : sim.takeEvents()) {
            if (e.hinge <= 0) continue;  // the script's own entries
            events.push_back(e);
            if (e.kind == EventKind::FlipFlop && first[size_t(e.hinge)] < 0) first[size_t(e.hinge)] = e.time;
        }
    }
    r.failure = sim.failure();
    r.events = int(events.size());
    r.quickRow = longestQuickRow(events);
    double last = 0;
    for (int j = 1; j < n && first[size_t(j)] >= last; ++j) {
        r.flipTimes.push_back(first[size_t(j)]);
        last = first[size_t(j)];
        ++r.reached;
    }
    for (int j = r.reached + 2; j < n; ++j) r.flipsElsewhere += first[size_t(j)] >= 0 ? 1 : 0;
    if (r.flipTimes.size() >= 2)
        r.meanTimeBetweenFlips = (r.flipTimes.back() - r.flipTimes.front()) / double(r.flipTimes.size() - 1);
    return r;
}

}  // namespace jl
