// labels: physics
// A table top under the ladder (docs/model.md section 17.8), against
// answers worked by hand: a hanging ladder let go lands when free fall
// says it does; the impact changes only what a frictionless table can
// push (no horizontal momentum, no angular momentum about the struck
// corner, none of the upper block's about its hinge), and stops the
// corner; the ladder comes to rest lying on the table, held up by its
// weight; a ladder that hangs clear of the table runs as if there were
// none; a corner that starts under the table is refused; a hand that
// drives blocks into the table stops the run.
#include "jl/engine/energy.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <sstream>

using namespace jl;
using namespace jl::test;

namespace {

constexpr double kG = 9.81;
constexpr double kTable = -0.2;  // m

// Two default blocks hanging from the hand, let go at t = 0 above a table.
std::string dropScene(double table = kTable, const std::string& solver = "{event_tolerance: 1e-12}") {
    std::ostringstream yaml;
    yaml << "format: jacobs-ladder/1\n"
            "title: two blocks dropped on a table\n"
            "ladder:\n"
            "  blocks: 2\n"
            "script:\n"
            "  - {at: 0, release: {block: 0}}\n"
            "floor: {height: "
         << table << "}\nsolver: " << solver << "\nduration: 1\n";
    return yaml.str();
}

// The lowest block corner and its height.
Vec2 lowestCorner(const Simulation& sim) {
    const Ladder& ladder = *sim.ladder();
    Vec2 low(0, 1e300);
    for (int i = 0; i < ladder.blockCount(); ++i)
        for (int k = 0; k < 4; ++k) {
            const Vec2 p = ladder.cornerWorld(sim.world(), i, k);
            if (p.y() < low.y()) low = p;
        }
    return low;
}

// Angular momentum of blocks [first, last] about point c (kg m^2/s), from
// each block's own velocity, or from `common` (every block translating at
// that velocity) when given.
double angularMomentum(const Simulation& sim, int first, int last, const Vec2& c, const Vec2* common = nullptr) {
    const World& w = sim.world();
    double l = 0;
    for (int i = first; i <= last; ++i) {
        const PartId p = sim.ladder()->block(i);
        const Twist v = common ? Twist{*common, 0} : w.partVelocity(p);
        l += w.part(p).mass * cross(w.partPose(p).position - c, v.linear) + w.part(p).inertia * v.angular;
    }
    return l;
}

// Every block flat on the table (its long sides level, its centre half a
// thickness, halfSize.x, above the top), still, no corner under the top,
// and the table's pushes holding up the whole weight.
void liesStillOnTheTable(const Simulation& sim, double table) {
    const World& w = sim.world();
    const Ladder& ladder = *sim.ladder();
    double weight = 0;
    for (int i = 0; i < ladder.blockCount(); ++i) {
        const PartId p = ladder.block(i);
        const Pose pose = w.partPose(p);
        const Twist v = w.partVelocity(p);
        const double speed = v.linear.norm() + ladder.length() * std::abs(v.angular);
        qInfo("block %d at (%.9f, %.9f) m, angle %.9f rad; speed %.3g m/s", i, pose.position.x(), pose.position.y(),
              pose.angle, speed);
        QVERIFY(speed < 1e-9);
        QVERIFY(std::abs(std::cos(pose.angle)) < 1e-9);
        QVERIFY(std::abs(pose.position.y() - (table + w.part(p).halfSize.x())) < 1e-9);
        weight += w.part(p).mass * kG;
    }
    QVERIFY(lowestCorner(sim).y() > table - 1e-9);
    World at = w;
    Dynamics d;
    d.evaluate(at, sim.time());
    const Eigen::VectorXd pushes = d.contactForces();
    qInfo("%d resting corners push %.12g N, weight %.12g N", int(pushes.size()), pushes.sum(), weight);
    QVERIFY(pushes.size() >= 2);
    QVERIFY(pushes.minCoeff() > -1e-12);
    QVERIFY(std::abs(pushes.sum() - weight) < 1e-9 * weight);
}

}  // namespace

class FloorTest : public QObject {
    Q_OBJECT

private slots:
    // Let go at rest, the ladder falls freely as it hung: its lowest
    // corner, d above the table, lands at t = sqrt(2 d / g), alone.
    void aLadderLetGoLandsWhenFreeFallSaysSo() {
        auto sim = simulate(dropScene());
        QVERIFY(sim);
        const double d = lowestCorner(*sim).y() - kTable;
        QVERIFY(d > 0.1);
        Event touch;
        std::vector<Event> instant;
        QVERIFY(stepUntil(*sim, EventKind::Touch, 0.5, &touch, &instant));
        const double landing = std::sqrt(2 * d / kG);
        qInfo("%s at %.12f s, by hand %.12f s", touch.text.c_str(), touch.time, landing);
        QVERIFY(std::abs(touch.time - landing) < 1e-10);
        QVERIFY(touch.text.find("strikes the floor") != std::string::npos);
        QCOMPARE(int(instant.size()), 1);  // one corner, and no hinge event with it
        QCOMPARE(int(sim->world().contacts().size()), 1);
    }

    // The table pushes only up, at the struck corner c; the hinge pushes
    // block 0 only at the hinge point h. So through the plastic impact
    // (the blocks falling at v = g t, not turning, before it):
    //   - the horizontal momentum stays zero;
    //   - the angular momentum of both blocks about c is kept;
    //   - block 0's angular momentum about h is kept;
    //   - the corner stops moving down (plastic);
    //   - the loss booked is the kinetic energy the jump took away.
    // Six equations for the two blocks' six velocities: the hand's answer.
    void theImpactChangesOnlyWhatTheTablePushes() {
        auto sim = simulate(dropScene());
        QVERIFY(sim);
        Event touch;
        std::vector<Event> instant;
        QVERIFY(stepUntil(*sim, EventKind::Touch, 0.5, &touch, &instant));
        QCOMPARE(int(instant.size()), 1);
        const World& w = sim->world();
        const Ladder& ladder = *sim->ladder();
        const Contact& contact = w.contacts().at(0);
        QCOMPARE(contact.cornerPart, ladder.block(1));
        const Vec2 c = w.pointPosition(contact.cornerPart, contact.corner);
        QVERIFY(std::abs(c.y() - kTable) < 1e-9);
        Vec2 h = ladder.cornerWorld(w, 0, 0);
        for (int k0 = 0; k0 < 4; ++k0)
            for (int k1 = 0; k1 < 4; ++k1)
                if ((ladder.cornerWorld(w, 0, k0) - ladder.cornerWorld(w, 1, k1)).norm() < 1e-9)
                    h = ladder.cornerWorld(w, 0, k0);
        const Vec2 fall(0, -kG * touch.time);
        double momentumX = 0, before = 0, after = 0;
        for (int i = 0; i < 2; ++i) {
            const PartId p = ladder.block(i);
            const Twist v = w.partVelocity(p);
            momentumX += w.part(p).mass * v.linear.x();
            before += 0.5 * w.part(p).mass * fall.squaredNorm();
            after += 0.5 * w.part(p).mass * v.linear.squaredNorm() + 0.5 * w.part(p).inertia * v.angular * v.angular;
        }
        const double aboutC0 = angularMomentum(*sim, 0, 1, c, &fall), aboutC1 = angularMomentum(*sim, 0, 1, c);
        const double aboutH0 = angularMomentum(*sim, 0, 0, h, &fall), aboutH1 = angularMomentum(*sim, 0, 0, h);
        const Twist v1 = w.partVelocity(ladder.block(1));
        const double cornerDown = (v1.linear + v1.angular * perp(c - w.partPose(ladder.block(1)).position)).y();
        qInfo("momentum x %.3g; about c %.12g -> %.12g; block 0 about h %.12g -> %.12g; corner %.3g m/s", momentumX,
              aboutC0, aboutC1, aboutH0, aboutH1, cornerDown);
        QVERIFY(std::abs(momentumX) < 1e-12);
        QVERIFY(std::abs(aboutC1 - aboutC0) < 1e-9 * std::abs(aboutC0));
        QVERIFY(std::abs(aboutH1 - aboutH0) < 1e-9 * std::abs(aboutH0) + 1e-15);
        QVERIFY(std::abs(cornerDown) < 1e-9 * fall.norm());
        QVERIFY(after < before);
        const double loss = sim->frame().energy.impactLoss;
        qInfo("loss %.12g J, by the jump %.12g J", loss, before - after);
        QVERIFY(std::abs(loss - (before - after)) < 1e-9 * (before - after));
    }

    // After it has tipped over, the ladder lies still on the table, its
    // books balanced through every impact.
    void theLadderComesToRestLyingOnTheTable() {
        auto sim = simulate(dropScene(kTable, "{}"));
        QVERIFY(sim);
        const Run run = runUntil(*sim, 1.0);
        QVERIFY2(run.failure.empty(), run.failure.c_str());
        liesStillOnTheTable(*sim, kTable);
        qInfo("worst balance %.3g J", run.worstBalance);
        QVERIFY(run.worstBalance < 1e-7);
        QVERIFY(sim->frame().energy.impactLoss > 0);
    }

    // examples/dropped-on-a-table.yaml, each claim of its description.
    void theExampleDoesWhatItSays() {
        auto sim = simulateFile("examples/dropped-on-a-table.yaml");
        QVERIFY(sim);
        const double table = sim->scene().floor->height;
        const double d = lowestCorner(*sim).y() - table;
        // "the pair falls as it hung, and the lower block strikes the table
        // on one corner when free fall says it must"
        Event touch;
        std::vector<Event> instant;
        QVERIFY(stepUntil(*sim, EventKind::Touch, 1.0, &touch, &instant));
        QVERIFY(std::abs(touch.time - (0.1 + std::sqrt(2 * d / kG))) < 1e-8);
        QCOMPARE(int(instant.size()), 1);
        // "that corner stops, and the energy the knock takes is booked"
        const World& w = sim->world();
        const Contact& c = w.contacts().at(0);
        const Twist v = w.partVelocity(c.cornerPart);
        const Vec2 arm = w.pointPosition(c.cornerPart, c.corner) - w.partPose(c.cornerPart).position;
        QVERIFY(std::abs((v.linear + v.angular * perp(arm)).y()) < 1e-9);
        QVERIFY(sim->frame().energy.impactLoss > 0);
        // "tips over, locks end to end, rocks from one end to the other with
        // ever quicker knocks": after the first lock, each knock (a lock)
        // lands the pair on the other end (a touch by the other block at
        // that instant), sooner after the one before than that one was.
        std::vector<double> locks;
        std::vector<int> landed;
        const Run run = runUntil(*sim, sim->scene().duration, [&](const Frame& f) {
            bool locked = false;
            for (const Event& e : f.events) locked = locked || e.kind == EventKind::Lock;
            if (!locked) return;
            locks.push_back(f.time);
            for (const Event& e : f.events)
                if (e.kind == EventKind::Touch) landed.push_back(e.text.rfind("block 0", 0) == 0 ? 0 : 1);
        });
        QVERIFY2(run.failure.empty(), run.failure.c_str());
        qInfo("%d knocks, the last at %.6f s", int(locks.size()), locks.empty() ? 0.0 : locks.back());
        QVERIFY(locks.size() >= 5);
        QVERIFY(landed.size() >= 4);
        for (size_t i = 1; i < landed.size(); ++i) QVERIFY(landed[i] != landed[i - 1]);
        for (size_t i = 2; i < locks.size(); ++i) QVERIFY(locks[i] - locks[i - 1] < locks[i - 1] - locks[i - 2]);
        // "comes to rest lying flat on the table, which holds up its whole weight"
        liesStillOnTheTable(*sim, table);
        QVERIFY(run.worstBalance < 1e-7);
    }

    // A table below where the ladder ever reaches: the same run, step for
    // step, as with no table (nothing is watched against it).
    void aTableNothingReachesChangesNothing() {
        const auto load = [](bool table) {
            SceneLoad l = loadScene(std::string(JL_SOURCE_DIR) + "/examples/classic.yaml");
            if (table) l.scene->floor = FloorSpec{-10};
            return Simulation::build(*l.scene);
        };
        auto with = load(true), without = load(false);
        QVERIFY(with.simulation && without.simulation);
        const Run a = runUntil(*with.simulation, 3), b = runUntil(*without.simulation, 3);
        QVERIFY(a.failure.empty() && b.failure.empty());
        QVERIFY(!a.events.empty());
        QCOMPARE(a.events.size(), b.events.size());
        for (size_t i = 0; i < a.events.size(); ++i) QCOMPARE(a.events[i].time, b.events[i].time);
        QVERIFY(with.simulation->world().q == without.simulation->world().q);
    }

    // The hand lowering three blocks onto the table drives them into it
    // through blocks the pins keep nearly straight: the plastic impact's
    // answer is an impulse without bound, booked alike as the hand's work
    // and as loss, so the books balance while blocks of 20 g fly off at
    // metres a second (9.7 J by 1.95 s, 5e8 J booked by 2.88 s). The run
    // stops at the first such instant, saying so, with the state before it:
    // nothing flung ever reaches a frame.
    void aHandDrivingBlocksIntoTheTableStopsTheRun() {
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "title: lowered onto a table\n"
            "ladder: {blocks: 3, held: [0]}\n"
            "floor: {height: -0.19}\n"
            "solver: {block_contact: on}\n"
            "duration: 4\n"
            "script:\n"
            "  - {at: 0.2, move: {block: 0, by: [0, -0.14], duration: 3}}\n");
        QVERIFY(sim);
        double mostKinetic = 0;
        const Run run =
            runUntil(*sim, 4, [&](const Frame& f) { mostKinetic = std::max(mostKinetic, f.energy.kinetic); });
        qInfo("%s; the most kinetic energy in a frame %.3g J", run.failure.c_str(), mostKinetic);
        QVERIFY(run.failure.find("J from the hand") != std::string::npos);
        QVERIFY(run.failure.find("into the floor") != std::string::npos);
        QVERIFY(sim->time() < 1.3);
        QVERIFY(mostKinetic < 1e-3);
        QVERIFY(run.worstBalance < 1e-5);
    }

    // A ladder hanging into the table is a scene that cannot be built: said
    // with the corner, the block and how far under.
    void aCornerStartingUnderTheTableIsRefused() {
        SceneLoad load = parseScene(dropScene(-0.05), "under.yaml");
        QVERIFY(load.scene);
        const Simulation::Built built = Simulation::build(*load.scene);
        QVERIFY(!built.simulation);
        QCOMPARE(int(built.errors.size()), 1);
        qInfo("%s", built.errors[0].c_str());
        QVERIFY(built.errors[0].find("of block 1 starts") != std::string::npos);
        QVERIFY(built.errors[0].find("below the floor") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(FloorTest)
#include "test_floor.moc"
