// labels: physics;engine
// A held block's scripted turn (docs/model.md section 10): its angular
// acceleration jumps where the turn starts and where it stops, and each step
// must see the side of the jump that belongs to it. A step that ends where
// the hand stops sees the turn's acceleration at its end; the next step, and
// the force tests at that instant, see the stop's.
#include "jl/engine/drive.h"
#include "jl/sim/simulation.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace jl;

namespace {

// A ladder of `blocks` whose top block the hand turns a quarter turn from
// t = 0 over 0.3 s, run to 0.36 s with `integrator` at fixed steps of
// `step` (0: adaptive at `tolerance`).
Frame turned(int blocks, Integrator integrator, double step, double tolerance = 1e-8) {
    Scene s;
    s.ladder = LadderSpec{};
    s.ladder->blocks = blocks;
    ScriptAction turn;
    turn.at = 0;
    turn.angle = std::numbers::pi / 2;
    turn.duration = 0.3;
    s.script.push_back(turn);
    s.solver.integrator = integrator;
    s.solver.step = step;
    s.solver.tolerance = tolerance;
    Simulation::Built built = Simulation::build(s);
    built.simulation->advanceExactlyTo(0.36);
    return built.simulation->frame();
}

double largestDistance(const Frame& a, const Frame& b) {
    double worst = 0;
    for (size_t i = 0; i < a.poses.size(); ++i)
        worst = std::max(worst, (a.poses[i].position - b.poses[i].position).norm());
    return worst;
}

}  // namespace

class HeldTurnTest : public QObject {
    Q_OBJECT
private slots:
    // The profile (1 - cos(pi s)) / 2 of a turn by D over tau: angular
    // acceleration pi^2 D / (2 tau^2) just after the start, minus that just
    // before the end, zero outside.
    void theHandsAccelerationHasTwoSidesAtEachEndOfTheTurn() {
        const double D = std::numbers::pi / 2, tau = 0.3;
        const double peak = std::numbers::pi * std::numbers::pi * D / (2 * tau * tau);
        Drive drive;
        drive.add({0.1, tau, Vec2::Zero(), D});
        const double start = 0.1, end = 0.1 + tau;
        // An instant belongs to the piece that starts there.
        QCOMPARE(drive.at(start).acceleration.angular, peak);
        QCOMPARE(drive.at(end).acceleration.angular, 0.0);
        // A step's own side: the step before the start, and the one that
        // ends where the turn ends (a hair past it by rounding included).
        QCOMPARE(drive.at(start, start - 0.001).acceleration.angular, 0.0);
        QVERIFY(std::abs(drive.at(end, end - 0.001).acceleration.angular + peak) < 1e-12 * peak);
        QVERIFY(std::abs(drive.at(end + 1e-16, end - 0.001).acceleration.angular + peak) < 1e-9 * peak);
        QVERIFY(std::abs(drive.at(end, end - 0.001).pose.angle - D) < 1e-15);
        QVERIFY(drive.samePiece(0.2, 0.3) && !drive.samePiece(0.35, end) && drive.samePiece(end, end + 1));
    }

    // RK4 at fixed steps that land on the start and the stop of the turn
    // keeps its fourth order through both (seen the other way, the first
    // stage at the start and the last at the stop put an error of order h
    // into the step there, and the order fell to 3, with errors 50 to 100
    // times larger at these steps). Against Dormand-Prince at 1e-13.
    void rk4KeepsItsOrderThroughTheStartAndTheStop() {
        for (int blocks : {2, 3}) {
            const Frame reference = turned(blocks, Integrator::DormandPrince45, 0, 1e-13);
            QVERIFY(reference.failure.empty());
            const double e1 = largestDistance(turned(blocks, Integrator::RK4, 0.3 / 120), reference);
            const double e2 = largestDistance(turned(blocks, Integrator::RK4, 0.3 / 240), reference);
            const double order = std::log2(e1 / e2);
            qInfo("%d blocks: %.3e m at 2.5 ms, %.3e m at 1.25 ms: order %.2f", blocks, e1, e2, order);
            QVERIFY2(std::abs(order - 4) < 0.3, qPrintable(QString::number(order)));
        }
    }

    // An adaptive step that starts where the hand starts or ends where it
    // stops is accepted as any other: seen the other way, its first or last
    // stage had the wrong side's acceleration, and the error control crept
    // up to both instants with shrinking steps (35 and 38 rejected steps
    // here, against 1 and 3).
    void anAdaptiveStepRunsUpToTheStopWithoutBeingRejected() {
        for (Integrator method : {Integrator::DormandPrince45, Integrator::Verner65}) {
            const Frame f = turned(2, method, 0, 1e-8);
            qInfo("%s: %lld steps, %lld rejected", method == Integrator::Verner65 ? "verner65" : "dormand_prince45",
                  f.solver.steps, f.solver.rejected);
            QVERIFY(f.failure.empty());
            QVERIFY2(f.solver.rejected <= 5, qPrintable(QString::number(f.solver.rejected)));
        }
    }
};

QTEST_GUILESS_MAIN(HeldTurnTest)
#include "test_held_turn.moc"
