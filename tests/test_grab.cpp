// labels: physics;ladder
// The hand takes hold of a moving block (docs/model.md section 10): an
// impact in which the block gets infinite mass. Its neighbours' contacts
// take the jump up as an impact's do: one that would have to pull opens.
// The known answer: the blocks below the grabbed one are pinned to it at
// one point, which the grab stops dead; the only impulse on them acts
// there, so their angular momentum about that point is kept through the
// grab, whatever their hinges do among themselves.
#include "jl/engine/world.h"
#include "jl/ladder/ladder.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <string>

using namespace jl;
using namespace jl::test;

namespace {

// The classic cascade with one more script row at `at`.
std::unique_ptr<Simulation> classicWith(const std::string& action, double at) {
    std::string yaml =
        "format: jacobs-ladder/1\n"
        "ladder: {blocks: 6, held: [0]}\n"
        "script:\n"
        "  - {at: 0.2, turn: {block: 0, by: 180deg, duration: 0.3}}\n";
    yaml += "  - {at: " + std::to_string(at) + ", " + action + "}\n";
    return simulate(yaml);
}

// Angular momentum of blocks first..last about the point p (kg m^2/s).
double momentAbout(const Simulation& sim, int first, int last, const Vec2& p) {
    const World& w = sim.world();
    double l = 0;
    for (int i = first; i <= last; ++i) {
        const PartId b = sim.ladder()->block(i);
        const Vec2 r = w.partPose(b).position - p;
        const Twist v = w.partVelocity(b);
        l += w.part(b).inertia * v.angular + w.part(b).mass * (r.x() * v.linear.y() - r.y() * v.linear.x());
    }
    return l;
}

}  // namespace

class GrabTest : public QObject {
    Q_OBJECT
private slots:
    // At 1.61 s block 3 is locked end to end to block 2 and leads it:
    // stopping block 2 would need hinge 3's contact to pull block 3 back.
    // It opens, and blocks 3 to 5 go on about hinge 3 with their angular
    // momentum about it. (Before, the grab stopped block 3 with block 2.)
    void aNeighbourThatWouldSwingAwayGoesOn() {
        const double at = 1.61;
        // The same run, a no-op at the same instant (a push on the held
        // block, which the hand takes): the steps land on it alike.
        auto before = classicWith("push: {block: 0, impulse: [0, 0], point: [0, 0]}", at);
        auto grabbed = classicWith("hold: {block: 2}", at);
        QVERIFY(before && grabbed);
        QVERIFY(runUntil(*before, at).failure.empty());
        const Run r = runUntil(*grabbed, at);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QCOMPARE(before->time(), at);
        QCOMPARE(grabbed->time(), at);
        QVERIFY(before->ladder()->hinge(3).mode == HingeMode::OpenLocked);

        const Ladder& ladder = *grabbed->ladder();
        bool opened = false;
        for (const Event& e : r.events)
            opened = opened || (e.time == at && e.hinge == 3 && e.kind == EventKind::Unlock);
        QVERIFY2(opened, "hinge 3 does not open at the grab");
        QVERIFY(ladder.hinge(3).mode == HingeMode::Free);
        QVERIFY(ladder.foldRate(grabbed->world(), 3) > 0);  // opening
        QCOMPARE(grabbed->world().partVelocity(ladder.block(2)).linear.norm(), 0.0);

        const Vec2 p = ladder.cornerWorld(grabbed->world(), 2, ladder.hinge(3).corner);
        const double l0 = momentAbout(*before, 3, 5, p), l1 = momentAbout(*grabbed, 3, 5, p);
        QVERIFY(std::abs(l0) > 1e-6);
        // To the pins' gap (1e-10 m over a 60 mm block, the arm of the pin
        // impulse about p): 1.0e-11 of it measured.
        QVERIFY2(std::abs(l1 - l0) < 1e-9 * std::abs(l0),
                 qPrintable(QString("angular momentum about hinge 3: %1 before, %2 after")
                                .arg(l0, 0, 'g', 17)
                                .arg(l1, 0, 'g', 17)));
        QVERIFY2(r.worstBalance < 1e-6, qPrintable(QString::number(r.worstBalance)));
    }
};

QTEST_GUILESS_MAIN(GrabTest)
#include "test_grab.moc"
