// labels: physics;engine
// The falling chain (N boxes pinned end to end, hung at one end, let fall):
// it stays assembled, and in this conservative scene the energy error
// shrinks at each integrator's order as the step shrinks.
#include "jl/engine/energy.h"
#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/reference/falling_chain.h"

#include <QtTest>

#include <cmath>

using namespace jl;

namespace {

struct ChainRun {
    double energyError = 0;  // J, largest |E(t) - E(0)|
    double residual = 0;     // m, largest pin gap after any step
    bool ok = true;
};

ChainRun fall(int n, Integrator kind, double h, double until) {
    World w;
    buildFallingChain(w, n);
    Dynamics d;
    Stepper s(kind, 1e-9);
    Ledger ledger;
    const double e0 = energy(w).total();
    ChainRun r;
    for (double t = 0; t < until - 1e-12;) {
        const MotionStep m = advanceAndProject(w, d, s, t, h, ledger, 1e-10);
        if (!m.ok()) {
            r.ok = false;
            break;
        }
        t += m.step.taken;
        r.residual = std::max(r.residual, pinResidual(w));
        r.energyError = std::max(r.energyError, std::abs(energy(w).total() - e0));
    }
    return r;
}

}  // namespace

class FallingChainTest : public QObject {
    Q_OBJECT
private slots:
    // 1,000 links, RK4 at 1 ms, 0.5 s of fall: every pin closed to the
    // projection tolerance after every step; the energy of this lossless
    // scene kept to a millionth of the chain's drop in potential energy.
    void thousandBlockChainStaysAssembled() {
        const int n = 1000;
        const ChainRun r = fall(n, Integrator::RK4, 1e-3, 0.5);
        QVERIFY(r.ok);
        QVERIFY2(r.residual <= 1e-10, qPrintable(QString::number(r.residual)));
        const FallingChain spec;
        const double scale = n * spec.mass() * 9.81 * 0.5 * 9.81 * 0.25;  // m g (g t^2 / 2): a free-fall drop
        qInfo("energy error %.3e J of scale %.3e J", r.energyError, scale);
        QVERIFY2(r.energyError < 1e-6 * scale, qPrintable(QString::number(r.energyError)));
    }

    void energyErrorShrinksAtFourthOrderWithRk4() {
        const ChainRun a = fall(5, Integrator::RK4, 4e-3, 0.4), b = fall(5, Integrator::RK4, 2e-3, 0.4);
        const double order = std::log2(a.energyError / b.energyError);
        qInfo("RK4 energy error %.3e -> %.3e: order %.2f", a.energyError, b.energyError, order);
        QVERIFY2(order > 3.5 && order < 5.5, qPrintable(QString::number(order)));
    }

    void energyErrorShrinksAtFirstOrderWithEuler() {
        const ChainRun a = fall(5, Integrator::ExplicitEuler, 2e-4, 0.4),
                       b = fall(5, Integrator::ExplicitEuler, 1e-4, 0.4);
        const double order = std::log2(a.energyError / b.energyError);
        qInfo("explicit Euler energy error %.3e -> %.3e: order %.2f", a.energyError, b.energyError, order);
        QVERIFY2(order > 0.8 && order < 1.3, qPrintable(QString::number(order)));
    }

    void adaptiveMeetsItsTolerance() {
        const ChainRun loose = fall(5, Integrator::DormandPrince45, 1e-2, 0.4);
        World w;
        buildFallingChain(w, 5);
        Dynamics d;
        Stepper s(Integrator::DormandPrince45, 1e-11);
        Ledger ledger;
        const double e0 = energy(w).total();
        double t = 0, worst = 0;
        while (t < 0.4) {
            const MotionStep m = advanceAndProject(w, d, s, t, 0.4 - t, ledger, 1e-12);
            QVERIFY(m.ok());
            t += m.step.taken;
            worst = std::max(worst, std::abs(energy(w).total() - e0));
        }
        qInfo("Dormand-Prince energy error %.3e (tolerance 1e-9), %.3e (1e-11)", loose.energyError, worst);
        QVERIFY(worst < loose.energyError);
        QVERIFY2(worst < 1e-9, qPrintable(QString::number(worst)));
    }

    // Dormand-Prince's last stage is the end of the step projected onto the
    // pins: the step leaves the end projected and evaluated (the caller's
    // evaluation of the end is that stage), the pins closed, and the motion
    // the same to well within the tolerance as with its last stage off the
    // pins and the projection after the step.
    void dormandPrincesLastStageIsTheProjectedEnd() {
        struct Chain {
            World w;
            Dynamics d;
            Stepper s{Integrator::DormandPrince45, 1e-8};
            Ledger ledger;
            double t = 0;
        };
        Chain onPins, offPins;
        for (Chain* c : {&onPins, &offPins}) buildFallingChain(c->w, 20);
        for (int i = 0; i < 40; ++i) {
            const MotionStep m =
                advanceAndProject(onPins.w, onPins.d, onPins.s, onPins.t, 0.5 - onPins.t, onPins.ledger, 1e-12);
            QVERIFY(m.ok() && m.step.endEvaluated);
            // What the step left is the end as evaluated afresh, bit for bit.
            const Eigen::VectorXd a = onPins.w.a;
            const Powers p = onPins.d.evaluate(onPins.w, onPins.t + m.step.taken);
            QVERIFY(onPins.w.a == a);
            QCOMPARE(p.held, m.step.endPowers.held);
            QVERIFY(pinResidual(onPins.w) <= 1e-12);
            onPins.t += m.step.taken;
        }
        // The same span with the projection after each step instead.
        while (offPins.t < onPins.t - 1e-15) {
            const StepOutcome o =
                offPins.s.advance(offPins.w, offPins.d, offPins.t, onPins.t - offPins.t, offPins.ledger);
            QVERIFY(o.finite && !o.endEvaluated);
            QVERIFY(projectPositions(offPins.w, offPins.d, 1e-12).converged);
            projectVelocities(offPins.w, offPins.d);
            offPins.t += o.taken;
        }
        QVERIFY2((onPins.w.q - offPins.w.q).cwiseAbs().maxCoeff() < 1e-7,
                 qPrintable(QString::number((onPins.w.q - offPins.w.q).cwiseAbs().maxCoeff())));
    }

    // After a step the position projection takes J from the factorisation in
    // hand, made where the bodies were a little before (docs/model.md section
    // 5.1): the pins close to the tolerance, at the point that a projection
    // with J taken where the bodies are reaches, to first order: the two
    // corrections differ by the move over a link's length times the gap
    // (1e-7 / 0.06 of 1e-7 m), summed along 50 links, under 1e-11 m. A factorisation
    // made far from there (moves and turns of 0.05 m and rad) gives way at
    // once to one where the bodies are: the same steps, bit for bit, as a
    // projection that had none in hand.
    void theProjectionClosesThePinsWithTheFactorisationInHand() {
        for (const double away : {1e-7, 0.05}) {
            World w;
            buildFallingChain(w, 50);
            Dynamics held;
            (void)held.evaluate(w, 0);  // factorised at the chain's start
            for (int b = 1; b < w.bodyCount(); ++b) {
                if (w.body(b).kinematic) continue;
                w.q[3 * b] += away * std::sin(b);
                w.q[3 * b + 1] += away * std::cos(b);
                w.q[3 * b + 2] += away * std::sin(2.0 * b);
            }
            World fresh = w;
            Dynamics unfactorised;
            const ProjectionResult a = projectPositions(w, held, 1e-13);
            const ProjectionResult b = projectPositions(fresh, unfactorised, 1e-13);
            QVERIFY(a.converged && b.converged);
            QVERIFY2(pinResidual(w) <= 1e-13, qPrintable(QString::number(pinResidual(w))));
            const double apart = (w.q - fresh.q).cwiseAbs().maxCoeff();
            qInfo("moved %g: %d and %d iterations, the two projections %.2e apart", away, a.iterations, b.iterations,
                  apart);
            if (away < 1e-6) {
                QVERIFY2(apart < 1e-11, qPrintable(QString::number(apart)));
                QVERIFY(apart > 0);  // the held J was used: not the fresh projection's steps
            } else {
                QCOMPARE(apart, 0.0);  // given way at once: the fresh projection's own steps
            }
        }
    }
};

// Not a chain, but the engine's external loads: a free box under a constant
// force through its centre and a constant torque, no gravity, follows
// x = F t^2 / 2m and theta = tau t^2 / 2I exactly (RK4 integrates a
// quadratic exactly), and the work F.x + tau theta is booked.
class AppliedLoadTest : public QObject {
    Q_OBJECT
private slots:
    void constantForceAndTorqueMoveAFreeBoxExactly() {
        World w;
        w.gravity = Vec2::Zero();
        const PartId box = w.addBox(0.02, Vec2(0.012, 0.06), 0.045, Pose{});
        w.editLoads().push_back({box, Vec2::Zero(), Vec2(0.3, -0.1), 0.002});
        Dynamics d;
        Stepper s(Integrator::RK4);
        Ledger ledger;
        const double h = 1e-3;
        for (int i = 0; i < 500; ++i) QVERIFY(advanceAndProject(w, d, s, i * h, h, ledger, 1e-12).ok());
        const double t = 0.5, m = 0.02, inertia = w.part(box).inertia;
        const Pose p = w.partPose(box);
        QVERIFY((p.position - Vec2(0.3, -0.1) * t * t / (2 * m)).norm() < 1e-12);
        QVERIFY(std::abs(p.angle - 0.002 * t * t / (2 * inertia)) < 1e-9);
        const double work = Vec2(0.3, -0.1).dot(p.position) + 0.002 * p.angle;
        QVERIFY(std::abs(ledger.user - work) < 1e-12);
        QVERIFY(std::abs(energy(w).kinetic - work) < 1e-12);
    }
};

int main(int argc, char** argv) {
    FallingChainTest chain;
    AppliedLoadTest loads;
    return QTest::qExec(&chain, argc, argv) | QTest::qExec(&loads, argc, argv);
}
#include "test_falling_chain.moc"
