#include "bench/examples.h"

#include "jl/base/thread_clock.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/recording.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace jl::bench {

namespace {

constexpr const char* kLong = "long-ladder.yaml";
constexpr int kLongBlocks = 1000;

// One scene for `horizon` s of simulated time (its duration if shorter).
ExampleRow runScene(const std::string& name, Scene scene, double horizon) {
    ExampleRow row;
    row.scene = name;
    row.asked = std::min(horizon, scene.duration);
    row.integrator = std::string(integratorWord(scene.solver.integrator));
    row.adaptive = isAdaptive(scene.solver.integrator);
    row.tolerance = scene.solver.tolerance;
    row.blocks = scene.ladder ? scene.ladder->blocks : int(scene.bodies.size() + scene.particles.size());
    const double t0 = threadSeconds();
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        row.cpu = threadSeconds() - t0;
        row.failure = built.errors.empty() ? "not built" : built.errors.front();
        return row;
    }
    // The hinge events counted as they come, so that a long run does not
    // keep them all; no frames (jl/sim/recording.h).
    struct HingeEvents : RecordTarget {
        int count = 0;
        bool frame(const Frame&) override { return true; }
        bool event(const Event& e) override {
            count += e.hinge > 0;
            return true;
        }
    } events;
    const Recording r = record(*built.simulation, row.asked, FrameGrid{}, &events);
    row.cpu = threadSeconds() - t0;
    row.simulated = r.time;
    row.hingeEvents = events.count;
    row.failure = r.failure;
    row.steps = r.solver.steps;
    row.automaticStep = r.solver.automaticStep;
    row.smallestStep = r.solver.smallestStep;
    row.largestStep = r.solver.largestStep;
    row.stepHalvings = r.solver.stepHalvings;
    std::fprintf(stderr,
                 "  example %-34s %5d blocks: %.2f of %.2f s in %.3f CPU s (%.3f per simulated s), %lld steps%s\n",
                 row.scene.c_str(), row.blocks, row.simulated, row.asked, row.cpu, row.perSimulated(), row.steps,
                 row.failure.empty() ? "" : (", failed: " + row.failure).c_str());
    return row;
}

}  // namespace

ExamplesStudy examplesStudy(const BenchPlan& plan, const std::filesystem::path& dir) {
    ExamplesStudy s;
    s.dir = dir;
    const double horizon = plan.quick ? 1.0 : 3.0;
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    if (ec || files.empty()) {
        s.error = "no scenes in " + dir.string() + (ec ? ": " + ec.message() : "") +
                  " (run from the source tree or pass --examples DIR)";
        std::fprintf(stderr, "  %s\n", s.error.c_str());
        return s;
    }
    std::sort(files.begin(), files.end());
    for (const std::filesystem::path& file : files) {
        const std::string name = file.filename().string();
        const SceneLoad load = loadScene(file.string());
        if (!load.scene) {
            ExampleRow row;
            row.scene = name;
            row.failure = load.errors.empty() ? "not loaded" : load.errors.front().message;
            s.rows.push_back(row);
            continue;
        }
        s.rows.push_back(runScene(name, *load.scene, horizon));
        if (name == kLong && !plan.quick && load.scene->ladder) {
            Scene longer = *load.scene;
            longer.ladder->blocks = kLongBlocks;
            s.rows.push_back(runScene(name + " x 1,000 blocks", longer, horizon));
        }
    }
    return s;
}

}  // namespace jl::bench
