// Test support for the examples' claims: an example's description is a
// claim, checked at the scene's own settings (tests/test_examples.cpp and the
// lessons with a file of their own).
#pragma once

#include "tests/scene_run.h"

#include <QtTest>

#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <vector>

namespace jl::test {

// What "small" means for the energy books of a ladder: lifting all of it
// through its own height, m g N L (1 J for the classic ladder).
inline double energyScale(const Simulation& sim) {
    double mass = 0;
    for (int i = 0; i < sim.blockCount(); ++i) mass += sim.world().part(sim.blockPart(i)).mass;
    const LadderSpec* l = sim.scene().ladder ? &*sim.scene().ladder : nullptr;
    return mass * 9.81 * (l ? l->blocks * l->block.length : 1.0);
}

// First flip time of each hinge that flipped, by hinge; and the flips after `from`.
inline std::map<int, double> firstFlips(const std::vector<Event>& events, double from = 0) {
    std::map<int, double> first;
    for (const Event& e : events)
        if (e.kind == EventKind::FlipFlop && e.time >= from && !first.count(e.hinge)) first[e.hinge] = e.time;
    return first;
}

// No failure, the books balanced to the integration error of the scene's
// own step (RK4 at 1 ms loses up to 1.1e-4 of the scale while the heavy
// block of heavy-middle.yaml swings near 1.82 s, no event in those steps;
// 2.7e-7 J at 0.25 ms), the pins closed to the projection tolerance (the
// examples keep the default, 1e-10 m) after every step and its events, and
// no hinge chattering. At the bottom of long-ladder.yaml's 200 thin blocks
// impacts come a fraction of a millisecond apart, and each may knock a
// closed contact open (held ones too, docs/model.md section 8.6): a hinge
// there goes through up to four quick cycles in a row, in two bursts.
inline void requireSoundRun(const Run& r, double scale) {
    QVERIFY2(r.failure.empty(), r.failure.c_str());
    QVERIFY2(r.worstResidual <= 1e-10 * 1.0000001, qPrintable(QString("pin gap %1 m").arg(r.worstResidual)));
    QVERIFY2(r.worstBalance < 2e-4 * scale, qPrintable(QString("%1 J of %2 J").arg(r.worstBalance).arg(scale)));
    const Chatter c = chatter(r.events);
    QVERIFY2(c.longest <= 4, qPrintable(QString("%1 quick cycles of one hinge in a row").arg(c.longest)));
}

// The scene of docs/scene-format.md's "A complete example", as loaded (its
// errors, if any, in `errors`).
inline SceneLoad formatPageExample() {
    std::ifstream page(std::string(JL_SOURCE_DIR) + "/docs/scene-format.md");
    const std::string text((std::istreambuf_iterator<char>(page)), std::istreambuf_iterator<char>());
    const std::size_t section = text.find("## A complete example");
    const std::size_t start = text.find("```yaml\n", section), end = text.find("```", start + 8);
    if (section == std::string::npos || start == std::string::npos || end == std::string::npos) return {};
    return parseScene(text.substr(start + 8, end - start - 8), "docs/scene-format.md");
}

// An example's scene, to run at other settings than its own.
inline Scene exampleScene(const char* name) {
    SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/examples/" + name);
    return load.scene ? *load.scene : Scene{};
}

}  // namespace jl::test
