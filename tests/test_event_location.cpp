// labels: physics;engine
// Locating an event inside a step: the step's quintic Hermite interpolant
// against motions with known answers, symplectic Euler's steps read as the
// method's own, and the bracket narrowing on the shape of a grazing contact
// that closes again just after a release.
#include "jl/engine/dynamics.h"
#include "jl/engine/step_interpolant.h"
#include "jl/engine/stepper.h"
#include "jl/engine/world.h"
#include "jl/sim/event_bracket.h"

#include <QtTest>

#include <cmath>
#include <functional>

using namespace jl;

namespace {

// A motion known at every instant: coordinate i follows x_i(t).
struct KnownMotion {
    std::function<double(int, double)> x, v, a;
    int n;
    Eigen::VectorXd sample(const std::function<double(int, double)>& f, double t) const {
        Eigen::VectorXd out(n);
        for (int i = 0; i < n; ++i) out[i] = f(i, t);
        return out;
    }
    StepInterpolant step(double t0, double h) const {
        StepInterpolant s;
        s.setEnd(sample(x, t0 + h), sample(v, t0 + h), sample(a, t0 + h));
        s.setStart(h, sample(x, t0), sample(v, t0), sample(a, t0));
        return s;
    }
    // The largest position and velocity errors of the interpolant at 16
    // instants inside [t0, t0 + h].
    std::pair<double, double> worstError(double t0, double h) const {
        const StepInterpolant s = step(t0, h);
        double dq = 0, dv = 0;
        Eigen::VectorXd q, vel;
        for (int k = 0; k <= 16; ++k) {
            const double tau = h * k / 16.0;
            s.at(tau, q, vel);
            dq = std::max(dq, (q - sample(x, t0 + tau)).cwiseAbs().maxCoeff());
            dv = std::max(dv, (vel - sample(v, t0 + tau)).cwiseAbs().maxCoeff());
        }
        return {dq, dv};
    }
};

}  // namespace

class EventLocation : public QObject {
    Q_OBJECT
private slots:
    // Any motion polynomial of degree 5 in time is reproduced exactly.
    void quinticMotionIsExact() {
        const double c[3][6] = {
            {0.3, -1.2, 4.0, -7.5, 2.25, 9.0}, {-2.0, 0.5, 0.0, 3.0, -1.0, 0.7}, {1.0, 0, 0, 0, 0, -4.0}};
        auto poly = [&](int i, double t, int derivative) {
            double sum = 0;
            for (int p = derivative; p < 6; ++p) {
                double coef = c[i][p];
                for (int d = 0; d < derivative; ++d) coef *= p - d;
                sum += coef * std::pow(t, p - derivative);
            }
            return sum;
        };
        const KnownMotion m{[&](int i, double t) { return poly(i, t, 0); },
                            [&](int i, double t) { return poly(i, t, 1); },
                            [&](int i, double t) { return poly(i, t, 2); }, 3};
        const auto [dq, dv] = m.worstError(0.4, 0.7);
        QVERIFY2(dq < 1e-13 && dv < 1e-13, qPrintable(QString("position error %1, velocity error %2").arg(dq).arg(dv)));
    }

    // Symplectic Euler's step read inside is the step that method takes to
    // that instant, bit for bit: a box on a spring to the ground (its
    // acceleration depends on where it is), one step of 2 ms read at 0.37
    // of it against a step of that length from the same start.
    void symplecticEulerIsReadAsItsOwnStep() {
        World w;
        w.gravity = Vec2(0, -9.81);
        const PartId box =
            w.addBox(0.02, Vec2(0.012, 0.06), 0.045, Pose{Vec2(0.03, -0.05), 0.3}, Twist{Vec2(0.2, 0), 1.5});
        w.addSpring({w.anchor(Vec2(0, 0)), w.addParticle(box, Vec2(0, 0.03)), 50, 0.02, 0});
        Dynamics d;
        d.evaluate(w, 0);
        const World start = w;
        const double h = 2e-3, tau = 0.37 * h;
        Ledger ledger;
        Stepper whole(Integrator::SymplecticEuler);
        whole.advance(w, d, 0, h, ledger);
        StepInterpolant inside(StepInterpolant::Inside::SymplecticEuler);
        inside.setEnd(w.q, w.v, w.a);
        inside.setStart(h, start.q, start.v, start.a);
        World cut = start;
        Stepper shorter(Integrator::SymplecticEuler);
        shorter.advance(cut, d, 0, tau, ledger);
        Eigen::VectorXd q, v;
        inside.at(tau, q, v);
        QVERIFY(q == cut.q && v == cut.v);
        QVERIFY(q[0] == inside.coordinateAt(tau, 0));
        // The quintic through the same ends passes elsewhere.
        StepInterpolant quintic;
        quintic.setEnd(w.q, w.v, w.a);
        quintic.setStart(h, start.q, start.v, start.a);
        quintic.at(tau, q, v);
        QVERIFY((q - cut.q).norm() > 1e-9);
    }

    // On a pendulum-like oscillation the error falls as h^6 in position and
    // h^5 in velocity: halving the step divides them by about 64 and 32.
    void errorOrderIsSixAndFive() {
        const double w = 7.0;
        const KnownMotion m{[&](int, double t) { return std::sin(w * t); },
                            [&](int, double t) { return w * std::cos(w * t); },
                            [&](int, double t) { return -w * w * std::sin(w * t); }, 1};
        const auto [q1, v1] = m.worstError(0.1, 0.02);
        const auto [q2, v2] = m.worstError(0.1, 0.01);
        const double orderQ = std::log2(q1 / q2), orderV = std::log2(v1 / v2);
        QVERIFY2(std::abs(orderQ - 6) < 0.3 && std::abs(orderV - 5) < 0.3,
                 qPrintable(QString("orders %1 (position), %2 (velocity)").arg(orderQ).arg(orderV)));
    }

    // A hinge just released sits at its limit with the function at its
    // tolerance, drifts out a little and closes again 8.5 us into a 1 ms
    // step, far from where a secant through the step's ends points: the
    // bracket must still close on the crossing, the event on its far side.
    void grazingReturnIsBracketed() {
        const double tol = 5e-8, root = 8.5e-6;
        const double drift = 0.5 * tol / root, turn = (tol + drift * root) / (root * root);
        auto f = [&](double t) { return tol + drift * t - turn * t * t; };
        QVERIFY(f(0) > 0 && std::abs(f(root)) < 1e-20 && f(1e-3) < 0);
        EventBracket bracket{0, f(0), 1e-3, f(1e-3)};
        const int trials = narrow(bracket, 1e-9, f);
        QVERIFY(bracket.width() <= 1e-9);
        QVERIFY(bracket.lo <= root && root <= bracket.hi);
        QVERIFY(f(bracket.lo) >= 0 && f(bracket.hi) < 0);
        QVERIFY2(trials <= 40, qPrintable(QString("%1 trials").arg(trials)));
    }

    // A crossing at either end of the step, and a start that is itself past
    // the threshold (rounding at a limit): always a bracket of the stated width.
    void crossingsAtTheEndsAreBracketed() {
        for (const double root : {1e-12, 0.5e-9, 0.999999e-3, 1e-3 - 1e-13}) {
            auto f = [&](double t) { return root - t; };
            EventBracket b{0, f(0), 1e-3, f(1e-3) - 1e-15};
            narrow(b, 1e-9, f);
            QVERIFY(b.width() <= 1e-9);
            QVERIFY2(b.lo <= root + 1e-18 && root <= b.hi + 1e-18, qPrintable(QString("root %1").arg(root)));
        }
        EventBracket b{0, 0.0, 1e-3, -1.0};
        narrow(b, 1e-9, [](double t) { return t < 3e-4 ? 0.0 : -1.0; });
        QVERIFY(b.width() <= 1e-9 && b.lo <= 3e-4 && 3e-4 <= b.hi);
    }
};

QTEST_APPLESS_MAIN(EventLocation)
#include "test_event_location.moc"
