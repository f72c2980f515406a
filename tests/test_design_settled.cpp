// labels: ladder
// A design's run stops once its first ripple's reach is settled
// (jl/design/reach_settled.h, docs/ripple-reach.md): by order, at the
// bottom, or by energy; the reach and its flip times are those of the
// whole run, and the stop applies only where the energy argument holds.
#include "jl/design/reach_settled.h"
#include "jl/design/ripple_reach.h"
#include "jl/engine/energy.h"
#include "jl/sim/simulation.h"

#include <QtTest>

#include <cmath>
#include <limits>

using namespace jl;

namespace {

constexpr double kAll = std::numeric_limits<double>::infinity();

RippleReach wholeRun(const Scene& s) { return firstRippleReach(s, nullptr, kAll, RippleStop::WholeRun); }

}  // namespace

class DesignSettledTest : public QObject {
    Q_OBJECT
private slots:
    // Fifty blocks 12 mm thick: hinge 1 flips, and the ladder soon has too
    // little energy left to fold hinge 2 under the 48 blocks below hinge 3.
    // The run stops long before its 11 s, with the whole run's reach.
    void aStalledRippleStopsByEnergy() {
        const Scene s = turnedLadder(50, 0.012);
        const RippleReach early = firstRippleReach(s), whole = wholeRun(s);
        QVERIFY2(early.failure.empty() && whole.failure.empty(), early.failure.c_str());
        QCOMPARE(whole.until, 1.0 + 0.2 * 50);
        QCOMPARE(whole.end, RippleEnd::RunEnd);
        QCOMPARE(early.end, RippleEnd::Energy);
        QVERIFY2(early.until < 0.25 * whole.until, qPrintable(QString::number(early.until)));
        QVERIFY(early.until > 0.5);  // not before the hand stops
        QVERIFY(early.whole);
        QCOMPARE(early.reached, whole.reached);
        QCOMPARE(early.flipTimes, whole.flipTimes);
        QVERIFY(early.events <= whole.events);
    }

    // The same with blocks that meet as solids: contacts between blocks
    // only take energy, so the stop by energy still gives the whole run's
    // reach and flips.
    void aStalledRippleAmongSolidBlocksStopsByEnergy() {
        Scene s = turnedLadder(50, 0.012);
        s.solver.blockContact = BlockContact::On;
        const RippleReach early = firstRippleReach(s), whole = wholeRun(s);
        QVERIFY2(early.failure.empty() && whole.failure.empty(), whole.failure.c_str());
        QCOMPARE(early.end, RippleEnd::Energy);
        QVERIFY2(early.until < 0.25 * whole.until, qPrintable(QString::number(early.until)));
        QCOMPARE(early.reached, whole.reached);
        QCOMPARE(early.flipTimes, whole.flipTimes);
    }

    // Twenty-five blocks 3 mm thick: the bottom block flips at 1.1 s, so once
    // hinge 23 has flipped the ripple can never take hinge 24 in order.
    void aRippleOvertakenStopsByOrder() {
        const Scene s = turnedLadder(25, 0.003);
        const RippleReach early = firstRippleReach(s), whole = wholeRun(s);
        QCOMPARE(early.end, RippleEnd::Order);
        QCOMPARE(early.reached, 23);
        QCOMPARE(early.flipTimes, whole.flipTimes);
        QCOMPARE(early.meanTimeBetweenFlips, whole.meanTimeBetweenFlips);
        QVERIFY(early.until < whole.until - 2);
        QVERIFY(early.until >= early.flipTimes.back());
    }

    // The classic: the ripple reaches the bottom, and the run stops in the
    // step of the last flip.
    void aRippleAtTheBottomStops() {
        const RippleReach r = firstRippleReach(turnedLadder(6, 0.012));
        QCOMPARE(r.end, RippleEnd::Bottom);
        QCOMPARE(r.reached, 5);
        QVERIFY(r.until >= r.flipTimes.back() && r.until < r.flipTimes.back() + 2e-3);
    }

    // A ladder left hanging has the least energy there is: nothing can fold,
    // so it stops at once; run whole, it hangs for its 2.1 s.
    void aLadderAtRestStopsAtOnce() {
        Scene s = turnedLadder(8, 0.012);
        s.script.clear();
        const RippleReach r = firstRippleReach(s);
        QCOMPARE(r.end, RippleEnd::Energy);
        QCOMPARE(r.until, 0.0);
        QCOMPARE(r.reached, 0);
        QCOMPARE(wholeRun(s).until, 0.5 + 0.2 * 8);
    }

    // The least potential energy is the engine's hanging equilibrium (every
    // diagonal vertical, hinge 1 at block 0's lower left corner), and the
    // lift a fold gives the blocks below is 2 sqrt(L^2 + T^2) -
    // sqrt(L^2 + 4 T^2): 60.0 mm at 1 mm, 56.6 mm at 15 mm.
    void theBoundIsTheHangingEquilibrium() {
        for (const double t : {0.001, 0.015}) {
            const Scene s = turnedLadder(20, t);
            Simulation::Built b = Simulation::build(s);
            QVERIFY(b.simulation);
            const ReachBarrier barrier(s, *b.simulation);
            QVERIFY(barrier.applies());
            QCOMPARE(barrier.handStops(), 0.5);
            const double v = energy(b.simulation->world()).potential, v0 = barrier.lowestPotential(*b.simulation);
            QVERIFY2(std::abs(v - v0) <= 1e-12 * std::abs(v0), qPrintable(QString::number(v - v0)));
            const double l = 0.06, lift = 2 * std::hypot(l, t) - std::hypot(l, 2 * t);
            QVERIFY(std::abs(barrier.lift(*b.simulation, 5) - lift) < 1e-15);
            QVERIFY(std::abs(lift - (t < 0.01 ? 0.0600 : 0.0566)) < 5e-5);
            // Block 5 itself, folded onto block 4: 1.5 sqrt(L^2 + T^2) -
            // sqrt(L^2 / 4 + 2.25 T^2), 60.0 and 55.3 mm.
            const double own = 1.5 * std::hypot(l, t) - std::hypot(l / 2, 1.5 * t);
            QVERIFY(std::abs(barrier.ownLift(*b.simulation, 5) - own) < 1e-15);
            QVERIFY(std::abs(own - (t < 0.01 ? 0.0600 : 0.0553)) < 5e-5);
            const double m = b.simulation->world().part(b.simulation->blockPart(5)).mass;
            QVERIFY(std::abs(barrier.barrier(*b.simulation, 5) - 9.81 * m * (own + 14 * lift)) < 1e-15);
            // Hinge 1 folds against the held block 0 (upright): block 1 then
            // lies beside it, hinge 2 no lower than block 0's bottom, block
            // 1's centre as high as block 0's.
            QVERIFY(std::abs(barrier.lift(*b.simulation, 1) - std::hypot(l, t)) < 1e-15);
            QVERIFY(std::abs(barrier.ownLift(*b.simulation, 1) - (l + std::hypot(l, t)) / 2) < 1e-15);
        }
    }

    // Where the argument does not hold, no energy stop: something else than
    // the hand can bring energy in, or a loss the argument has not checked.
    void theStopAppliesOnlyWhereEnergyOnlyFalls() {
        const Scene base = turnedLadder(8, 0.006);
        auto applies = [](const Scene& s) {
            Simulation::Built b = Simulation::build(s);
            return b.simulation && ReachBarrier(s, *b.simulation).applies();
        };
        QVERIFY(applies(base));
        Scene damped = base;
        damped.ladder->hinges.damping = 1e-4;
        damped.ladder->hinges.restitution = 0.5;
        QVERIFY(applies(damped));  // losses only
        Scene pushed = base;
        ScriptAction push;
        push.kind = ScriptAction::Kind::Push;
        push.at = 1;
        push.block = 4;
        push.impulse = {1e-3, 0};
        pushed.script.push_back(push);
        QVERIFY(!applies(pushed));
        Scene twoHands = base;
        twoHands.ladder->held = {0, 7};
        QVERIFY(!applies(twoHands));
        Scene solid = base;
        solid.solver.blockContact = BlockContact::On;
        QVERIFY(applies(solid));  // frictionless contacts and plastic impacts
        Scene table = base;
        table.floor = FloorSpec{-1.0};
        QVERIFY(!applies(table));
        Scene euler = base;
        euler.solver.integrator = Integrator::SymplecticEuler;
        QVERIFY(!applies(euler));
        Scene released = base;
        ScriptAction release;
        release.kind = ScriptAction::Kind::Release;
        release.at = 1;
        released.script.push_back(release);
        QVERIFY(!applies(released));
        // A design where it does not apply never stops by energy.
        const RippleReach r = firstRippleReach(twoHands);
        QVERIFY(r.end != RippleEnd::Energy);
    }
};

QTEST_APPLESS_MAIN(DesignSettledTest)
#include "test_design_settled.moc"
