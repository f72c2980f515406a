// labels: physics;ladder
// The books of a scripted join (docs/model.md sections 11.4 and 12.3): the
// merge of the two blocks' motion is a plastic impact whose loss is the
// energy of its velocity jump in the mass metric, which needs no frame, so
// that the impact loss never falls, however many blocks the hand holds and
// however it moves.
#include "jl/engine/energy.h"
#include "jl/engine/world.h"
#include "tests/scene_run.h"

#include <QtTest>

using namespace jl;
using namespace jl::test;

class ScriptedJoinTest : public QObject {
    Q_OBJECT
private slots:
    // Three blocks, 0 and 2 held, both hinges cut at t = 0: block 1 falls
    // free while the hand sweeps block 2 sideways (2 m in 0.3 s). At 0.01 s
    // block 1 is joined to the moving block 2. The join used to book its
    // loss as a drop of kinetic energy in the held block's frame, which
    // with two held blocks is no frame at all: the hand's push on block 1
    // counted as negative dissipation, and the impact loss fell to
    // -2.97e-3 J. The loss is now the jump's own energy, 1/2 m |dv|^2 +
    // 1/2 I dw^2 of block 1, and the hand's share is its work.
    void aJoinToAMovingHandNeverCreatesEnergy() {
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "ladder: {blocks: 3, held: [0, 2]}\n"
            "script:\n"
            "  - {at: 0, cut: {hinge: 1}}\n"
            "  - {at: 0, cut: {hinge: 2}}\n"
            "  - {at: 0, move: {block: 2, by: [2, 0], duration: 0.3}}\n"
            "  - {at: 0.01, join: {block: 1, corner: 3, other: 2, other_corner: 3}}\n");
        QVERIFY(sim);
        QVERIFY(sim->advanceExactlyTo(0.01 - 1e-9));
        const PartId block1 = sim->blockPart(1);
        const Twist before = sim->world().partVelocities()[size_t(block1)];
        const double lossBefore = sim->frame().energy.impactLoss;
        QVERIFY(sim->advanceExactlyTo(0.01));
        const Frame at = sim->frame();
        const Twist after = sim->world().partVelocities()[size_t(block1)];
        const Part& part = sim->world().part(block1);
        const double jump = 0.5 * part.mass * (after.linear - before.linear).squaredNorm() +
                            0.5 * part.inertia * std::pow(after.angular - before.angular, 2);
        qInfo("loss booked at the join %.6g J, the jump's energy %.6g J", at.energy.impactLoss - lossBefore, jump);
        QVERIFY(jump > 1e-4);
        QVERIFY(std::abs((at.energy.impactLoss - lossBefore) - jump) <= 1e-12 + 1e-9 * jump);
        const Run r = runUntil(*sim, 0.3);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(r.impactLossNeverFell);
        // The books hold to RK4's error with the hand sweeping at up to
        // 10 m/s (1.6e-7 J), whatever the split between loss and work.
        QVERIFY2(r.worstBalance < 1e-6, qPrintable(QString("books %1 J").arg(r.worstBalance)));
    }
};

QTEST_GUILESS_MAIN(ScriptedJoinTest)
#include "test_scripted_join.moc"
