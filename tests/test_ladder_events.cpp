// labels: physics;ladder
// Two- and three-block cases worked by hand for each event type (docs/model.md
// section 14.5): the mode sequence, the hinge corner and the sign and size of
// the reactions. Blocks are 60 x 12 x 45 mm, density 600 (m = 19.44 g).
#include "jl/engine/dynamics.h"
#include "jl/engine/energy.h"
#include "jl/engine/world.h"
#include "jl/ladder/block_corners.h"
#include "jl/ladder/ladder.h"
#include "tests/ladder_scenes.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <cstdio>
#include <numbers>

using namespace jl;
using namespace jl::test;

namespace {

constexpr double L = 0.06, T = 0.012, g = 9.81;
constexpr double m = 600 * L * T * 0.045;

HingeContact contactNow(const Simulation& sim, int j) {
    World w = sim.world();
    Dynamics d;
    d.evaluate(w, sim.time());
    return sim.ladder()->contact(w, d, j);
}

}  // namespace

class LadderEventsTest : public QObject {
    Q_OBJECT
private slots:
    // The views number corners from the design alone; the engine pins hinges
    // to its own: they must be the same points, per-block thickness included,
    // and a hinge must join the same-numbered corners of its two blocks.
    void cornersFromTheDesignAreTheEngines() {
        LadderSpec spec;
        spec.blocks = 5;
        BlockOverride thick;
        thick.index = 2;
        thick.thickness = 0.02;
        spec.overrides.push_back(thick);
        World w;
        const Ladder ladder(w, spec);
        const auto corners = blockCorners(spec);
        QCOMPARE(int(corners.size()), 5);
        for (int i = 0; i < 5; ++i)
            for (int k = 0; k < 4; ++k) QCOMPARE(corners[size_t(i)][size_t(k)], ladder.cornerLocal(i, k));
        QCOMPARE(corners[2][2].x(), 0.01);   // half the overridden thickness
        QCOMPARE(corners[0][1].y(), 0.03);   // even blocks: corner 1 at the top end
        QCOMPARE(corners[1][1].y(), -0.03);  // odd blocks: at the bottom end
        for (int j = 1; j < 5; ++j) {
            const int k = ladder.hinge(j).corner;
            const Vec2 a = ladder.cornerWorld(w, j - 1, k), b = ladder.cornerWorld(w, j, k);
            QVERIFY((a - b).norm() < 1e-9);
        }
    }

    // Block 1 falls off the end of the flat block, hits phi = 0 and locks as a
    // cantilever. Moments about the pin: m g L/2 = N T, so N = m g L / (2 T).
    void lockHoldsCantileverWithHandWorkedForce_data() { bothModelsOfRigidPairs(); }
    void lockHoldsCantileverWithHandWorkedForce() {
        QFETCH(QString, pairs);
        auto sim = simulate(flatHeldBlock(1.4, "90deg", pairs));
        QVERIFY(sim);
        const Run r = runUntil(*sim, 0.9);
        QCOMPARE(int(r.events.size()), 1);
        QCOMPARE(r.events[0].kind, EventKind::Lock);
        QCOMPARE(r.events[0].corner, 0);
        QCOMPARE(sim->ladder()->hinge(1).mode, HingeMode::OpenLocked);
        const double expected = m * g * L / (2 * T);
        const double n = contactNow(*sim, 1).normal;
        QVERIFY2(std::abs(n / expected - 1) < 1e-6,
                 qPrintable(QString("N = %1, m g L / 2T = %2").arg(n).arg(expected)));
        QVERIFY(r.lastImpactLoss > 0);  // the plastic impact dissipated energy
        QVERIFY2(r.worstBalance < 1e-8, qPrintable(QString::number(r.worstBalance)));
    }

    // Blocks of unequal thickness (12 and 20 mm) lock end to end as a
    // cantilever: the hinge's own corners stay together and the pair does not
    // move sideways. The
    // second corners of a lock (k^2) lie 12 and 20 mm across: they cannot
    // coincide, so the pair must keep the hinge corners as its pin (in weld
    // mode, the weld holds the angle; in merge mode, one body).
    void unequalThicknessesLockWithoutShifting_data() { bothModelsOfRigidPairs(); }
    void unequalThicknessesLockWithoutShifting() {
        QFETCH(QString, pairs);
        // Block 0 held flat, block 1 falls off its end and locks as a cantilever.
        std::string yaml = flatHeldBlock(1.4, "0deg", pairs);
        yaml.replace(yaml.find("  held: [0]\n"), 12, "  held: [0]\n  overrides: [{index: 1, thickness: 0.02}]\n");
        auto sim = simulate(yaml);
        QVERIFY(sim);
        // Just after the lock (the first event).
        QVERIFY(sim->advanceToNextEvent(1.0));
        QVERIFY2(sim->failure().empty(), sim->failure().c_str());
        QCOMPARE(sim->ladder()->hinge(1).mode, HingeMode::OpenLocked);
        const Ladder& ladder = *sim->ladder();
        const int k = ladder.hinge(1).corner;
        const World& w = sim->world();
        const double gap = (ladder.cornerWorld(w, 0, k) - ladder.cornerWorld(w, 1, k)).norm();
        QVERIFY2(gap < 1e-9, qPrintable(QString("hinge corners %1 m apart").arg(gap)));
        // Locked straight below block 0 (upright at the origin), not shifted.
        const double across = (ladder.cornerWorld(w, 0, k ^ 2) - ladder.cornerWorld(w, 1, k ^ 2)).norm();
        QVERIFY2(std::abs(across - 0.008) < 1e-9, qPrintable(QString("lock corners %1 m apart").arg(across)));
        QVERIFY2(pinResidual(w) < 1e-9, qPrintable(QString::number(pinResidual(w))));
    }

    // Block 1 hangs from the upright held block 0 by hinge 1 and is let go at
    // rest from fold angle phi0: a physical pendulum about the pin, hanging
    // at phi = a = atan(T/L), with omega0^2 = m g r / I_p = 3 g / (2 sqrt(L^2 + T^2)).
    // From psi0 = phi0 - a it swings through the bottom to psi = -a, where
    // phi = 0 and it locks: t = (K(k) + F(asin(sin(a/2)/k), k)) / omega0 with
    // k = sin(psi0/2) (sin(psi/2) = k sin(u) turns the energy integral into
    // Legendre's form). The lock is located where phi crosses 0 itself, so
    // its time converges to that instant as the event tolerance shrinks,
    // with no floor: an angle threshold of 5e-8 rad would make it 3e-9 s late.
    void lockIsLocatedWhereTheFoldAngleReachesZero_data() {
        QTest::addColumn<double>("eventTolerance");
        QTest::newRow("1e-6 s") << 1e-6;
        QTest::newRow("1e-8 s") << 1e-8;
        QTest::newRow("1e-10 s") << 1e-10;
        QTest::newRow("1e-12 s") << 1e-12;
    }
    void lockIsLocatedWhereTheFoldAngleReachesZero() {
        QFETCH(double, eventTolerance);
        const double phi0 = 1.2, a = std::atan(T / L);
        const double omega0 = std::sqrt(3 * g / (2 * std::hypot(L, T)));
        const double k = std::sin((phi0 - a) / 2);
        const double exact = (std::comp_ellint_1(k) + std::ellint_1(k, std::asin(std::sin(a / 2) / k))) / omega0;
        char tol[32];
        std::snprintf(tol, sizeof tol, "%.17g", eventTolerance);
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "solver: {integrator: rk4, step: 1e-4, event_tolerance: " +
            std::string(tol) +
            "}\n"
            "ladder: {blocks: 2, held: [0], initial: {fold_angles: [1.2]}}\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, exact + 0.01);
        QVERIFY(r.failure.empty());
        QVERIFY(!r.events.empty());
        QCOMPARE(r.events[0].kind, EventKind::Lock);
        const double error = r.events[0].time - exact;
        qInfo("lock at %.15f s, closed form %.15f s, error %.2e s", r.events[0].time, exact, error);
        // Located at or just after the crossing, within the event tolerance;
        // RK4 at 0.1 ms adds about 1e-13 s.
        QVERIFY2(error > -1e-12 && error <= eventTolerance + 1e-12, qPrintable(QString::number(error)));
        if (eventTolerance <= 1e-10) QVERIFY(std::abs(error) < 1e-10);
    }

    // The same lock at a tight and a loose event tolerance: the instant is
    // narrowed on the step's interpolant, angles alone, and the state there
    // read off it, so the step that records the lock evaluates the dynamics
    // as often whatever the tolerance, and only a few times more than a
    // plain step (its start, for the interpolant, and resolve's passes). The
    // step used to be run again to the instant: four more evaluations, and
    // a re-run for every trial where the interpolant disagreed.
    void locatingALockRunsNoStepAgain() {
        std::vector<long long> extra;
        for (const char* tolerance : {"1e-6", "1e-12"}) {
            auto sim = simulate(
                "format: jacobs-ladder/1\n"
                "solver: {integrator: rk4, step: 1e-3, event_tolerance: " +
                std::string(tolerance) +
                "}\n"
                "ladder: {blocks: 2, held: [0], initial: {fold_angles: [1.2]}}\n");
            QVERIFY(sim);
            long long before = sim->frame().solver.evaluations, plain = 0, eventful = -1;
            while (eventful < 0 && sim->time() < 0.2) {
                QVERIFY(sim->stepOnce());
                const Frame f = sim->frame();  // takes the step's events with it
                const long long now = f.solver.evaluations;
                bool locked = false;
                for (const Event& e : f.events) locked = locked || e.kind == EventKind::Lock;
                if (locked)
                    eventful = now - before;
                else
                    plain = now - before;
                before = now;
            }
            QVERIFY(eventful > 0 && plain > 0);
            qInfo("event tolerance %s s: the step with the lock evaluates %lld times, a plain step %lld", tolerance,
                  eventful, plain);
            extra.push_back(eventful - plain);
        }
        QCOMPARE(extra[0], extra[1]);
        QVERIFY2(extra[0] <= 4, qPrintable(QString::number(extra[0])));
    }

    // The same cantilever with a spring from a point above pulling block 1
    // up at its centre: the contact carries what gravity and the spring
    // together need, N = N0 * M / M0 with M the moment of gravity and spring
    // about the pin and M0 that of gravity alone (N0 = m g L / 2T).
    // The contact test once left springs and loads out and kept N0.
    void lockedContactCarriesTheSpringsPullToo() {
        const double k = 0.572;  // N/m: about 0.3 m g at the 0.1 m stretch
        auto sim = simulate(flatHeldBlock(1.4, "90deg") +
                            "springs: [{a: {body: world, local: [-0.06, 0.1]}, b: {body: 'block:1', local: [0, 0]}, "
                            "stiffness: " +
                            std::to_string(k) + ", rest_length: 0}]\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 0.9);
        QVERIFY(r.failure.empty());
        QCOMPARE(sim->ladder()->hinge(1).mode, HingeMode::OpenLocked);
        const World& w = sim->world();
        const Vec2 p = sim->ladder()->cornerWorld(w, 0, sim->ladder()->hinge(1).corner);
        const Vec2 c = w.partPose(sim->blockPart(1)).position;
        const Vec2 spring = k * (Vec2(-0.06, 0.1) - c), weight = m * w.gravity;
        const double expected =
            m * g * L / (2 * T) * (cross(c - p, weight) + cross(c - p, spring)) / cross(c - p, weight);
        const double n = contactNow(*sim, 1).normal;
        qInfo("N = %.9f N, by hand %.9f N (without the spring %.9f N)", n, expected, m * g * L / (2 * T));
        QVERIFY2(std::abs(n / expected - 1) < 1e-6, qPrintable(QString("N = %1, by hand %2").arg(n).arg(expected)));
    }

    // A cut hinge has no ribbons, so no hinge friction either: block 1,
    // falling and turning after its hinge is cut, loses nothing to the
    // damper (it once kept acting across the cut).
    void aCutHingeLosesItsDamper() {
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "ladder: {blocks: 2, held: [0], hinges: {damping: 1e-3}, initial: {fold_angles: [1.2]}}\n"
            "script: [{at: 0.05, cut: {hinge: 1}}]\n");
        QVERIFY(sim);
        double lossAtCut = -1, omega0 = 0;
        const Run r = runUntil(*sim, 0.2, [&](const Frame& f) {
            if (f.time >= 0.05 && lossAtCut < 0) {
                lossAtCut = f.energy.dampingLoss;
                omega0 = sim->world().partVelocity(sim->blockPart(1)).angular;
            }
        });
        QVERIFY(r.failure.empty());
        QVERIFY(lossAtCut > 0);  // the damper worked while the hinge held
        QVERIFY(std::abs(omega0) > 0.1);
        QCOMPARE(sim->frame().energy.dampingLoss, lossAtCut);
        QCOMPARE(sim->world().partVelocity(sim->blockPart(1)).angular, omega0);
    }

    // The hand grabs block 3 while the ripple swings it, and lets go again:
    // the block stops dead (an impact on its neighbours, booked: the held
    // frame's loss dissipated, the rest the hand's work), and the block's own
    // energy leaves the books while held and comes back with it. The books
    // once jumped by 0.02 J at the grab (the hold's velocity jump was left to
    // the next projection, unbooked).
    void grabbingAMovingBlockIsBookedLikeAnImpact() {
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "ladder: {blocks: 6, held: [0]}\n"
            "script:\n"
            "  - {at: 0.2, turn: {block: 0, by: 180deg, duration: 0.3}}\n"
            "  - {at: 0.8, hold: {block: 3}}\n"
            "  - {at: 1.0, release: {block: 3}}\n");
        QVERIFY(sim);
        double speedBefore = 0;
        const Run r = runUntil(*sim, 1.5, [&](const Frame& f) {
            if (f.time < 0.8) speedBefore = sim->world().partVelocity(sim->blockPart(3)).linear.norm();
            if (f.time >= 0.8 && f.time < 1.0)
                QCOMPARE(sim->world().partVelocity(sim->blockPart(3)).linear.norm(), 0.0);
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(speedBefore > 0.05);  // it was moving when the hand took it
        QVERIFY2(r.worstBalance < 1e-6, qPrintable(QString::number(r.worstBalance)));
        QVERIFY(r.impactLossNeverFell);
    }

    // Two hands, one on each block of a pair: when the turned block comes
    // down on the other, the pair would be one rigid body with two drives
    // (the first one won) and an undetermined contact force. The run stops
    // and says so, naming the blocks, instead of following one hand.
    void aLockBetweenTwoHeldBlocksStopsTheRunAndSaysWhy() {
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "ladder: {blocks: 2, held: [0, 1], initial: {fold_angles: [1.2]}}\n"
            "script: [{at: 0.1, turn: {block: 1, by: 90deg, duration: 0.3}}]\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 1.0);
        QVERIFY(!r.failure.empty());
        qInfo("%s", r.failure.c_str());
        QVERIFY(r.failure.find("blocks 0 and 1 are both held") != std::string::npos);
    }

    // A ladder error stops the run in the step that raised it and keeps that
    // step's start: the motion, the structure and the time from before it,
    // nothing half settled. Before, the run kept the located instant with
    // the lock half made.
    void aLadderErrorKeepsTheStartOfItsStep() {
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "ladder: {blocks: 2, held: [0, 1], initial: {fold_angles: [1.2]}}\n"
            "script: [{at: 0.1, turn: {block: 1, by: 90deg, duration: 0.3}}]\n");
        QVERIFY(sim);
        double lastTime = 0;
        std::uint64_t lastHash = sim->stateHash();
        while (sim->stepOnce()) {
            lastTime = sim->time();
            lastHash = sim->stateHash();
        }
        QVERIFY(!sim->failure().empty());
        QCOMPARE(sim->time(), lastTime);
        QCOMPARE(sim->stateHash(), lastHash);
        QCOMPARE(sim->ladder()->hinge(1).mode, HingeMode::Free);
        QVERIFY(sim->ladder()->error().empty());  // the kept ladder is the step's start
        for (const Event& e : sim->frame().events) QVERIFY(e.time <= lastTime);
    }

    // Turned upright, the locked pair's contact unloads; when the hand stops
    // (its acceleration jumps to zero) the hanging block would need N = -m g/2:
    // it unlocks, then swings as a pendulum about the corner from phi = 0 at
    // rest, up to twice its hanging angle atan(T/L).
    void unlockWhenTheHandStopsThenSwingsToTwiceTheHangingAngle_data() { bothModelsOfRigidPairs(); }
    void unlockWhenTheHandStopsThenSwingsToTwiceTheHangingAngle() {
        QFETCH(QString, pairs);
        auto sim = simulate(flatHeldBlock(1.4, "90deg", pairs));
        QVERIFY(sim);
        double lastLockedN = 1, maxPhi = 0;
        const Run r = runUntil(*sim, 1.9, [&](const Frame& f) {
            if (f.hinges[0].mode == HingeMode::OpenLocked) lastLockedN = contactNow(*sim, 1).normal;
            if (f.time > 1.5) maxPhi = std::max(maxPhi, f.hinges[0].foldAngle);
        });
        QVERIFY(r.failure.empty());
        QVERIFY(r.events.size() >= 2);
        QCOMPARE(r.events[1].kind, EventKind::Unlock);
        QVERIFY2(std::abs(r.events[1].time - 1.5) < 1e-9, qPrintable(QString::number(r.events[1].time, 'g', 12)));
        QVERIFY(lastLockedN > 0);  // pushing up to the end of the turn
        QVERIFY2(std::abs(maxPhi - 2 * std::atan(T / L)) < 2e-4,
                 qPrintable(QString("max phi %1, 2 atan(T/L) = %2").arg(maxPhi).arg(2 * std::atan(T / L))));
    }

    // Block 1 topples onto the flat block and rests face to face: each end
    // carries half its weight, N_near = N_far = m g / 2.
    void foldRestsWithHalfTheWeightAtEachEnd_data() { bothModelsOfRigidPairs(); }
    void foldRestsWithHalfTheWeightAtEachEnd() {
        QFETCH(QString, pairs);
        auto sim = simulate(flatHeldBlock(2.0, "-90deg", pairs));
        QVERIFY(sim);
        const Run r = runUntil(*sim, 0.9);
        QCOMPARE(int(r.events.size()), 1);
        QCOMPARE(r.events[0].kind, EventKind::Fold);
        const HingeContact c = contactNow(*sim, 1);
        QVERIFY2(std::abs(c.nearEnd / (m * g / 2) - 1) < 1e-6, qPrintable(QString::number(c.nearEnd)));
        QVERIFY2(std::abs(c.farEnd / (m * g / 2) - 1) < 1e-6, qPrintable(QString::number(c.farEnd)));
    }

    // Turning the far end down, block 1 tips outward about its lower end: the
    // near contact unloads first and the hinge jumps to the far corner k^1.
    void flipFlopMovesHingeToFarCorner_data() { bothModelsOfRigidPairs(); }
    void flipFlopMovesHingeToFarCorner() {
        QFETCH(QString, pairs);
        auto sim = simulate(flatHeldBlock(2.0, "-90deg", pairs));
        QVERIFY(sim);
        HingeContact before;
        const Run r = runUntil(*sim, 1.45, [&](const Frame& f) {
            if (f.hinges[0].mode == HingeMode::Folded) before = contactNow(*sim, 1);
        });
        QCOMPARE(int(r.events.size()), 2);
        QCOMPARE(r.events[1].kind, EventKind::FlipFlop);
        QCOMPARE(r.events[1].corner, 1);  // k = 0 -> k ^ 1
        QCOMPARE(sim->ladder()->hinge(1).corner, 1);
        QVERIFY(before.nearEnd < before.farEnd);
        QVERIFY(before.nearEnd > -1e-6 && before.nearEnd < 0.01);  // it reached zero
        // Both blocks now share corner 1: the hinge point is the same on both.
        const World& w = sim->world();
        QVERIFY((sim->ladder()->cornerWorld(w, 0, 1) - sim->ladder()->cornerWorld(w, 1, 1)).norm() < 1e-9);
    }

    // The mirror turn unloads the far contact: the pair unfolds about k.
    void unfoldKeepsTheHingeCorner_data() { bothModelsOfRigidPairs(); }
    void unfoldKeepsTheHingeCorner() {
        QFETCH(QString, pairs);
        auto sim = simulate(flatHeldBlock(2.0, "90deg", pairs));
        QVERIFY(sim);
        HingeContact before;
        const Run r = runUntil(*sim, 1.45, [&](const Frame& f) {
            if (f.hinges[0].mode == HingeMode::Folded) before = contactNow(*sim, 1);
        });
        QCOMPARE(int(r.events.size()), 2);
        QCOMPARE(r.events[1].kind, EventKind::Unfold);
        QCOMPARE(sim->ladder()->hinge(1).corner, 0);
        QVERIFY(before.farEnd < before.nearEnd);
    }

    // A push is taken up like an impact: block 1, locked as a cantilever to
    // the held flat block 0 (the first case), is pushed at its centre. Up,
    // the impulse would pull the contact at the lower corner: it unlocks at
    // once and block 1 turns about the hinge pin as about a fixed pivot,
    // omega = ((c - h) x P) / I_p (worked by hand). Down, the contact takes
    // the push and the hand holds the pair: nothing moves.
    void pushThatWouldPullALockedContactUnlocksIt_data() {
        QTest::addColumn<double>("up");
        QTest::newRow("pushed up") << 1.0;
        QTest::newRow("pushed down") << -1.0;
    }
    void pushThatWouldPullALockedContactUnlocksIt() {
        QFETCH(double, up);
        const Vec2 P(0, up * 1e-3);
        auto sim = simulate(flatHeldBlock(1.4, "90deg") + "  - {at: 0.95, push: {block: 1, impulse: [0, " +
                            std::to_string(P.y()) + "], point: [0, 0]}}\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 0.95);
        QVERIFY(std::abs(sim->time() - 0.95) < 1e-12);
        QCOMPARE(r.events.front().kind, EventKind::Lock);
        const World& w = sim->world();
        const PartId b = sim->blockPart(1);
        const Twist v = w.partVelocity(b);
        if (up < 0) {
            QCOMPARE(r.events.back().kind, EventKind::Lock);
            QCOMPARE(sim->ladder()->hinge(1).mode, HingeMode::OpenLocked);
            QVERIFY(v.linear.norm() < 1e-12 && std::abs(v.angular) < 1e-12);
            return;
        }
        QCOMPARE(r.events.back().kind, EventKind::Unlock);
        QCOMPARE(r.events.back().time, 0.95);
        QCOMPARE(sim->ladder()->hinge(1).mode, HingeMode::Free);
        const Vec2 h = sim->ladder()->cornerWorld(w, 0, sim->ladder()->hinge(1).corner);
        const Vec2 c = w.partPose(b).position;
        const double ip = w.part(b).inertia + m * (c - h).squaredNorm();
        const double omega = cross(c - h, P) / ip;
        QVERIFY2(std::abs(v.angular / omega - 1) < 1e-9,
                 qPrintable(QString("omega %1, by hand %2").arg(v.angular).arg(omega)));
        QVERIFY((v.linear - omega * perp(c - h)).norm() < 1e-9 * std::abs(omega) * (c - h).norm());
        QVERIFY(sim->ladder()->foldRate(w, 1) > 0);                                    // opening
        QVERIFY2(r.worstBalance < 1e-8, qPrintable(QString::number(r.worstBalance)));  // as the lock case
    }

    void flipAndUnfoldAreMirrorImages() {
        auto flip = simulate(flatHeldBlock(2.0, "-90deg"));
        auto unfold = simulate(flatHeldBlock(2.0, "90deg"));
        const Run a = runUntil(*flip, 1.45), b = runUntil(*unfold, 1.45);
        QCOMPARE(int(a.events.size()), 2);
        QCOMPARE(int(b.events.size()), 2);
        QVERIFY(std::abs(a.events[1].time - b.events[1].time) < 1e-9);
    }

    // No held block, no gravity: a push at t = 0 closes the hinge; the plastic
    // LOCK impact keeps the pair's linear momentum (= the push) and its angular
    // momentum about the origin, and loses kinetic energy.
    void lockConservesMomentumWithoutHeldBlocks_data() { bothModelsOfRigidPairs(); }
    void lockConservesMomentumWithoutHeldBlocks() {
        QFETCH(QString, pairs);
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "solver: {rigid_pairs: " +
            pairs.toStdString() +
            "}\n"
            "gravity: [0, 0]\n"
            "ladder: {blocks: 2, held: [], initial: {fold_angles: [0.6]}}\n"
            "script:\n"
            "  - {at: 0, push: {block: 1, impulse: [0.004, 0.001], point: [0, -0.02]}}\n");
        QVERIFY(sim);
        auto momentum = [&](Vec2& p, double& spin) {
            const World& w = sim->world();
            p.setZero();
            spin = 0;
            for (int i = 0; i < 2; ++i) {
                const PartId id = sim->blockPart(i);
                const Twist v = w.partVelocity(id);
                const Vec2 c = w.partPose(id).position;
                p += w.part(id).mass * v.linear;
                spin += w.part(id).inertia * v.angular + w.part(id).mass * cross(c, v.linear);
            }
        };
        Vec2 p0;
        double l0 = 0;
        momentum(p0, l0);
        QVERIFY((p0 - Vec2(0.004, 0.001)).norm() < 1e-12);
        const double ke0 = energy(sim->world()).kinetic;
        const Run r = runUntil(*sim, 0.5);
        QVERIFY(!r.events.empty());
        QCOMPARE(r.events[0].kind, EventKind::Lock);
        Vec2 p1;
        double l1 = 0;
        momentum(p1, l1);
        QVERIFY2((p1 - p0).norm() < 1e-12, qPrintable(QString::number((p1 - p0).norm())));
        QVERIFY2(std::abs(l1 - l0) < 1e-12, qPrintable(QString::number(l1 - l0)));
        QVERIFY(energy(sim->world()).kinetic < ke0);
        QVERIFY(r.lastImpactLoss > 0);
        // The push at t = 0 is the user's work, booked once.
        QVERIFY2(r.worstBalance < 1e-12, qPrintable(QString::number(r.worstBalance)));
    }

    // Three blocks, the top turned half a turn counter-clockwise: hinge 1
    // folds and flips (corner 0 -> 1), then hinge 2 (corner 3 -> 2).
    void threeBlockCascadeFoldsAndFlipsInOrder_data() { bothModelsOfRigidPairs(); }
    void threeBlockCascadeFoldsAndFlipsInOrder() {
        QFETCH(QString, pairs);
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "solver: {rigid_pairs: " +
            pairs.toStdString() +
            "}\n"
            "ladder: {blocks: 3, held: [0]}\n"
            "script: [{at: 0.2, turn: {block: 0, by: 180deg, duration: 0.3}}]\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 1.0);
        QVERIFY(r.failure.empty());
        std::vector<const Event*> folds, flips;
        for (const Event& e : r.events) {
            if (e.kind == EventKind::Fold) folds.push_back(&e);
            if (e.kind == EventKind::FlipFlop) flips.push_back(&e);
        }
        QCOMPARE(int(flips.size()), 2);
        QCOMPARE(flips[0]->hinge, 1);
        QCOMPARE(flips[0]->corner, 1);
        QCOMPARE(flips[1]->hinge, 2);
        QCOMPARE(flips[1]->corner, 2);
        QVERIFY(flips[0]->time < flips[1]->time);
        QVERIFY(r.worstBalance < 1e-6);
        QVERIFY(r.impactLossNeverFell);
    }
};

QTEST_GUILESS_MAIN(LadderEventsTest)
#include "test_ladder_events.moc"
