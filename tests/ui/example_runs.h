// Example scenes run by the engine alone, headless, for the UI tests to hold
// what the window shows against.
#pragma once

#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"

#include <QString>
#include <QtGlobal>

#include <vector>

inline QString example(const char* name) { return QString(JL_SOURCE_DIR) + "/examples/" + name; }

inline jl::Scene loadExample(const char* name) {
    const jl::SceneLoad load = jl::loadScene(example(name).toStdString());
    if (!load.scene) qFatal("%s does not load", name);
    return *load.scene;
}

// The engine's frames at the scene's frame interval, as the timeline records them.
struct Run {
    std::vector<jl::Frame> frames;
    std::vector<jl::Event> events;
};

inline Run runHeadless(const jl::Scene& scene, double until) {
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) qFatal("the scene does not build");
    Run r;
    const double dt = scene.solver.frameInterval;
    for (int i = 0; i * dt <= until + 1e-12; ++i) {
        built.simulation->advanceTo(i * dt);
        r.frames.push_back(built.simulation->frame());
        for (const jl::Event& e : r.frames.back().events) r.events.push_back(e);
    }
    return r;
}
