// TEMPORARY: stands in for jl/design/*.h until the design core lands; deleted then.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/simulation.h"

#include <atomic>
#include <cmath>
#include <string>
#include <vector>

namespace jl {

enum class DesignParameter { Blocks, Thickness, Length, Width, Density, HingeDamping, TurnDuration };

struct DesignAxis {
    DesignParameter parameter = DesignParameter::Blocks;
    double from = 4, to = 12, step = 2;
    bool operator==(const DesignAxis&) const = default;
};

struct RippleReach {
    int hinges = 0;
    int reached = 0;
    std::vector<double> flipTimes;
    double meanTimeBetweenFlips = 0;
    std::string failure;
    bool cancelled = false;
};

inline std::vector<double> axisValues(const DesignAxis& a) {
    std::vector<double> v;
    const int n = int(std::floor((a.to - a.from) / a.step + 1e-9)) + 1;
    for (int i = 0; i < n; ++i) v.push_back(a.from + i * a.step);
    return v;
}

inline Scene withParameter(Scene s, DesignParameter p, double value) {
    if (!s.ladder) s.ladder = LadderSpec{};
    LadderSpec& l = *s.ladder;
    switch (p) {
        case DesignParameter::Blocks:
            l.blocks = int(std::lround(value));
            break;
        case DesignParameter::Thickness:
            l.block.thickness = value;
            break;
        case DesignParameter::Length:
            l.block.length = value;
            break;
        case DesignParameter::Width:
            l.block.width = value;
            break;
        case DesignParameter::Density:
            l.block.density = value;
            break;
        case DesignParameter::HingeDamping:
            l.hinges.damping = value;
            break;
        case DesignParameter::TurnDuration:
            for (ScriptAction& a : s.script)
                if (a.kind == ScriptAction::Kind::Turn) a.duration = value;
            break;
    }
    return s;
}

inline RippleReach firstRippleReach(const Scene& scene, const std::atomic<bool>* cancel) {
    RippleReach r;
    Scene s = scene;
    if (!s.ladder) {
        r.failure = "no ladder";
        return r;
    }
    const int n = s.ladder->blocks;
    r.hinges = n - 1;
    auto built = Simulation::build(s);
    if (!built.simulation) {
        r.failure = built.errors.empty() ? "cannot build" : built.errors.front();
        return r;
    }
    auto& sim = built.simulation;
    std::vector<double> first(size_t(n), -1);
    const double until = 1.0 + 0.2 * n;
    while (sim->time() < until && sim->stepOnce()) {
        if (cancel && cancel->load()) {
            r.cancelled = true;
            return r;
        }
        for (const Event& e : sim->takeEvents())
            if (e.hinge > 0 && e.kind == EventKind::FlipFlop && first[size_t(e.hinge)] < 0)
                first[size_t(e.hinge)] = e.time;
    }
    r.failure = sim->failure();
    double last = 0;
    for (int j = 1; j < n && first[size_t(j)] >= last; ++j) {
        r.flipTimes.push_back(first[size_t(j)]);
        last = first[size_t(j)];
        ++r.reached;
    }
    if (r.flipTimes.size() >= 2)
        r.meanTimeBetweenFlips = (r.flipTimes.back() - r.flipTimes.front()) / double(r.flipTimes.size() - 1);
    return r;
}

}  // namespace jl
