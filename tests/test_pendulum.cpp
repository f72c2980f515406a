// labels: physics
// A block swinging from a corner pin against the exact physical-pendulum
// period (docs/model.md section 14.1), and each integrator's order of
// convergence.
#include "jl/engine/motion.h"
#include "jl/engine/world.h"
#include "jl/reference/elliptic.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/recording.h"
#include "tests/restructure_closed.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <vector>

using namespace jl;
using namespace jl::test;

namespace {

constexpr double L = 0.06, T = 0.012, W = 0.045, rho = 600, g = 9.81;

struct Pendulum {
    World world;
    PartId block = -1;
    double mass = rho * L * T * W;
    double r = std::hypot(L / 2, T / 2);
    double inertiaAboutPin = mass * (L * L + T * T) / 12 + mass * r * r;
    double rest = 0;  // angle of the block when hanging at rest

    explicit Pendulum(double theta0) {
        const Vec2 corner(-L / 2, -T / 2);
        rest = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x());
        const double angle = rest + theta0;
        const Vec2 centre = -rotate(angle, corner);  // corner at the origin
        block = world.addBox(mass, Vec2(L, T), W, Pose{centre, angle});
        combineClosed(world, world.anchor(Vec2::Zero()), world.addParticle(block, corner));
    }
    double swing() const { return world.partPose(block).angle - rest; }
    double period(double theta0) const { return pendulumPeriod(inertiaAboutPin, mass, g, r, theta0); }
};

// Runs one exact period in n equal steps; the error is how far the block is
// from where it started (angle and scaled angular speed).
double errorAfterOnePeriod(Integrator kind, double theta0, int n, double* residual = nullptr) {
    Pendulum p(theta0);
    const double period = p.period(theta0);
    const double h = period / n;
    Dynamics d;
    Stepper s(kind);
    Ledger ledger;
    double worst = 0;
    for (int i = 0; i < n; ++i) {
        const MotionStep m = advanceAndProject(p.world, d, s, i * h, h, ledger, 1e-12);
        if (!m.ok()) return INFINITY;
        worst = std::max(worst, pinResidual(p.world));
    }
    if (residual) *residual = worst;
    const double omegaScale = std::sqrt(p.mass * g * p.r / p.inertiaAboutPin);
    return std::hypot(p.swing() - theta0, p.world.partVelocity(p.block).angular / omegaScale);
}

double observedOrder(Integrator kind, double theta0, int n) {
    const double e1 = errorAfterOnePeriod(kind, theta0, n);
    const double e2 = errorAfterOnePeriod(kind, theta0, 2 * n);
    qInfo("error %.3e with %d steps, %.3e with %d: order %.3f", e1, n, e2, 2 * n, std::log2(e1 / e2));
    return std::log2(e1 / e2);
}

}  // namespace

class PendulumTest : public QObject {
    Q_OBJECT
private slots:
    void smallAmplitudePeriodMatchesLinearFormula() {
        const double theta0 = 1e-3;
        Pendulum p(theta0);
        const double linear = 2 * std::numbers::pi * std::sqrt(p.inertiaAboutPin / (p.mass * g * p.r));
        // The exact period differs from the linear one by theta0^2/16 relative.
        QVERIFY(std::abs(p.period(theta0) / linear - 1) < 1e-7);
        // Measured: the time of the second upward zero crossing of the swing.
        Dynamics d;
        Stepper s(Integrator::RK4);
        Ledger ledger;
        const double h = linear / 4000;
        double t = 0, prev = p.swing(), firstCrossing = -1, crossing = -1;
        while (crossing < 0 && t < 3 * linear) {
            QVERIFY(advanceAndProject(p.world, d, s, t, h, ledger, 1e-12).ok());
            t += h;
            const double now = p.swing();
            if (prev < 0 && now >= 0) {
                // Cubic Hermite root would be better; the step is tiny, and
                // linear interpolation errs by O(h^2) ~ 1e-8 of the period.
                const double tc = t - h * now / (now - prev);
                if (firstCrossing < 0)
                    firstCrossing = tc;
                else
                    crossing = tc;
            }
            prev = now;
        }
        QVERIFY(crossing > 0);
        QVERIFY2(std::abs((crossing - firstCrossing) / linear - 1) < 1e-6,
                 qPrintable(QString("measured %1 s, formula %2 s")
                                .arg(crossing - firstCrossing, 0, 'g', 12)
                                .arg(linear, 0, 'g', 12)));
    }

    void largeAmplitudeReturnsAfterExactEllipticPeriod() {
        // 150 degrees: the period is 1.76x the small-amplitude one.
        const double theta0 = 150 * std::numbers::pi / 180;
        double residual = 0;
        QVERIFY(errorAfterOnePeriod(Integrator::RK4, theta0, 2000, &residual) < 1e-8);
        QVERIFY(residual <= 1e-12);
    }

    void eulerConvergesAtFirstOrder() {
        const double order = observedOrder(Integrator::ExplicitEuler, 0.5, 20000);
        QVERIFY2(std::abs(order - 1) < 0.15, qPrintable(QString::number(order)));
    }

    void symplecticEulerConvergesAtFirstOrder() {
        const double order = observedOrder(Integrator::SymplecticEuler, 0.5, 20000);
        QVERIFY2(order > 0.85, qPrintable(QString::number(order)));
    }

    void rk4ConvergesAtFourthOrder() {
        const double order = observedOrder(Integrator::RK4, 0.5, 100);
        QVERIFY2(std::abs(order - 4) < 0.3, qPrintable(QString::number(order)));
    }

    // Two blocks end to end, joined at both corners of their shared face,
    // swing from a corner as one bar 2L x T: the exact period with the
    // bar's inertia, whether the pair is merged into one body or kept as
    // two bodies held by a pin and a weld (World::setWeldRigidPairs).
    void rigidPairSwingsAsOneBar_data() {
        QTest::addColumn<bool>("weld");
        QTest::newRow("merged") << false;
        QTest::newRow("welded") << true;
    }
    void rigidPairSwingsAsOneBar() {
        QFETCH(bool, weld);
        const double theta0 = 1.0, m = rho * L * T * W, M = 2 * m;
        const Vec2 corner(-L, -T / 2);  // the pivot, from the bar's centre
        const double r = corner.norm(), inertia = M * (4 * L * L + T * T) / 12 + M * r * r;
        const double rest = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x());
        const double angle = rest + theta0;
        const Vec2 centre = -rotate(angle, corner);
        World w;
        w.setWeldRigidPairs(weld);
        const PartId a = w.addBox(m, Vec2(L, T), W, Pose{centre + rotate(angle, Vec2(-L / 2, 0)), angle});
        const PartId b = w.addBox(m, Vec2(L, T), W, Pose{centre + rotate(angle, Vec2(L / 2, 0)), angle});
        QVERIFY(!combineClosed(w, w.anchor(Vec2::Zero()), w.addParticle(a, Vec2(-L / 2, -T / 2))));
        for (double y : {-T / 2, T / 2})
            QVERIFY(!combineClosed(w, w.addParticle(a, Vec2(L / 2, y)), w.addParticle(b, Vec2(-L / 2, y))));
        QCOMPARE(int(w.welds().size()), weld ? 1 : 0);
        QCOMPARE(w.part(a).body == w.part(b).body, !weld);
        const double period = pendulumPeriod(inertia, M, g, r, theta0);
        const int n = 2000;
        Dynamics d;
        Stepper s(Integrator::RK4);
        Ledger ledger;
        double worst = 0;
        for (int i = 0; i < n; ++i) {
            QVERIFY(advanceAndProject(w, d, s, i * period / n, period / n, ledger, 1e-12).ok());
            worst = std::max(worst, pinResidual(w));
        }
        const double swing = w.partPose(a).angle - rest;
        const double omegaScale = std::sqrt(M * g * r / inertia);
        const double error = std::hypot(swing - theta0, w.partVelocity(a).angular / omegaScale);
        QVERIFY2(error < 1e-8, qPrintable(QString::number(error)));
        QVERIFY(worst <= 1e-12);
        // The pair stays one rigid bar: same angle, same spin.
        QVERIFY(std::abs(w.partPose(b).angle - w.partPose(a).angle) < 1e-12);
        QVERIFY(std::abs(w.partVelocity(b).angular - w.partVelocity(a).angular) < 1e-10);
    }

    void adaptiveReachesOneInABillion() {
        const double theta0 = 2.0;
        Pendulum p(theta0);
        const double period = p.period(theta0);
        Dynamics d;
        Stepper s(Integrator::DormandPrince45, 1e-12);
        Ledger ledger;
        double t = 0;
        int steps = 0;
        while (t < period) {
            const MotionStep m = advanceAndProject(p.world, d, s, t, period - t, ledger, 1e-13);
            QVERIFY(m.ok());
            t += m.step.taken;
            ++steps;
        }
        const double relative = std::abs(p.swing() - theta0) / theta0;
        qInfo("adaptive: relative error %.3e in %d steps", relative, steps);
        QVERIFY2(relative < 1e-9, qPrintable(QString("relative error %1 in %2 steps").arg(relative).arg(steps)));
    }

    // Frames at exact times, read off the steps' dense output: the example
    // pendulum (30 degrees, the adaptive integrator) recorded every eighth of
    // its exact period has a frame at exactly each multiple, passing the
    // bottom at 1/4 and 3/4 and at its extremes at 1/2 and 1; and asking for
    // frames leaves the run itself as it was, bit for bit.
    void framesAtExactTimesFromTheDenseOutput() {
        struct Frames : RecordTarget {
            std::vector<Frame> kept;
            bool frame(const Frame& f) override {
                kept.push_back(f);
                return true;
            }
            bool event(const Event&) override { return true; }
        };
        const SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/examples/pendulum.yaml");
        QVERIFY(load.scene);
        const double m = rho * L * T * W, r = std::hypot(L, T) / 2, theta0 = std::numbers::pi / 6;
        const double period = pendulumPeriod(m * (L * L + T * T) / 3, m, g, r, theta0);
        const double every = period / 8, rest = -std::atan(T / L);

        auto withFrames = Simulation::build(*load.scene).simulation;
        Frames frames;
        const Recording a = record(*withFrames, 2 * period, FrameGrid{0, every}, &frames);
        QVERIFY(a.complete());
        QCOMPARE(int(frames.kept.size()), 17);
        for (int k = 0; k <= 16; ++k) {
            const Frame& f = frames.kept[size_t(k)];
            QCOMPARE(f.time, k * every);
            const double swing = f.poses[0].angle - rest;
            const double expected = k % 4 == 0 ? (k % 8 == 0 ? theta0 : -theta0) : k % 2 == 0 ? 0.0 : NAN;
            if (!std::isnan(expected))
                QVERIFY2(std::abs(swing - expected) < 1e-7, qPrintable(QString("k = %1: %2").arg(k).arg(swing)));
        }
        // The grid times fall inside steps, not on their ends: they were read off.
        QVERIFY(a.steps > 40);

        auto without = Simulation::build(*load.scene).simulation;
        const Recording b = record(*without, 2 * period, FrameGrid{}, nullptr);
        QCOMPARE(b.steps, a.steps);
        QCOMPARE(without->frame().poses[0].angle, withFrames->frame().poses[0].angle);
        QCOMPARE(without->frame().poses[0].position, withFrames->frame().poses[0].position);
    }
};

QTEST_GUILESS_MAIN(PendulumTest)
#include "test_pendulum.moc"
