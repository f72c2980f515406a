// Test support: build a scene from YAML text, record its run (jl/sim/recording.h),
// collect events and contacts.
#pragma once

#include "jl/engine/projection.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/recording.h"
#include "jl/sim/simulation.h"

#include <QtTest>

#include <functional>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace jl::test {

inline std::unique_ptr<Simulation> simulate(const std::string& yaml) {
    SceneLoad load = parseScene(yaml, "test.yaml");
    for (const Diagnostic& d : load.errors) qWarning("%s", d.format().c_str());
    if (!load.scene) return nullptr;
    Simulation::Built built = Simulation::build(*load.scene);
    for (const std::string& e : built.errors) qWarning("%s", e.c_str());
    return std::move(built.simulation);
}

inline std::unique_ptr<Simulation> simulateFile(const std::string& relativePath) {
    SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/" + relativePath);
    for (const Diagnostic& d : load.errors) qWarning("%s", d.format().c_str());
    if (!load.scene) return nullptr;
    return std::move(Simulation::build(*load.scene).simulation);
}

struct Run {
    std::vector<Event> events;  // hinge events only (script actions left out)
    double worstBalance = 0;    // J, |E - (E0 + W - D)|
    double worstResidual = 0;   // m
    double lastImpactLoss = 0;
    bool impactLossNeverFell = true;
    std::string failure;
};

// Records the run to exactly `until` (jl/sim/recording.h), checking every
// step and calling `each` after it with its frame (for contacts and angles)
// and the step's events.
inline Run runUntil(Simulation& sim, double until, const std::function<void(const Frame&)>& each = {}) {
    struct EveryStep : RecordTarget {
        Run r;
        std::vector<Event> stepEvents;
        const std::function<void(const Frame&)>& each;
        explicit EveryStep(const std::function<void(const Frame&)>& e) : each(e) {}
        bool frame(const Frame&) override { return true; }
        bool event(const Event& e) override {
            stepEvents.push_back(e);
            if (e.hinge > 0) r.events.push_back(e);
            return true;
        }
        bool step(Simulation& s) override {
            Frame f = s.frame();
            f.events = std::exchange(stepEvents, {});
            r.worstBalance = std::max(r.worstBalance, std::abs(f.energy.balance()));
            // Measured on the world itself after the step and its events, not
            // read from the projection (which reports what it aimed at).
            r.worstResidual = std::max(r.worstResidual, pinResidual(s.world()));
            if (f.energy.impactLoss < r.lastImpactLoss - 1e-15) r.impactLossNeverFell = false;
            r.lastImpactLoss = f.energy.impactLoss;
            if (each) each(f);
            return true;
        }
    } target(each);
    target.r.failure = record(sim, until, FrameGrid{}, &target).failure;
    return target.r;
}

// Records the run until the step of the first event of `kind`; false if
// none by `until`. The events of that step go to `instant`.
inline bool stepUntil(Simulation& sim, EventKind kind, double until, Event* found,
                      std::vector<Event>* instant = nullptr) {
    struct FirstOfKind : RecordTarget {
        EventKind kind;
        Event* found;
        std::vector<Event> stepEvents;
        bool seen = false;
        FirstOfKind(EventKind k, Event* f) : kind(k), found(f) {}
        bool frame(const Frame&) override { return true; }
        bool event(const Event& e) override {
            stepEvents.push_back(e);
            if (!seen && e.kind == kind) *found = e, seen = true;
            return true;
        }
        bool step(Simulation&) override {
            if (!seen) stepEvents.clear();
            return !seen;  // stops the run after the step of the event
        }
    } target(kind, found);
    record(sim, until, FrameGrid{}, &target);
    if (!sim.failure().empty()) qWarning("%s", sim.failure().c_str());
    if (target.seen && instant) *instant = target.stepEvents;
    return target.seen;
}

inline std::vector<int> firstFlipOrder(const std::vector<Event>& events) {
    std::vector<int> order;
    for (const Event& e : events)
        if (e.kind == EventKind::FlipFlop && std::find(order.begin(), order.end(), e.hinge) == order.end())
            order.push_back(e.hinge);
    return order;
}

// Chatter: a hinge released (unlock, flip, unfold) and closed again (lock,
// fold) within `window` seconds is one quick cycle; `longest` is the most
// quick cycles of one hinge in a row. A row ends with a slower cycle, or
// when the hinge stays closed longer than `window` before its next release:
// a contact knocked open by impacts some milliseconds apart, each closing it
// again at once, is not chattering.
struct Chatter {
    int cycles = 0;
    int longest = 0;
};
inline Chatter chatter(const std::vector<Event>& events, double window = 1e-3) {
    Chatter c;
    std::map<int, double> releasedAt, closedAt;
    std::map<int, int> row;
    for (const Event& e : events) {
        if (e.kind == EventKind::Unlock || e.kind == EventKind::FlipFlop || e.kind == EventKind::Unfold ||
            e.kind == EventKind::Bounce) {
            const auto closed = closedAt.find(e.hinge);
            if (closed != closedAt.end() && e.time - closed->second > window) row[e.hinge] = 0;
            releasedAt[e.hinge] = e.time;
        }
        if (e.kind != EventKind::Lock && e.kind != EventKind::Fold) continue;
        closedAt[e.hinge] = e.time;
        const auto r = releasedAt.find(e.hinge);
        if (r != releasedAt.end() && e.time - r->second <= window) {
            ++c.cycles;
            c.longest = std::max(c.longest, ++row[e.hinge]);
        } else {
            row[e.hinge] = 0;
        }
    }
    return c;
}

}  // namespace jl::test
