// The desktop program's window on a scene, for the tests of playing it
// (test_playback.cpp) and of the user's hand in it (test_drag_replay.cpp),
// and the same runs made directly on the engine to compare with.
#pragma once

#include "jl/sim/recording.h"
#include "jl/sim/simulation.h"
#include "ui/view3d/ladder_view.h"
#include "ui_test_support.h"

#include <QDoubleSpinBox>
#include <QtTest>

#include <memory>
#include <optional>

namespace jl::test {

using namespace jl::ui;

// The same run the window makes, done directly on the engine: the state
// at the end of the step that passes i * interval...
inline std::unique_ptr<jl::Simulation> engineAt(const jl::Scene& scene, int index) {
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) qFatal("the scene does not build");
    built.simulation->advanceTo(index * scene.solver.frameInterval);
    return std::move(built.simulation);
}
// ...and frame i, the state at exactly i * interval, as the command line's
// recording takes it (from the dense output of the step that passes it).
inline jl::Frame engineFrameAt(const jl::Scene& scene, int index) {
    struct Keep : jl::RecordTarget {
        double at = 0;
        jl::Frame kept;
        bool frame(const jl::Frame& f) override {
            if (f.time == at) kept = f;
            return true;
        }
        bool event(const jl::Event&) override { return true; }
    } keep;
    const double every = scene.solver.frameInterval;
    keep.at = jl::FrameGrid{0, every}.at(index);
    auto built = jl::Simulation::build(scene);
    if (!built.simulation) qFatal("the scene does not build");
    (void)jl::record(*built.simulation, (index + 1) * every, jl::FrameGrid{0, every}, &keep);
    if (keep.kept.time != keep.at) qFatal("no frame at %g s", keep.at);
    return keep.kept;
}
inline std::uint64_t engineHashAt(const jl::Scene& scene, int index) { return engineAt(scene, index)->stateHash(); }

// A ladder of `blocks` default blocks hanging at rest (no script).
inline jl::Scene hangingLadder(int blocks) {
    jl::Scene scene;
    scene.ladder = jl::LadderSpec{};
    scene.ladder->blocks = blocks;
    return scene;
}

// The same on the full model: every block its own body from the start, as
// when the motion has reached them all (hanging at rest, a long ladder's
// blocks join into a still tail and a step costs next to nothing). For the
// tests of what the window says while a long run takes seconds.
inline jl::Scene slowHangingLadder(int blocks) {
    jl::Scene scene = hangingLadder(blocks);
    scene.solver.stillTail = jl::StillTail::Separate;
    return scene;
}

inline bool samePoses(const jl::Frame& a, const jl::Frame& b) {
    if (a.poses.size() != b.poses.size()) return false;
    for (size_t i = 0; i < a.poses.size(); ++i)
        if (a.poses[i].position != b.poses[i].position || a.poses[i].angle != b.poses[i].angle) return false;
    return true;
}

struct Fixture {
    MainWindow window{jl::test::quietWindow()};
    SimController* sim = window.controller();
    explicit Fixture(const jl::Scene& scene) {
        window.resize(1300, 850);
        window.show();
        const auto before = jl::test::loadsSoFar(sim);
        window.document()->reset(scene, QString());
        if (!jl::test::loadedAfter(sim, before)) qFatal("the scene was not loaded");
    }
    // Where block `block` of the frame on screen is drawn, once the view
    // shows that frame (it takes the worker's status a moment later):
    // nothing if it never does.
    std::optional<QPoint> blockOnScreen(int block) {
        LadderView* view = window.ladderView();
        const QPoint at = view->pixelOf(sim->status()->frame->poses[size_t(block)].position).toPoint();
        const bool shown = QTest::qWaitFor([&] {
            const auto p = view->planePoint(at);
            return p && view->blockAt(*p);
        });
        return shown ? std::optional<QPoint>(at) : std::nullopt;
    }
    // An edit in the Ladder panel (the blocks' thickness, in mm); the loads so far before it.
    std::uint64_t editThickness(double mm) {
        const auto before = jl::test::loadsSoFar(sim);
        window.findChild<QDoubleSpinBox*>("thickness")->setValue(mm);
        return before;
    }
    // Simulates (paused) up to frame `index` and waits until it is on screen.
    bool goTo(int index, int timeoutMs = 20000) {
        const double dt = sim->status()->interval;
        sim->seek(index * dt + dt / 4);
        return jl::test::waitForStatus(
            sim, [index](const SimStatus& s) { return s.frameIndex == index && !s.playing; }, timeoutMs);
    }
};

}  // namespace jl::test
