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

#include <QtTest>

#include <cmath>
#include <numbers>
#include <random>

using namespace jl;

namespace {

constexpr double L = 0.06, T = 0.012, W = 0.045, rho = 600, g = 9.81;

// A block swinging from a corner pinned to the ground, released at theta0
// from its hanging pose; after one exact period it is back where it began.
double errorAfterOnePeriod(double theta0, int n) {
    const double mass = rho * L * T * W, r = std::hypot(L / 2, T / 2);
    const double inertia = mass * (L * L + T * T) / 12 + mass * r * r;
    const Vec2 corner(-L / 2, -T / 2);
    const double rest = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x());
    World w;
    const PartId block = w.addBox(mass, Vec2(L, T), W, Pose{-rotate(rest + theta0, corner), rest + theta0});
    w.combine(w.anchor(Vec2::Zero()), w.addParticle(block, corner));
    const double period = pendulumPeriod(inertia, mass, g, r, theta0), h = period / n;
    Dynamics d;
    Stepper s(Integrator::RosenbrockW);
    Ledger ledger;
    for (int i = 0; i < n; ++i)
        if (!advanceAndProject(w, d, s, i * h, h, ledger, 1e-13, true).ok()) return INFINITY;
    const double omegaScale = std::sqrt(mass * g * r / inertia);
    return std::hypot(w.partPose(block).angle - rest - theta0, w.partVelocity(block).angular / omegaScale);
}

// A ladder of n blocks hanging at rest from its held top block, every block
// given a small random spin (made consistent with the pins): all its modes
// ring, the fastest (each block rocking against its neighbours) included.
struct RingingLadder {
    World world;
    std::optional<Ladder> ladder;
    explicit RingingLadder(int n) {
        LadderSpec spec;
        spec.blocks = n;
        ladder.emplace(world, spec);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> spin(-0.05, 0.05);  // rad/s
        for (int b = 0; b < world.bodyCount(); ++b)
            if (world.invMassDiag[3 * b + 2] > 0) world.v[3 * b + 2] = spin(random);
        PinSolver solver;
        projectVelocities(world, solver);
    }
};

struct RunResult {
    bool ok = true;
    double largestEnergy = 0;  // J above the start, the most over the run
    double finalKinetic = 0;
};

RunResult ring(RingingLadder& l, Integrator kind, double h, int steps) {
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

}  // namespace

class LinearlyImplicitTest : public QObject {
    Q_OBJECT
private slots:
    // With fixed steps it converges at third order to the exact elliptic
    // period, whatever W is (a W-method's order does not depend on it).
    void convergesAtThirdOrderOnTheExactPendulum() {
        const double e1 = errorAfterOnePeriod(0.5, 200), e2 = errorAfterOnePeriod(0.5, 400);
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
        RingingLadder probe(n);
        Dynamics d;
        d.evaluate(probe.world, 0);
        const double omega = fastestVibration(probe.world, d.pinForces());
        const double h = 8 * imaginaryStabilityLimit(Integrator::RK4) / omega;
        qInfo("fastest vibration %.0f rad/s; step %.3g s, 8x RK4's limit", omega, h);

        RingingLadder explicitRun(n);
        const RunResult rk4 = ring(explicitRun, Integrator::RK4, h, 60);
        qInfo("RK4: %s, energy up to %.3g J above the start", rk4.ok ? "finite" : "stopped", rk4.largestEnergy);
        const double e0 = std::abs(energy(explicitRun.world).potential) + 1;
        QVERIFY2(!rk4.ok || rk4.largestEnergy > 1e-3 * e0,
                 qPrintable(QString("RK4 made only %1 J").arg(rk4.largestEnergy)));

        RingingLadder implicitRun(n);
        const double kinetic0 = energy(implicitRun.world).kinetic;
        const RunResult ros = ring(implicitRun, Integrator::RosenbrockW, h, 60);
        QVERIFY(ros.ok);
        qInfo("Rosenbrock-W: energy at most %.3g J above the start; kinetic %.3g J -> %.3g J", ros.largestEnergy,
              kinetic0, ros.finalKinetic);
        QVERIFY2(ros.largestEnergy <= 1e-9 * e0, qPrintable(QString::number(ros.largestEnergy)));
        QVERIFY(pinResidual(implicitRun.world) < 1e-9);
    }

    // The classic cascade as the adaptive explicit method gives it at a
    // tight tolerance: the same events in the same order, at the same
    // instants to 1e-6 s, and books that balance.
    void classicCascadeAgreesWithTheExplicitMethods() {
        auto run = [](Integrator kind, double tolerance) {
            SceneLoad loaded = loadScene(std::string(JL_SOURCE_DIR) + "/examples/classic.yaml");
            Scene s = *loaded.scene;
            s.solver.integrator = kind;
            s.solver.tolerance = tolerance;
            Simulation::Built built = Simulation::build(s);
            built.simulation->advanceExactlyTo(3.0);
            return built.simulation->frame();
        };
        const Frame reference = run(Integrator::DormandPrince45, 1e-11);
        const Frame ros = run(Integrator::RosenbrockW, 1e-9);
        QVERIFY(reference.failure.empty());
        QVERIFY2(ros.failure.empty(), ros.failure.c_str());
        QCOMPARE(ros.events.size(), reference.events.size());
        double worst = 0;
        for (size_t i = 0; i < ros.events.size(); ++i) {
            QCOMPARE(int(ros.events[i].kind), int(reference.events[i].kind));
            QCOMPARE(ros.events[i].hinge, reference.events[i].hinge);
            worst = std::max(worst, std::abs(ros.events[i].time - reference.events[i].time));
        }
        qInfo("%zu events, worst time difference %.2e s; books off by %.2e J at the end", ros.events.size(), worst,
              ros.energy.balance());
        QVERIFY(worst < 1e-6);
        QVERIFY(std::abs(ros.energy.balance()) < 1e-8);
    }
};

QTEST_GUILESS_MAIN(LinearlyImplicitTest)
#include "test_linearly_implicit.moc"
