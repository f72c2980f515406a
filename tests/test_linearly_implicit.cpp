// labels: physics
// The linearly implicit integrator (Rosenbrock-W ROS34PW2, docs/model.md
// section 6.4): third order on the exact pendulum, stable far past the
// explicit limit on a hanging ladder's fastest mode, and the classic
// cascade's events and books as the explicit methods give them.
#include "jl/engine/energy.h"
#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/engine/stable_step.h"
#include "jl/ladder/ladder.h"
#include "jl/reference/elliptic.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "tests/integrator_cases.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace jl;
using namespace jl::test;

namespace {

struct RunResult {
    bool ok = true;
    double largestEnergy = 0;  // J above the start, the most over the run
    double finalKinetic = 0;
};

RunResult ring(test::RingingLadder& l, Integrator kind, double h, int steps) {
    Dynamics d;
    Stepper s(kind);
    Ledger ledger;
    const double e0 = energy(l.world).total();
    RunResult r;
    for (int i = 0; i < steps && r.ok; ++i) {
        r.ok = advanceAndProject(l.world, d, s, i * h, h, ledger, 1e-10, true).ok();
        const double e = energy(l.world).total() - e0;
        r.ok = r.ok && std::isfinite(e);
        r.largestEnergy = std::max(r.largestEnergy, e);
    }
    r.finalKinetic = energy(l.world).kinetic;
    return r;
}

// Three blocks 60 x 12 x 45 mm: the first hangs from its corner (-L/2,
// -T/2) pinned to the ground, turned 0.8 rad from hanging; each of the
// others hangs by its own corner from one of the first block's two
// neighbouring corners, straight down.
World branched() {
    constexpr double L = 0.06, T = 0.012, W = 0.045, mass = 600 * L * T * W;
    World w;
    const Vec2 corner(-L / 2, -T / 2);
    const double top = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x()) + 0.8;
    const PartId a = w.addBox(mass, Vec2(L, T), W, Pose{-rotate(top, corner), top});
    combineClosed(w, w.anchor(Vec2::Zero()), w.addParticle(a, corner));
    for (const Vec2& at : {Vec2(L / 2, -T / 2), Vec2(-L / 2, T / 2)}) {
        const Vec2 point = w.pointPosition(a, at);
        const double hang = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x());
        const PartId b = w.addBox(mass, Vec2(L, T), W, Pose{point - rotate(hang, corner), hang});
        combineClosed(w, w.addParticle(a, at), w.addParticle(b, corner));
    }
    return w;
}

}  // namespace

class LinearlyImplicitTest : public QObject {
    Q_OBJECT
private slots:
    // With fixed steps it converges at third order to the exact elliptic
    // period, whatever W is (a W-method's order does not depend on it).
    void convergesAtThirdOrderOnTheExactPendulum() {
        const double e1 = test::pendulumErrorAfterOnePeriod(Integrator::RosenbrockW, 0.5, 200),
                     e2 = test::pendulumErrorAfterOnePeriod(Integrator::RosenbrockW, 0.5, 400);
        const double order = std::log2(e1 / e2);
        qInfo("error %.3e with 200 steps, %.3e with 400: order %.3f", e1, e2, order);
        QVERIFY2(std::abs(order - 3) < 0.25, qPrintable(QString::number(order)));
        QVERIFY(e2 < 1e-6);
    }

    // The hanging ladder's fastest mode bounds the explicit step: RK4 at 8
    // times its stability limit for that mode runs away within 60 steps; the
    // linearly implicit method at the same step stays finite, makes no
    // energy (it damps what it cannot resolve) and keeps the pins.
    void stableFarPastTheExplicitLimitOnAHangingLadder() {
        const int n = 400;
        test::RingingLadder probe(n);
        Dynamics d;
        d.evaluate(probe.world, 0);
        const double omega = fastestVibration(probe.world, d.pinForces());
        const double h = 8 * imaginaryStabilityLimit(Integrator::RK4) / omega;
        qInfo("fastest vibration %.0f rad/s; step %.3g s, 8x RK4's limit", omega, h);

        test::RingingLadder explicitRun(n);
        const RunResult rk4 = ring(explicitRun, Integrator::RK4, h, 60);
        qInfo("RK4: %s, energy up to %.3g J above the start", rk4.ok ? "finite" : "stopped", rk4.largestEnergy);
        const double e0 = std::abs(energy(explicitRun.world).potential) + 1;
        QVERIFY2(!rk4.ok || rk4.largestEnergy > 1e-3 * e0,
                 qPrintable(QString("RK4 made only %1 J").arg(rk4.largestEnergy)));

        test::RingingLadder implicitRun(n);
        const double kinetic0 = energy(implicitRun.world).kinetic;
        const RunResult ros = ring(implicitRun, Integrator::RosenbrockW, h, 60);
        QVERIFY(ros.ok);
        qInfo("Rosenbrock-W: energy at most %.3g J above the start; kinetic %.3g J -> %.3g J", ros.largestEnergy,
              kinetic0, ros.finalKinetic);
        QVERIFY2(ros.largestEnergy <= 1e-9 * e0, qPrintable(QString::number(ros.largestEnergy)));
        QVERIFY(pinResidual(implicitRun.world) < 1e-9);
    }

    // A branched structure takes the sparse factorisation for the step's
    // matrix too (a block hanging by one corner from the ground, with a
    // block hanging from each of its two other free corners: three pins on
    // one body). Released from rest, it keeps third order against the
    // adaptive explicit method at a tight tolerance, and its energy.
    void convergesAtThirdOrderOnABranchedStructure() {
        const auto run = [](Integrator kind, int steps) {
            World w = branched();
            Dynamics d;
            Stepper s(kind, 1e-12);
            Ledger ledger;
            const double e0 = energy(w).total(), end = 0.3;
            const bool adaptive = steps == 0;
            double t = 0;
            while (t < end - 1e-15) {
                const double h = adaptive ? end - t : end / steps;
                const MotionStep m = advanceAndProject(w, d, s, t, h, ledger, 1e-13, !adaptive);
                if (!m.ok()) return std::pair<World, double>(std::move(w), INFINITY);
                t += m.step.taken;
            }
            const double drift = std::abs(energy(w).total() - e0);
            return std::pair<World, double>(std::move(w), drift);
        };
        const auto [reference, referenceDrift] = run(Integrator::DormandPrince45, 0);
        QVERIFY(referenceDrift < 1e-10);
        const auto distance = [&](const World& w) {
            double worst = 0;
            for (PartId p = 1; p < w.partCount(); ++p)
                worst = std::max(worst, (w.partPose(p).position - reference.partPose(p).position).norm());
            return worst;
        };
        const auto [coarse, coarseDrift] = run(Integrator::RosenbrockW, 60);
        const auto [fine, fineDrift] = run(Integrator::RosenbrockW, 120);
        const double e1 = distance(coarse), e2 = distance(fine), order = std::log2(e1 / e2);
        qInfo("block centres %.3e m off with 60 steps, %.3e with 120: order %.3f; energy %.2e J, %.2e J", e1, e2, order,
              coarseDrift, fineDrift);
        QVERIFY2(std::abs(order - 3) < 0.3, qPrintable(QString::number(order)));
        QVERIFY(e2 < 1e-5);
        QVERIFY(fineDrift < 1e-4);
    }

    // The classic cascade as the adaptive explicit method gives it at a
    // tight tolerance: the same events in the same order, at the same
    // instants to 1e-6 s, and books that balance.
    void classicCascadeAgreesWithTheExplicitMethods() {
        const Frame reference = test::classicCascade(Integrator::DormandPrince45, 1e-11);
        const Frame ros = test::classicCascade(Integrator::RosenbrockW, 1e-9);
        QVERIFY(reference.failure.empty());
        QVERIFY2(ros.failure.empty(), ros.failure.c_str());
        const double worst = test::worstEventTimeDifference(ros, reference);
        qInfo("%zu events, worst time difference %.2e s; books off by %.2e J at the end", ros.events.size(), worst,
              ros.energy.balance());
        QVERIFY(worst < 1e-6);
        QVERIFY(std::abs(ros.energy.balance()) < 1e-8);
    }
};

QTEST_GUILESS_MAIN(LinearlyImplicitTest)
#include "test_linearly_implicit.moc"
