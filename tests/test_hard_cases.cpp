// labels: hard
// Hard cases of issue 7: each must end without a crash and without NaN, with
// the energy balance of PHYSICS.md section 7 and the pin residual in bounds,
// or stop with a clear diagnostic while keeping the last good state.
// Short forms by default (CI); JL_SOAK=1 runs the long forms.
#include "core/falling_chain.h"
#include "core/motion.h"
#include "core/simulation.h"

#include <QtTest>
#include <cmath>
#include <cstdlib>
#include <numbers>

using namespace jl;

namespace {

bool soak() { return std::getenv("JL_SOAK") && std::string(std::getenv("JL_SOAK")) == "1"; }

constexpr double kPi = std::numbers::pi;

Scene ladderScene(int blocks) {
    Scene s;
    s.ladder = LadderSpec{};
    s.ladder->blocks = blocks;
    return s;
}

ScriptAction turn(double at, double angle, double duration) {
    ScriptAction a;
    a.at = at;
    a.angle = angle;
    a.duration = duration;
    return a;
}

// What a run did, frame by frame.
struct Outcome {
    bool finite = true;        // every pose and energy of every frame
    double worstBalance = 0;   // J, |E - (E0 + W_held + W_user - D)|
    double worstResidual = 0;  // m, pin gap after a step
    double energyScale = 0;    // J, m_total g (ladder height): what "small" is measured against
    std::string failure;
    long long events = 0;
    double time = 0;
    double until = 0;          // s, the time asked for
};

Outcome run(const Scene& scene, double until, double frameInterval = 0.01) {
    Outcome o;
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
    for (double t = frameInterval; t <= until + 1e-12; t += frameInterval) {
        sim.advanceTo(t);
        const Frame f = sim.frame();
        for (const Pose& p : f.blocks)
            if (!p.position.allFinite() || !std::isfinite(p.angle)) o.finite = false;
        if (!std::isfinite(f.energy.balance())) o.finite = false;
        o.worstBalance = std::max(o.worstBalance, std::abs(f.energy.balance()));
        o.worstResidual = std::max(o.worstResidual, f.solver.residual);
        o.events += (long long)f.events.size();
        o.time = f.time;
        if (!f.failure.empty()) {
            o.failure = f.failure;
            break;
        }
    }
    qInfo("t = %.3f s, %lld events, balance %.2e J (scale %.2e J), residual %.2e m%s%s", o.time, o.events,
          o.worstBalance, o.energyScale, o.worstResidual, o.failure.empty() ? "" : ", stopped: ", o.failure.c_str());
    return o;
}

// The common pass criterion of a run that must complete.
void requireSound(const Outcome& o, double relativeBalance = 1e-6) {
    QVERIFY(o.finite);
    QVERIFY2(o.failure.empty(), o.failure.c_str());
    QVERIFY(o.time >= o.until - 1e-9);
    QVERIFY2(o.worstBalance <= relativeBalance * o.energyScale,
             qPrintable(QString("balance %1 J of scale %2 J").arg(o.worstBalance).arg(o.energyScale)));
    QVERIFY2(o.worstResidual <= 1e-8, qPrintable(QString::number(o.worstResidual)));
}

// The criterion of a run allowed to stop: if it stops, it says why, and the
// state it keeps is finite.
void requireSoundOrDiagnosed(const Outcome& o) {
    QVERIFY(o.finite);
    if (!o.failure.empty()) QVERIFY(o.failure.size() > 10);
}

}  // namespace

class HardCasesTest : public QObject {
    Q_OBJECT
private slots:
    void massRatioOfTenThousandBetweenNeighbours() {
        // The light blocks above the heavy one carry 10,000x their weight:
        // their hinges are stiff. The adaptive method must get through;
        // RK4 at 1 ms is past its stability limit and must say so.
        Scene s = ladderScene(6);
        BlockOverride heavy;
        heavy.index = 3;
        heavy.mass = 1e4 * s.ladder->block.density * s.ladder->block.length * s.ladder->block.thickness * s.ladder->block.width;
        s.ladder->overrides.push_back(heavy);
        s.script.push_back(turn(0.1, kPi, 0.3));
        s.solver.integrator = Integrator::DormandPrince45;
        s.solver.tolerance = 1e-8;
        requireSound(run(s, soak() ? 5.0 : 1.0));
        s.solver.integrator = Integrator::RK4;
        requireSoundOrDiagnosed(run(s, 1.0));
    }

    void longLadderTurnedOver() {
        // RK4 at 1 ms is past its stability limit at the top of a 10,000-block
        // ladder (the hanging weight makes the top hinges stiff); 0.5 ms is not.
        Scene s = ladderScene(soak() ? 10000 : 1000);
        s.solver.step = soak() ? 5e-4 : 1e-3;
        s.script.push_back(turn(0.0, kPi, 0.3));
        requireSound(run(s, soak() ? 0.5 : 0.05));
    }

    void tenThousandBlocksAtOneMillisecondStopsWithADiagnostic() {
        if (!soak()) QSKIP("long form only (JL_SOAK=1)");
        Scene s = ladderScene(10000);
        const Outcome o = run(s, 0.1);
        requireSoundOrDiagnosed(o);
    }

    void violentDragTenMetresAwayForOneSecond() {
        Scene s = ladderScene(6);
        DragRecord d;
        d.block = 5;
        d.samples.push_back({0.05, {10.0, 0.0}});
        d.end = 1.05;
        s.drags.push_back(d);
        // The capped, stiff mouse spring drives ~2,000 events: 1e-4 of the scale.
        requireSound(run(s, soak() ? 3.0 : 1.5), 1e-4);
    }

    void explicitEulerBeyondItsStabilityLimitIsReported() {
        Scene s = ladderScene(200);
        s.solver.integrator = Integrator::ExplicitEuler;
        s.solver.step = 5e-3;
        s.script.push_back(turn(0.0, kPi, 0.3));
        const Outcome o = run(s, 1.0);
        QVERIFY(o.finite);
        QVERIFY2(!o.failure.empty(), "explicit Euler at 5 ms on 200 blocks should be detected as unstable");
    }

    void severalEventsInOneStepFromASymmetricStart() {
        // Every hinge starts open at its limit: they all lock at t = 0.
        Scene s = ladderScene(8);
        s.ladder->initial.kind = InitialState::Kind::FoldAngles;
        s.ladder->initial.foldAngles.assign(7, 0.0);
        requireSound(run(s, soak() ? 5.0 : 1.0));
    }

    void veryThinBlocks() {
        Scene s = ladderScene(10);
        s.ladder->block.thickness = s.ladder->block.length / 1000;
        s.script.push_back(turn(0.1, kPi, 0.3));
        // Measured: ~50,000 events in 1.5 s (reported to the lead as likely
        // chattering); the books must still balance.
        requireSound(run(s, soak() ? 5.0 : 1.5), 1e-5);
    }

    void restitutionNineFiveDoesNotChatterForever() {
        Scene s = ladderScene(6);
        s.ladder->hinges.restitution = 0.95;
        s.script.push_back(turn(0.1, kPi, 0.3));
        const double until = soak() ? 10.0 : 2.0;
        const Outcome o = run(s, until);
        requireSound(o);
        // Bounded: at most a few hundred events per simulated second.
        QVERIFY2(o.events < 500 * until, qPrintable(QString::number(o.events)));
    }

    void longRunWithoutDampingKeepsItsEnergy() {
        Scene s = ladderScene(6);
        s.ladder->initial.kind = InitialState::Kind::FoldAngles;
        s.ladder->initial.foldAngles = {0.5, 1.0, 1.5, 1.0, 0.5};
        const double until = soak() ? 3600.0 : 60.0;
        requireSound(run(s, until, 1.0), 1e-5);
    }

    void stormOfScriptedCutsAndJoins() {
        Scene s = ladderScene(12);
        for (int k = 0; k < 20; ++k) {
            ScriptAction cut;
            cut.kind = ScriptAction::Kind::Cut;
            cut.at = 0.05 + 0.05 * k;
            cut.hinge = 1 + (k * 5) % 11;
            s.script.push_back(cut);
            ScriptAction join;
            join.kind = ScriptAction::Kind::Join;
            join.at = 0.075 + 0.05 * k;
            join.block = (k * 7) % 11;
            join.otherBlock = join.block + 1;
            join.corner = join.otherCorner = (k % 2) ? 0 : 3;
            s.script.push_back(join);
        }
        const Outcome o = run(s, soak() ? 3.0 : 1.2);
        requireSoundOrDiagnosed(o);
        QEXPECT_FAIL("", "a scripted join moves and merges blocks without booking the energy it takes (reported)", Continue);
        QVERIFY2(o.worstBalance <= 1e-6 * o.energyScale, qPrintable(QString("balance %1 J").arg(o.worstBalance)));
    }

    void heldBlockTurnedAtOneHundredTurnsPerSecond() {
        Scene s = ladderScene(6);
        s.script.push_back(turn(0.1, 2 * kPi * 10, 0.1));  // 10 turns in 0.1 s
        const Outcome o = run(s, soak() ? 2.0 : 0.5);
        requireSoundOrDiagnosed(o);
    }

    void adaptiveRecoversFromARejectedFirstStep() {
        // Regression: a rejected trial used to leave its end state for the
        // next trial's first stage; a first trial of 0.5 s is all NaN.
        World w;
        buildFallingChain(w, 10);
        Dynamics d;
        Stepper st(Integrator::DormandPrince45, 1e-6);
        Ledger ledger;
        double t = 0;
        int steps = 0;
        while (t < 0.5 && steps < 100000) {
            const MotionStep m = advanceAndProject(w, d, st, t, 0.5 - t, ledger, 1e-10);
            QVERIFY(m.ok());
            t += m.step.taken;
            ++steps;
        }
        QVERIFY(t >= 0.5 - 1e-12);
    }
};

QTEST_GUILESS_MAIN(HardCasesTest)
#include "test_hard_cases.moc"
