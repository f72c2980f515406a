// The folding chain (bench/folding_chain.h) in this engine: a general scene
// of boxes and pins whose stops (docs/model.md section 18) are the hinges'
// limits, run with every integrator at several steps or tolerances, with
// events located and at the ends of steps.
#include "bench/folding_chain.h"
#include "jl/base/thread_clock.h"
#include "jl/engine/energy.h"
#include "jl/sim/simulation.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <numbers>
#include <string>

namespace jl::bench {

namespace {

Scene foldingScene(int n) {
    Scene s;
    s.title = "The folding chain";
    s.gravity = {0, -folding::kGravity};
    s.duration = folding::kDuration;
    const double stop = folding::stopAngle(n);
    for (int i = 0; i < n; ++i) {
        BodySpec b;
        b.name = "link" + std::to_string(i);
        b.length = folding::kLength;
        b.thickness = folding::kThickness;
        b.width = folding::kWidth;
        b.density = folding::kDensity;
        b.position = {(i + 0.5) * folding::kLength, 0};
        b.angle = -std::numbers::pi / 2;  // the box's length (local y) along +x
        s.bodies.push_back(b);
        PinSpec pin;
        pin.a =
            i == 0 ? PointRef{"world", {0, 0}} : PointRef{"link" + std::to_string(i - 1), {0, folding::kLength / 2}};
        pin.b = PointRef{b.name, {0, -folding::kLength / 2}};
        if (i > 0) pin.minAngle = -stop, pin.maxAngle = stop;
        s.pins.push_back(pin);
    }
    return s;
}

struct Setting {
    Integrator integrator;
    EventPolicy events;
    double step = 0, tolerance = 0;  // one of them
};

std::string methodName(const Setting& s) {
    const char* name = s.integrator == Integrator::RK4               ? "rk4"
                       : s.integrator == Integrator::DormandPrince45 ? "dormand_prince45"
                       : s.integrator == Integrator::Verner65        ? "verner65"
                       : s.integrator == Integrator::RosenbrockW     ? "rosenbrock_w"
                       : s.integrator == Integrator::SymplecticEuler ? "symplectic_euler"
                                                                     : "explicit_euler";
    return std::string(name) + (s.events == EventPolicy::Located ? ", located" : ", end of step");
}

// One run to kDuration: the samples at their exact times, the first
// closing of each stop as the stops kept it.
FoldingRun runOnce(int n, const Setting& setting) {
    Scene scene = foldingScene(n);
    scene.solver.integrator = setting.integrator;
    scene.solver.events = setting.events;
    if (setting.step > 0) scene.solver.step = setting.step;
    if (setting.tolerance > 0) scene.solver.tolerance = setting.tolerance;
    FoldingRun r;
    r.engine = "jladder";
    r.method = methodName(setting);
    r.stopModel = "rigid unilateral stop: located plastic impact, then a weld while its moment pushes";
    char text[64];
    std::snprintf(text, sizeof text, setting.step > 0 ? "dt = %.3g s" : "tolerance %.3g",
                  setting.step > 0 ? setting.step : setting.tolerance);
    r.setting = text;
    r.blocks = n;
    r.firstClosing.assign(size_t(n) - 1, kNever);
    const double start = threadSeconds();
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        r.finished = false;
        r.why = built.errors.empty() ? "not built" : built.errors.front();
        return r;
    }
    Simulation& sim = *built.simulation;
    sim.setRibbonsInFrames(false);
    sim.setTimingEvents(true);  // the table of where the time goes
    const double e0 = energy(sim.world()).total();
    for (size_t k = 0; k < folding::kSampleTimes.size(); ++k) {
        const double t = folding::kSampleTimes[k];
        while (sim.time() < t && sim.failure().empty()) {
            sim.stepOnceUpTo(t);
            r.events += (long long)sim.takeEvents().size();
        }
        if (!sim.failure().empty()) {
            r.finished = false;
            r.why = sim.failure();
            break;
        }
        for (int i = 0; i < n; ++i) r.centres[k].push_back(sim.world().partPose(sim.blockPart(i)).position);
        r.dissipated[k] = e0 - energy(sim.world()).total();
    }
    r.cpuSeconds = threadSeconds() - start;
    r.eventSeconds = sim.eventSeconds();
    r.locatingSeconds = sim.locatingSeconds();
    r.steps = sim.frame().solver.steps;
    // Stop i joins link i to link i + 1 (foldingScene).
    if (const PinStops* stops = sim.stops())
        for (int i = 0; i < stops->count() && i < n - 1; ++i) r.firstClosing[size_t(i)] = stops->firstClosing(i);
    return r;
}

}  // namespace

FoldingRun runFoldingSetting(int n, const std::string& integrator, bool located, double step) {
    const Integrator i = integrator == "rk4" ? Integrator::RK4 : Integrator::SymplecticEuler;
    return runOnce(n, {i, located ? EventPolicy::Located : EventPolicy::EndOfStep, step, 0});
}

FoldingRun runFoldingReference(int n, double tolerance) {
    return runOnce(n, {Integrator::DormandPrince45, EventPolicy::Located, 0, tolerance});
}

std::vector<FoldingRun> runFoldingOurs(int n, double minSeconds) {
    std::vector<Setting> settings;
    for (EventPolicy events : {EventPolicy::Located, EventPolicy::EndOfStep})
        for (double h : {2e-3, 1e-3, 2.5e-4, 1e-4, 2.5e-5}) settings.push_back({Integrator::RK4, events, h, 0});
    for (double h : {1e-3, 2.5e-4, 1e-4, 2.5e-5})
        settings.push_back({Integrator::SymplecticEuler, EventPolicy::Located, h, 0});
    for (Integrator i : {Integrator::DormandPrince45, Integrator::Verner65})
        for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) settings.push_back({i, EventPolicy::Located, 0, tol});
    for (double tol : {1e-4, 1e-6}) settings.push_back({Integrator::RosenbrockW, EventPolicy::Located, 0, tol});
    std::vector<FoldingRun> out;
    for (const Setting& s : settings) {
        out.push_back(runOnce(n, s));
        FoldingRun& r = out.back();
        // Short runs repeated until the clock resolves them, as the peers' are.
        double cpu = r.cpuSeconds;
        int repeats = 1;
        for (; r.finished && cpu < minSeconds; ++repeats) cpu += runOnce(n, s).cpuSeconds;
        r.cpuSeconds = cpu / repeats;
        std::fprintf(stderr, "  jladder %-28s %-16s N=%-4d %8.3f CPU s%s\n", r.method.c_str(), r.setting.c_str(), n,
                     r.cpuSeconds, r.finished ? "" : (" failed: " + r.why).c_str());
    }
    return out;
}

}  // namespace jl::bench
