// Test support for the hard cases (docs/model.md section 16.3): ladders
// and scripts built in code, a run recorded and checked step by step, and the two
// pass criteria (a run that must complete; a run allowed to stop with a
// diagnostic, keeping a sound state).
#pragma once

#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/reference/falling_chain.h"
#include "jl/sim/recording.h"
#include "jl/sim/simulation.h"

#include <QtTest>

#include <cmath>
#include <cstdlib>
#include <numbers>

namespace jl::test {

inline bool soak() { return std::getenv("JL_SOAK") && std::string(std::getenv("JL_SOAK")) == "1"; }

constexpr double kPi = std::numbers::pi;

inline Scene ladderScene(int blocks) {
    Scene s;
    s.ladder = LadderSpec{};
    s.ladder->blocks = blocks;
    return s;
}

inline ScriptAction turn(double at, double angle, double duration) {
    ScriptAction a;
    a.at = at;
    a.angle = angle;
    a.duration = duration;
    return a;
}

// What a run did, step by step.
struct Outcome {
    bool finite = true;        // every pose and energy after every step
    double worstBalance = 0;   // J, |E - (E0 + W_held + W_user - D)|
    double worstResidual = 0;  // m, pin gap after a step
    double energyScale = 0;    // J, m_total g (ladder height): what "small" is measured against
    double flowed = 0;         // J, the most energy that has flowed through the books (work in, losses out, kinetic)
    std::string failure;
    long long events = 0;
    double time = 0;
    double until = 0;  // s, the time asked for
};

// Records the run to `until` (jl/sim/recording.h), checking the state after
// every step (the last good one, when it stops on a failure).
inline Outcome run(const Scene& scene, double until) {
    struct EveryStep : RecordTarget {
        Outcome o;
        bool frame(const Frame&) override { return true; }
        bool event(const Event&) override { return true; }
        bool step(Simulation& sim) override {
            const Frame f = sim.frame();
            for (const Pose& p : f.poses)
                if (!p.position.allFinite() || !std::isfinite(p.angle)) o.finite = false;
            if (!std::isfinite(f.energy.balance())) o.finite = false;
            o.worstBalance = std::max(o.worstBalance, std::abs(f.energy.balance()));
            o.flowed = std::max(o.flowed, std::abs(f.energy.heldWork) + std::abs(f.energy.userWork) +
                                              f.energy.impactLoss + f.energy.dampingLoss + f.energy.kinetic);
            o.worstResidual = std::max(o.worstResidual, pinResidual(sim.world()));  // measured, not reported
            return true;
        }
    } target;
    Outcome& o = target.o;
    o.until = until;
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        o.failure = built.errors.empty() ? "not built" : built.errors.front();
        o.finite = false;
        return o;
    }
    Simulation& sim = *built.simulation;
    double mass = 0;
    for (int i = 0; i < sim.blockCount(); ++i) mass += sim.world().part(sim.blockPart(i)).mass;
    const double height = scene.ladder ? scene.ladder->blocks * scene.ladder->block.length : 1.0;
    o.energyScale = mass * 9.81 * height;
    const Recording r = record(sim, until, FrameGrid{}, &target);
    o.failure = r.failure;
    o.events = r.events;
    o.time = r.time;
    qInfo("t = %.3f s, %lld events, balance %.2e J (scale %.2e J), residual %.2e m%s%s", o.time, o.events,
          o.worstBalance, o.energyScale, o.worstResidual, o.failure.empty() ? "" : ", stopped: ", o.failure.c_str());
    return o;
}

// The common pass criterion of a run that must complete.
// The pins closed after every step and its events to the projection
// tolerance every scene here keeps, 1e-10 m (docs/model.md section 14.3).
constexpr double kLargestGap = 1e-10 * (1 + 1e-7);

inline void requireSound(const Outcome& o, double relativeBalance = 1e-6) {
    QVERIFY(o.finite);
    QVERIFY2(o.failure.empty(), o.failure.c_str());
    QVERIFY(o.time >= o.until - 1e-9);
    QVERIFY2(o.worstBalance <= relativeBalance * o.energyScale,
             qPrintable(QString("balance %1 J of scale %2 J").arg(o.worstBalance).arg(o.energyScale)));
    QVERIFY2(o.worstResidual <= kLargestGap, qPrintable(QString::number(o.worstResidual)));
}

// The criterion of a run allowed to stop: the state it keeps is sound (finite,
// the pins closed, the books balanced to what the checks allow), and if it
// stops it says when and why; if it does not, it ran the whole time.
inline void requireSoundOrDiagnosed(const Outcome& o) {
    QVERIFY(o.finite);
    QVERIFY2(o.worstResidual <= kLargestGap, qPrintable(QString::number(o.worstResidual)));
    // Relative to the ladder's weight lifted through its height, or to what
    // flowed through the books if more did (a hand spinning the top block at
    // 100 turns a second puts in 1,300 J where m g H is 0.4 J).
    const double scale = std::max(o.energyScale, o.flowed);
    QVERIFY2(o.worstBalance <= 3e-5 * scale,
             qPrintable(QString("balance %1 J of scale %2 J").arg(o.worstBalance).arg(scale)));
    if (o.failure.empty())
        QVERIFY(o.time >= o.until - 1e-9);
    else
        QVERIFY2(o.failure.rfind("at t = ", 0) == 0 && o.failure.size() > 30, o.failure.c_str());
}

// Two 60 x 12 x 45 mm blocks of density 600 (m = 19.44 g), block 0 held
// upright at the origin, block 1 hanging from hinge 1 at corner 0 in its
// equilibrium: its centre straight below the hinge, at rest.
constexpr double kL = 0.06, kT = 0.012, kG = 9.81;
constexpr double kMass = 600 * kL * kT * 0.045;

inline Scene hangingPair() { return ladderScene(2); }

inline ScriptAction scripted(ScriptAction::Kind kind, double at) {
    ScriptAction a;
    a.kind = kind;
    a.at = at;
    return a;
}

// Two blocks, block 0 held flat (-90 degrees) with hinge 1 on top at its
// left end, block 1 started at fold angle `phi` (1.4: it falls off the end
// and locks as a cantilever; 2.0: it topples onto block 0 and folds); from
// t = 1 s the hand turns block 0 by `turn` over 0.5 s.
inline Scene flatHeldBlock(double phi, double turnBy) {
    Scene s = ladderScene(2);
    s.ladder->initial.kind = InitialState::Kind::FoldAngles;
    s.ladder->initial.foldAngles = {phi};
    BlockState first;
    first.angle = -kPi / 2;
    s.ladder->initial.poses = {first};
    s.script.push_back(turn(1.0, turnBy, 0.5));
    return s;
}

}  // namespace jl::test
