// labels: physics;reference
// The benchmark's independent reference (reduced-coordinate chain) checked
// against the exact pendulum period, its own energy, and the engine.
#include "jl/engine/motion.h"
#include "jl/reference/elliptic.h"
#include "jl/reference/falling_chain.h"
#include "jl/reference/reference_chain.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using namespace jl;

class ReferenceChainTest : public QObject {
    Q_OBJECT
private slots:
    void oneLinkReturnsAfterExactEllipticPeriod() {
        // One link released horizontally: a physical pendulum at 90 degrees.
        ReferenceChainSpec spec;
        spec.links = 1;
        const double r = spec.length / 2, ip = spec.inertia() + spec.mass() * r * r;
        const double period = pendulumPeriod(ip, spec.mass(), spec.gravity, r, std::numbers::pi / 2);
        ReferenceChain chain(spec);
        chain.advanceTo(period, 1e-13);
        const double omegaScale = std::sqrt(spec.mass() * spec.gravity * r / ip);
        const double error = std::hypot(chain.angles()[0], chain.rates()[0] / omegaScale);
        qInfo("one link after one period: error %.3e rad", error);
        QVERIFY2(error < 1e-9, qPrintable(QString::number(error)));
    }

    void energyIsConservedToTheTolerance() {
        for (int n : {10, 100}) {
            ReferenceChainSpec spec;
            spec.links = n;
            ReferenceChain chain(spec);
            const double e0 = chain.energy();
            chain.advanceTo(0.5, 1e-12);
            // Scale: the potential energy released, m g (N L / 2) N.
            const double released = spec.mass() * spec.gravity * n * n * spec.length / 2;
            const double drift = std::abs(chain.energy() - e0) / released;
            qInfo("N=%d: relative energy drift %.3e", n, drift);
            QVERIFY2(drift < 1e-9, qPrintable(QString::number(drift)));
        }
    }

    void agreesWithTheEngineOnTheFallingChain() {
        const int n = 10;
        ReferenceChainSpec spec;
        spec.links = n;
        ReferenceChain reference(spec);
        reference.advanceTo(0.5, 1e-12);
        World w;
        const std::vector<PartId> parts = buildFallingChain(w, n);
        Dynamics d;
        Stepper s(Integrator::RK4);
        Ledger ledger;
        const int steps = 5000;
        for (int i = 0; i < steps; ++i) QVERIFY(advanceAndProject(w, d, s, i * 1e-4, 1e-4, ledger, 1e-12).ok());
        double worst = 0;
        for (int i = 0; i < n; ++i)
            worst = std::max(worst, (w.partPose(parts[size_t(i)]).position - reference.centre(i)).norm());
        qInfo("engine (RK4, 0.1 ms) against reference: %.3e m", worst);
        QVERIFY2(worst < 1e-6, qPrintable(QString::number(worst)));
    }
};

QTEST_GUILESS_MAIN(ReferenceChainTest)
#include "test_reference_chain.moc"
