// Example scenes run by the engine alone, headless, for the UI tests to hold
// what the window shows against.
#pragma once

#include "jl/scene/scene_io.h"
#include "jl/sim/recording.h"

#include <QString>
#include <QtGlobal>

#include <utility>
#include <vector>

inline QString example(const char* name) { return QString(JL_SOURCE_DIR) + "/examples/" + name; }

inline jl::Scene loadExample(const char* name) {
    const jl::SceneLoad load = jl::loadScene(example(name).toStdString());
    if (!load.scene) qFatal("%s does not load", name);
    return *load.scene;
}

// The engine's frames at exactly each multiple of the scene's frame
// interval, ribbons in them, as the timeline records them, and every event.
struct Run {
    std::vector<jl::Frame> frames;
    std::vector<jl::Event> events;
};

inline Run runHeadless(const jl::Scene& scene, double until) {
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) qFatal("the scene does not build");
    jl::WholeRun whole;
    whole.ribbons = true;
    jl::record(*built.simulation, until, jl::FrameGrid{0, scene.solver.frameInterval}, &whole);
    return {std::move(whole.frames), std::move(whole.events)};
}
