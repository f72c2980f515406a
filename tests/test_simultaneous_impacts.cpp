// labels: physics;ladder
// Two hinges that strike their limits at the same instant, worked by hand.
// Three default blocks (60 x 12 x 45 mm, density 600) lie end to end in
// free space, no gravity, no hand: block 1 is still, blocks 0 and 2 turn
// about its two hinges at the same rate, closing both. The picture is
// symmetric under the half turn about block 1's centre, so both hinges
// strike with the same approach speed, and nothing outside the ladder does
// work: whatever the kinetic energy loses is the impact's loss, and the
// hand's work is zero (docs/model.md section 12.3).
#include "jl/engine/dynamics.h"
#include "jl/engine/energy.h"
#include "jl/engine/world.h"
#include "jl/ladder/ladder.h"

#include <QtTest>

#include <array>
#include <cmath>

using namespace jl;

namespace {

struct Strike {
    World w;
    Ladder ladder;
    std::array<double, 2> approach{};  // rad/s, hinges 1 and 2 closing before the impact
    double keBefore = 0;
    std::array<double, 3> momentumBefore{};
    double loss = 0, heldWork = 0;
    std::vector<Event> events;

    static LadderSpec spec(double restitution, double minRebound) {
        LadderSpec s;
        s.blocks = 3;
        s.held.clear();
        s.hinges.restitution = restitution;
        s.hinges.minReboundSpeed = minRebound;
        s.initial.kind = InitialState::Kind::FoldAngles;
        s.initial.foldAngles = {0, 0};
        return s;
    }

    // Blocks 0 and 2 turn at omega0 and omega2 about their hinges, both
    // closing them (the signs are flipped together if they open).
    Strike(double restitution, double minRebound, double omega0, double omega2)
        : ladder(w, spec(restitution, minRebound)) {
        const Vec2 p1 = ladder.cornerWorld(w, 0, ladder.hinge(1).corner);
        const Vec2 p2 = ladder.cornerWorld(w, 1, ladder.hinge(2).corner);
        const auto about = [&](int block, const Vec2& pivot, double rate) {
            const Vec2 arm = w.partPose(ladder.block(block)).position - pivot;
            return Twist{rate * Vec2(-arm.y(), arm.x()), rate};
        };
        std::vector<Twist> v = w.partVelocities();
        v[size_t(ladder.block(0))] = about(0, p1, omega0);
        v[size_t(ladder.block(1))] = Twist{Vec2::Zero(), 0};
        v[size_t(ladder.block(2))] = about(2, p2, omega2);
        w.setPartVelocities(v);
        if (ladder.foldRate(w, 1) > 0) {
            for (Twist& t : v) t = Twist{-t.linear, -t.angular};
            w.setPartVelocities(v);
        }
        approach = {-ladder.foldRate(w, 1), -ladder.foldRate(w, 2)};
        keBefore = energy(w).kinetic;
        momentumBefore = momentum();
        Dynamics d;
        events = ladder.resolve(w, d, 0, &loss, &heldWork);
    }
    double ke() const { return energy(w).kinetic; }
    // Linear momentum and angular momentum about the origin: no force
    // outside the ladder, so an impact keeps all three.
    std::array<double, 3> momentum() const {
        std::array<double, 3> p{};
        for (int i = 0; i < 3; ++i) {
            const Part& part = w.part(ladder.block(i));
            const Vec2 c = w.partPose(ladder.block(i)).position;
            const Twist v = w.partVelocity(ladder.block(i));
            p[0] += part.mass * v.linear.x();
            p[1] += part.mass * v.linear.y();
            p[2] += part.inertia * v.angular + part.mass * (c.x() * v.linear.y() - c.y() * v.linear.x());
        }
        return p;
    }
    // The impact kept the momenta and booked every joule the ladder lost
    // as its loss, none as a hand's work (there is no hand).
    QString booksOpen() const {
        const auto now = momentum();
        for (int k = 0; k < 3; ++k)
            if (std::abs(now[size_t(k)] - momentumBefore[size_t(k)]) > 1e-12)
                return QString("momentum %1 went from %2 to %3")
                    .arg(k)
                    .arg(momentumBefore[size_t(k)])
                    .arg(now[size_t(k)]);
        if (std::abs(keBefore - ke() - loss) > 1e-12 * keBefore)
            return QString("the ladder lost %1 J, the impact booked %2 J").arg(keBefore - ke()).arg(loss);
        if (std::abs(heldWork) > 1e-12 * keBefore) return QString("a hand's work of %1 J with no hand").arg(heldWork);
        return {};
    }
};

int count(const std::vector<Event>& events, EventKind kind) {
    int n = 0;
    for (const Event& e : events) n += e.kind == kind;
    return n;
}

}  // namespace

class SimultaneousImpactsTest : public QObject {
    Q_OBJECT
private slots:
    // The set-up is what the header says: both hinges close, at one rate
    // when the blocks turn alike.
    void bothHingesClose() {
        const Strike s(0, 1e-4, 2.0, 2.0);
        QVERIFY(s.approach[0] > 0.5);
        QVERIFY2(std::abs(s.approach[1] - s.approach[0]) < 1e-12 * s.approach[0],
                 qPrintable(QString("%1 %2").arg(s.approach[0]).arg(s.approach[1])));
    }

    // Plastic: both lock and the three blocks turn as one rod, every hinge
    // still. (The rod's turning then pulls each end contact open, a release
    // by force at the same instant: its pin sits off the rod's axis.)
    void aPlasticDoubleStrikeBooksItsWholeLossAsLoss() {
        Strike s(0, 1e-4, 2.0, 2.0);
        QCOMPARE(count(s.events, EventKind::Lock), 2);
        QCOMPARE(count(s.events, EventKind::Bounce), 0);
        for (int j : {1, 2}) QVERIFY(std::abs(s.ladder.foldRate(s.w, j)) < 1e-12);
        QVERIFY2(s.booksOpen().isEmpty(), qPrintable(s.booksOpen()));
    }

    // Restitution e: by the symmetry both hinges take the same approach
    // speed and both bounce, each opening at e times it; the energy the
    // ladder keeps is booked, none of it as a hand's work.
    void bothHingesBounceAtETimesTheirOwnApproach() {
        const double e = 0.5;
        Strike s(e, 1e-4, 2.0, 2.0);
        QCOMPARE(count(s.events, EventKind::Bounce), 2);
        for (int j : {1, 2})
            QVERIFY2(std::abs(s.ladder.foldRate(s.w, j) - e * s.approach[0]) < 1e-9 * s.approach[0],
                     qPrintable(QString("hinge %1 opens at %2, approach %3")
                                    .arg(j)
                                    .arg(s.ladder.foldRate(s.w, j))
                                    .arg(s.approach[0])));
        QVERIFY2(s.booksOpen().isEmpty(), qPrintable(s.booksOpen()));
    }

    // Adjacent hinges struck at once take the approach speeds they had
    // before the impact: v_min just below e times that speed bounces both,
    // just above it bounces neither. (A speed read after the first hinge
    // merged its pair differs, and treated the two unlike.)
    void theApproachIsTakenBeforeAnyHingeMerges() {
        const double e = 0.5;
        const double approach = Strike(0, 1e-4, 2.0, 2.0).approach[0];
        for (double share : {0.99, 1.01}) {
            const Strike s(e, share * e * approach, 2.0, 2.0);
            QCOMPARE(count(s.events, EventKind::Bounce), share < 1 ? 2 : 0);
            QVERIFY2(s.booksOpen().isEmpty(), qPrintable(s.booksOpen()));
        }
    }

    // A mixed outcome: block 2 turns three times faster, v_min between the
    // two rebounds, so hinge 2 bounces and hinge 1 is stopped (a second,
    // plastic jump after the bounce). With no hand, the loss booked is all
    // the ladder lost.
    void aMixedOutcomeBooksNoHandWork() {
        const double e = 0.5;
        const Strike probe(0, 1e-4, 2.0, 3.0);
        QVERIFY(probe.approach[1] > 1.4 * probe.approach[0]);
        const Strike s(e, e * std::sqrt(probe.approach[0] * probe.approach[1]), 2.0, 3.0);
        QCOMPARE(count(s.events, EventKind::Bounce), 1);
        QVERIFY(std::abs(s.ladder.foldRate(s.w, 1)) < 1e-12);  // stopped
        QVERIFY(s.ladder.foldRate(s.w, 2) > 0);                // opening
        QVERIFY2(s.booksOpen().isEmpty(), qPrintable(s.booksOpen()));
    }
};

QTEST_GUILESS_MAIN(SimultaneousImpactsTest)
#include "test_simultaneous_impacts.moc"
