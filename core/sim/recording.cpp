#include "jl/sim/recording.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace jl {

namespace {

void account(Recording& r, const Frame& f) {
    r.worstBalance = std::max(r.worstBalance, std::abs(f.energy.balance()));
    r.energyEnd = f.energy.total();
}

}  // namespace

Recording record(Simulation& sim, double until, const FrameGrid& grid, RecordTarget* target,
                 const std::function<int()>& interruption) {
    Recording r;
    // Numbers only, unless the target draws the frames: no ribbons to draw then.
    const bool ribbons = sim.ribbonsInFrames();
    sim.setRibbonsInFrames(target && target->drawsRibbons());
    const auto handOn = [&](const std::vector<Event>& events) {
        for (const Event& e : events) {
            ++r.events;
            r.targetFailed = r.targetFailed || (target && !target->event(e));
        }
    };
    const Frame first = sim.frame();
    handOn(first.events);
    r.energyStart = first.energy.total();
    account(r, first);
    r.targetFailed = r.targetFailed || (target && !target->frame(first));
    // Frames at exactly the grid's instants: inside a step from its dense
    // output, at a step's end when it ends on one (jl/sim/simulation.h).
    const FrameGrid before = sim.frameGrid();
    sim.setFrameGrid(grid);
    const auto start = std::chrono::steady_clock::now();
    while (!r.targetFailed && sim.time() < until && sim.failure().empty()) {
        if (interruption && (r.interrupted = interruption())) break;
        if (!sim.stepOnceUpTo(until)) break;  // the run ends at exactly `until`
        handOn(sim.takeEvents());
        r.worstResidual = std::max(r.worstResidual, sim.lastResidual());
        r.targetFailed = r.targetFailed || (target && !target->step(sim));
        for (const Frame& f : sim.takeGridFrames()) {
            account(r, f);
            r.targetFailed = r.targetFailed || (target && !target->frame(f));
        }
        const bool onGrid = grid.on(sim.time());
        if (!onGrid && sim.time() < until) continue;
        Frame f = sim.frame();
        handOn(f.events);
        account(r, f);
        if (onGrid) {
            f.time = grid.at(grid.nearest(sim.time()));  // within rounding of it: the grid's time, exactly
            r.targetFailed = r.targetFailed || (target && !target->frame(f));
        }
    }
    sim.setFrameGrid(before);
    const Frame last = sim.frame();
    sim.setRibbonsInFrames(ribbons);
    r.failure = last.failure;
    r.time = sim.time();
    r.steps = last.solver.steps;
    r.evaluations = last.solver.evaluations;
    r.solver = last.solver;
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

}  // namespace jl
