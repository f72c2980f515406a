// labels: physics
// Contact between blocks that are not neighbours (docs/model.md section 17),
// against answers worked by hand: a block dropped flat onto a held block
// (when it lands, what it loses, the pushes that hold it up), a block
// landing on one corner (the impulse of a rigid-body impact), a block
// sliding down a tilted face without friction (energy kept), and every
// example and design of the map's 12-block row (no two blocks inside each
// other).
#include "jl/design/ripple_reach.h"
#include "jl/engine/energy.h"
#include "tests/block_overlap.h"
#include "tests/example_claims.h"
#include "tests/ladder_scenes.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <filesystem>
#include <memory>
#include <numbers>

using namespace jl;
using namespace jl::test;

namespace {

constexpr double kG = 9.81;

// Three default blocks: block 0 lies flat at the origin, blocks 1 and 2 are
// held (hinges at 135 degrees, so block 2 lies flat below block 0 and half
// under it, 38.9 mm lower), and hinge 1 is cut at t = 0: block 0 falls
// freely onto block 2, which it never meets through a hinge.
std::string dropScene(const std::string& extra, const std::string& solver = "",
                      const std::string& gravity = "[0, -9.81]") {
    std::string yaml =
        "format: jacobs-ladder/1\n"
        "title: drop\n"
        "ladder:\n"
        "  blocks: 3\n"
        "  block: {length: 0.06, thickness: 0.012, width: 0.045, density: 600}\n"
        "  held: [1, 2]\n"
        "  initial:\n"
        "    kind: fold_angles\n"
        "    poses:\n"
        "      - {block: 0, position: [0, 0], angle: 90deg}\n"
        "    fold_angles: [2.356194490192345, 2.356194490192345]\n"
        "duration: 1\n";
    yaml.append("gravity: ").append(gravity).append("\n");
    if (!solver.empty()) yaml.append("solver: ").append(solver).append("\n");
    yaml.append("script:\n  - {at: 0, cut: {hinge: 1}}\n").append(extra);
    return yaml;
}

// The pushes of the resting contacts in the state the simulation holds.
Eigen::VectorXd pushes(const Simulation& sim) {
    World w = sim.world();
    Dynamics d;
    d.evaluate(w, sim.time());
    return d.contactForces();
}

// The complete example of docs/scene-format.md with contact between blocks on.
std::unique_ptr<Simulation> formatPageExampleWithContact() {
    SceneLoad load = formatPageExample();
    if (!load.scene) return nullptr;
    load.scene->solver.blockContact = BlockContact::On;
    return std::move(Simulation::build(*load.scene).simulation);
}

}  // namespace

class BlockContactTest : public QObject {
    Q_OBJECT

private slots:
    // Block 0 falls h = (its height above block 2) - T from rest: it lands
    // at t = sqrt(2 h / g), with both touching corners at once (block 0's
    // bottom right on block 2's face, block 2's top left on block 0's),
    // loses all of m g h in the plastic impact, and rests on block 2 with
    // pushes adding up to its weight, m g.
    void aFlatDropRestsOnItsWeight() {
        auto sim = simulate(dropScene("", "{block_contact: on, event_tolerance: 1e-12}"));
        QVERIFY(sim);
        const World& w0 = sim->world();
        const Ladder& ladder = *sim->ladder();
        const double m = w0.part(ladder.block(0)).mass;
        const double top = w0.partPose(ladder.block(0)).position.y();
        const double h = top - w0.partPose(ladder.block(2)).position.y() - 0.012;
        QVERIFY(std::abs(h - 0.050911688245431419) < 1e-12);
        const double landing = std::sqrt(2 * h / kG);  // 0.1018800724 s
        Event touch;
        std::vector<Event> instant;
        QVERIFY(stepUntil(*sim, EventKind::Touch, 0.5, &touch, &instant));
        for (const Event& e : instant) qInfo("%.12f %s %s", e.time, toString(e.kind), e.text.c_str());
        qInfo("landed at %.12f s, by hand %.12f s", touch.time, landing);
        QVERIFY(std::abs(touch.time - landing) < 1e-10);
        const double lossByHand = m * kG * h;  // 9.709e-3 J
        runUntil(*sim, 0.4);
        const Frame f = sim->frame();
        qInfo("impact loss %.12g J, by hand %.12g J", f.energy.impactLoss, lossByHand);
        QVERIFY(std::abs(f.energy.impactLoss - lossByHand) < 1e-9 * lossByHand);
        QVERIFY(std::abs(f.energy.balance()) < 1e-9);
        // At rest, on top of block 2.
        const Pose rest = sim->world().partPose(ladder.block(0));
        qInfo("at rest %.12f m below where it fell from, h = %.12f m", top - rest.position.y(), h);
        QVERIFY(std::abs(rest.position.y() - (top - h)) < 1e-9);
        QVERIFY(sim->world().partVelocity(ladder.block(0)).linear.norm() < 1e-9);
        const Eigen::VectorXd p = pushes(*sim);
        QCOMPARE(int(p.size()), 2);
        qInfo("pushes %.12g + %.12g N, weight %.12g N", p[0], p[1], m * kG);
        QVERIFY(p.minCoeff() > 0);
        QVERIFY(std::abs(p.sum() - m * kG) < 1e-9 * m * kG);
        QVERIFY(deepestOverlap(*sim) < 1e-9);
        // The frame the views draw: both corners, on the faces they rest
        // on, pushed up (block 0's corner) and down (block 2's), with the
        // same pushes.
        const std::vector<BlockContactFrame> marks = sim->frame().blockContacts;
        QCOMPARE(int(marks.size()), 2);
        for (size_t i = 0; i < marks.size(); ++i) {
            const BlockContactFrame& c = marks[i];
            QVERIFY((c.block == 0 && c.other == 2) || (c.block == 2 && c.other == 0));
            const Vec2 corner = ladder.cornerWorld(sim->world(), c.block, c.corner);
            QVERIFY((c.point - corner).norm() < 1e-12);
            QVERIFY(std::abs(std::abs(c.normal.y()) - 1) < 1e-9);
            QVERIFY(c.normal.y() * (c.block == 0 ? 1 : -1) > 0);
            QVERIFY(std::abs(c.push - p[Eigen::Index(i)]) < 1e-12);
        }
    }

    // A push at t = 0 sets block 0 spinning as it falls: one corner lands
    // first. Plastic, frictionless, the block otherwise free, the impulse
    // along the face's normal n at arm r from the centre is
    //     P = -(v + w perp(r)) . n / (1/m + (r x n)^2 / I),
    // and v+ = v + P n / m, w+ = w + P (r x n) / I.
    void aCornerLandingIsARigidBodyImpact() {
        auto sim = simulate(dropScene("  - {at: 0, push: {block: 0, point: [0, 0.02], impulse: [0, 0.0006]}}\n",
                                      "{block_contact: on, event_tolerance: 1e-12}"));
        QVERIFY(sim);
        const Ladder& ladder = *sim->ladder();
        const PartId block = ladder.block(0);
        const double m = sim->world().part(block).mass, inertia = sim->world().part(block).inertia;
        const Twist start = sim->world().partVelocity(block);
        QVERIFY(std::abs(start.angular) > 1);
        Event touch;
        std::vector<Event> instant;
        QVERIFY(stepUntil(*sim, EventKind::Touch, 0.5, &touch, &instant));
        // Only one corner: the impact is that corner's alone.
        int touches = 0;
        for (const Event& e : instant) touches += e.kind == EventKind::Touch;
        QCOMPARE(touches, 1);
        const World& w = sim->world();
        const Contact& c = w.contacts().at(0);
        QCOMPARE(c.cornerPart, block);
        const Vec2 n = rotate(w.partPose(c.facePart).angle, c.normal);
        const Vec2 r = w.pointPosition(block, c.corner) - w.partPose(block).position;
        // Before: free flight since t = 0.
        const Vec2 v0 = start.linear + Vec2(0, -kG) * touch.time;
        const double w0 = start.angular;
        const double approach = (v0 + w0 * perp(r)).dot(n);
        QVERIFY(approach < -0.1);
        const double P = -approach / (1 / m + cross(r, n) * cross(r, n) / inertia);
        const Twist after = w.partVelocity(block);
        const Vec2 v1 = v0 + P * n / m;
        const double w1 = w0 + P * cross(r, n) / inertia;
        qInfo("P = %.9g N s; v+ = (%.9g, %.9g) m/s, w+ = %.9g rad/s; engine (%.9g, %.9g), %.9g", P, v1.x(), v1.y(), w1,
              after.linear.x(), after.linear.y(), after.angular);
        QVERIFY((after.linear - v1).norm() < 1e-9 * v1.norm() + 1e-12);
        QVERIFY(std::abs(after.angular - w1) < 1e-9 * std::abs(w1));
        // The corner's normal speed is zero after a plastic impact.
        QVERIFY(std::abs((after.linear + after.angular * perp(r)).dot(n)) < 1e-12);
        // The loss booked is the energy of the jump, P^2 / (2 K).
        const double lossByHand = 0.5 * P * P * (1 / m + cross(r, n) * cross(r, n) / inertia);
        qInfo("loss %.12g J, by hand %.12g J", sim->frame().energy.impactLoss, lossByHand);
        QVERIFY(std::abs(sim->frame().energy.impactLoss - lossByHand) < 1e-9 * lossByHand);
    }

    // With restitution e = 0.5 the flat drop bounces: landed at t0 =
    // sqrt(2 h / g) at v0 = g t0, it leaves at e^k v0 after the k-th close
    // and is in the air for r_k = 2 e^k v0 / g = t0 / 2^(k-1). The rebounds
    // shrink, and the first close that ends one shorter than the Zeno time
    // t_Z = 0.0125 sqrt(L / g) (0.978 ms) and than the one before is the
    // sequence's limit (docs/model.md section 8.6): r_8 = 0.796 ms, at
    // t0 (3 - 2^-7). Held there, it does not bounce: it rests on block 2.
    void aBounceIsHeldAtItsZenoLimit() {
        std::string yaml = dropScene("", "{block_contact: on, event_tolerance: 1e-12}");
        yaml.replace(yaml.find("  held: [1, 2]\n"), 15, "  held: [1, 2]\n  hinges: {restitution: 0.5}\n");
        auto sim = simulate(yaml);
        QVERIFY(sim);
        const double h = 0.050911688245431419, t0 = std::sqrt(2 * h / kG);
        const double zeno = 0.0125 * std::sqrt(0.06 / kG);
        int k = 1;
        while (t0 / std::pow(2.0, k - 1) >= zeno) ++k;
        QCOMPARE(k, 8);
        const double heldAt = t0 * (3 - std::pow(2.0, 1 - k));
        std::vector<double> bounces, touches;
        const Run run = runUntil(*sim, 0.6, [&](const Frame& f) {
            for (const Event& e : f.events) {
                if (e.kind == EventKind::Bounce) bounces.push_back(e.time);
                if (e.kind == EventKind::Touch) touches.push_back(e.time);
            }
        });
        QVERIFY2(run.failure.empty(), run.failure.c_str());
        qInfo("%zu bounces, %zu touches, the last at %.12f s; by hand 16 and 18, held at %.12f s", bounces.size(),
              touches.size(), touches.back(), heldAt);
        QCOMPARE(int(bounces.size()), 2 * k);  // both landing corners, at closes 0 to 7
        QCOMPARE(int(touches.size()), 2 * (k + 1));
        QVERIFY(std::abs(touches.back() - heldAt) < 1e-10);
        QVERIFY(bounces.back() < heldAt - 1e-4);
        const World& w = sim->world();
        const double m = w.part(sim->ladder()->block(0)).mass;
        QVERIFY(w.partVelocity(sim->ladder()->block(0)).linear.norm() < 1e-9);
        QVERIFY(std::abs(sim->frame().energy.impactLoss - m * kG * h) < 1e-9 * m * kG * h);
        QVERIFY(run.worstBalance < 1e-9);
    }

    // Gravity tilted by 10 degrees: block 0 lands flat on block 2's face,
    // then slides down it without friction until a corner reaches the
    // face's end. While it slides nothing dissipates: the total energy
    // stays put to the integrator's error (RK4 at 0.1 ms), and no impact
    // is booked.
    void aFrictionlessSlideKeepsItsEnergy() {
        const double tilt = 10 * std::numbers::pi / 180;
        std::string gravity = "[";
        gravity.append(std::to_string(kG * std::sin(tilt))).append(", ").append(std::to_string(-kG * std::cos(tilt)));
        gravity.append("]");
        auto sim = simulate(dropScene("", "{block_contact: on, step: 1e-4}", gravity));
        QVERIFY(sim);
        Event touch;
        QVERIFY(stepUntil(*sim, EventKind::Touch, 0.5, &touch));
        runUntil(*sim, touch.time + 1e-3);
        QCOMPARE(int(sim->world().contacts().size()), 2);
        const double e0 = sim->frame().energy.total(), loss0 = sim->frame().energy.impactLoss;
        const double x0 = sim->world().partPose(sim->ladder()->block(0)).position.x();
        double worst = 0;
        double slid = 0;
        while (sim->time() < 0.6 && sim->stepOnce()) {
            bool parted = false;
            for (const Event& e : sim->frame().events) parted = parted || e.kind == EventKind::Part;
            if (parted) break;
            worst = std::max(worst, std::abs(sim->frame().energy.total() - e0));
            slid = sim->world().partPose(sim->ladder()->block(0)).position.x() - x0;
            QCOMPARE(sim->frame().energy.impactLoss, loss0);
        }
        qInfo("slid %.6g m, energy kept to %.3g J", slid, worst);
        QVERIFY(slid > 0.005);  // it did slide, downhill (+x)
        QVERIFY(worst < 1e-9);
        QVERIFY(deepestOverlap(*sim) < 1e-9);
    }

    // With the option off, the paper's model: block 0 falls through block 2.
    void theOptionOffLetsBlocksPassThrough() {
        auto sim = simulate(dropScene("", "{block_contact: off}"));
        QVERIFY(sim);
        runUntil(*sim, 0.12);
        QVERIFY(deepestOverlap(*sim) > 1e-3);
    }

    // Where no block strikes another, turning contact on changes nothing:
    // the same events at the same instants and the same final state, to
    // the last bit (a corner grazing a face at a hinge's instant leaves
    // that instant as it is, docs/model.md section 17.4).
    void contactChangesNothingWhereNoBlockStrikes_data() {
        QTest::addColumn<QString>("file");
        for (const char* f : {"classic.yaml", "back-and-forth.yaml", "heavy-middle.yaml", "two-ripples.yaml"})
            QTest::newRow(f) << QString(f);
    }
    void contactChangesNothingWhereNoBlockStrikes() {
        QFETCH(QString, file);
        std::vector<Event> events[2];
        Eigen::VectorXd q[2];
        for (int on = 0; on < 2; ++on) {
            SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/examples/" + file.toStdString());
            QVERIFY(load.scene);
            load.scene->solver.blockContact = on ? BlockContact::On : BlockContact::Off;
            auto sim = std::move(Simulation::build(*load.scene).simulation);
            QVERIFY(sim);
            const Run r = runUntil(*sim, 3.0, [&](const Frame& f) {
                for (const Event& e : f.events) events[on].push_back(e);
            });
            QVERIFY2(r.failure.empty(), r.failure.c_str());
            q[on] = sim->world().q;
        }
        QCOMPARE(events[1].size(), events[0].size());
        double apart = 0;
        for (size_t i = 0; i < events[0].size(); ++i) {
            QCOMPARE(events[1][i].text, events[0][i].text);
            apart = std::max(apart, std::abs(events[1][i].time - events[0][i].time));
        }
        qInfo("%zu events, at most %.3g s apart; final state %.3g apart", events[0].size(), apart,
              (q[1] - q[0]).cwiseAbs().maxCoeff());
        QCOMPARE(apart, 0.0);
        QVERIFY(q[1] == q[0]);
    }

    // A corner that reaches a face closing slower than v_min L while its
    // acceleration takes it away grazes the face: no impact. In the
    // complete example of docs/scene-format.md with contact on, block 3's
    // corner meets block 0's end at 0.8043 s; made a contact, its push
    // pulled at once and it parted, to be struck again 0.55 ns later at
    // 2e-10 m/s, over and over: 234,578 events by 0.805 s, where the run
    // stopped with its books running away.
    void aCornerGrazingAFaceIsNoImpact() {
        auto sim = formatPageExampleWithContact();
        QVERIFY(sim);
        int touches = 0;
        const Run r = runUntil(*sim, 1.0, [&](const Frame& f) {
            for (const Event& e : f.events) touches += e.kind == EventKind::Touch;
        });
        qInfo("to 1 s: %d strikes; books %.3g J", touches, r.worstBalance);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(touches < 100);
        QVERIFY(r.worstBalance < 2e-4 * energyScale(*sim));
    }

    // The complete example of docs/scene-format.md with contact on, its
    // whole 4 s. Blocks 0 to 3 wedge against the hand more than once, and
    // corners reach faces where a push moves next to nothing (the pins hold
    // them there). That lost its books (5.4e-4 J, 2.7x the bound): at
    // 1.7784 s block 3's corner 2, resting 4e-11 m inside block 0 where the
    // pins hold it, drew the narrowing to the step's start, the step was
    // taken whole again, and block 0's corner 3 was met 2.1 um inside
    // block 3 at its end; the contact pulled it out in the next step's
    // projection, through pins that magnify the depth, and the step's
    // interpolant read that jump as 4.5e-4 J of kinetic energy at the lock
    // it located 1.5 us later. A contact met inside now holds its corner
    // there, and a corner inside by more than the touch band at a step's
    // start is not located in the step (docs/model.md 17.2, 17.4).
    // At 0.8034 s block 3's corner 2 grazes block 0's side, and block 0's
    // corner 3 crosses block 3's side later in the same step. Taken whole
    // after the graze, the step met that corner only at its end, 69 um
    // inside, and blocks 0 and 3 sank 0.357 mm into each other; the step
    // is now located again from the graze (docs/model.md 17.4). At 1.8965 s
    // the two lie side by side with their ends flush, turned a hair about
    // the corners that meet: each far corner slid along the other's end
    // plane into its side, was made a contact on that end, which the pins
    // already hold, and the sides sank 0.051 mm into each other. A corner
    // now goes in through the face of the boxes' least overlap (their
    // separating axis, docs/model.md 17.1): 0.0027 mm.
    void theFormatPagesCompleteExampleKeepsItsBooksWithContact() {
        auto sim = formatPageExampleWithContact();
        QVERIFY(sim);
        double deepest = 0, when = 0;
        int events = 0, touches = 0;
        const Run r = runUntil(*sim, sim->scene().duration, [&](const Frame& f) {
            events += int(f.events.size());
            for (const Event& e : f.events) touches += e.kind == EventKind::Touch;
            const double d = deepestOverlap(*sim);
            if (d > deepest) deepest = d, when = sim->time();
        });
        const double scale = energyScale(*sim);
        qInfo("to %.1f s: %d events, %d strikes; deepest overlap %.3g mm at %.4f s; books %.3g J of %.3g J",
              sim->time(), events, touches, deepest * 1e3, when, r.worstBalance, scale);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QCOMPARE(sim->time(), sim->scene().duration);
        QVERIFY(r.worstBalance < 2e-4 * scale);
        QVERIFY(events < 1000);
        QVERIFY(deepest <= 0.05e-3);
    }

    // A scripted join pulls two corners together in an instant. Hinge 1
    // of a hanging 12-block ladder is cut at 0.05 s; at 0.075 s corner 3 of
    // block 1 is to be joined to corner 3 of the held block 0, which would
    // pull block 2 into block 0. The contacts meet a corner only as it
    // arrives at a face, so the join is refused, said in the log, and the
    // run goes on as without it (to 1e-12 m).
    void aJoinThatWouldPullABlockIntoAnotherIsRefused() {
        const std::string scene =
            "format: jacobs-ladder/1\n"
            "title: join\n"
            "ladder: {blocks: 12}\n"
            "solver: {block_contact: on}\n"
            "script:\n"
            "  - {at: 0.05, cut: {hinge: 1}}\n";
        auto joined = simulate(scene + "  - {at: 0.075, join: {block: 0, corner: 3, other: 1, other_corner: 3}}\n");
        auto plain = simulate(scene);
        QVERIFY(joined && plain);
        std::string said;
        const Run r = runUntil(*joined, 0.3, [&](const Frame& f) {
            for (const Event& e : f.events)
                if (e.text.find("join") != std::string::npos) said = e.text;
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        runUntil(*plain, 0.3);
        qInfo("%s", said.c_str());
        QVERIFY(said.find("is refused: the pull would pass through: corner 2 of block 0 would be") !=
                std::string::npos);
        QVERIFY(said.find("inside block 2") != std::string::npos);
        QCOMPARE(joined->time(), plain->time());
        double apart = 0;
        for (int i = 0; i < joined->blockCount(); ++i)
            apart = std::max(apart, (joined->world().partPose(joined->blockPart(i)).position -
                                     plain->world().partPose(plain->blockPart(i)).position)
                                        .norm());
        qInfo("block centres at 0.3 s at most %.3g m from the run without the join", apart);
        QVERIFY(apart < 1e-12);
    }

    // The ladder packs (docs/model.md section 17.3): in the wrong-way turn
    // with contact on, block 3 comes to lie along block 0 as hinge 2 folds
    // flat and hinge 3 locks straight, a dead point of the loop of blocks 0
    // to 3. Block 3's corner 3 strikes block 0 at 0.8995 s, and hinges 2
    // and 3 close at that same instant, in one impact; the pins are within
    // their tolerance after every step, the located instant's included
    // (1.6e-10 m when the strike stopped the hinges short of their limits).
    void theLadderPacksAtTheDeadPoint() {
        SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/examples/wrong-way.yaml");
        QVERIFY(load.scene);
        load.scene->solver.blockContact = BlockContact::On;
        auto sim = std::move(Simulation::build(*load.scene).simulation);
        QVERIFY(sim);
        double strike = -1;
        const Run r = runUntil(*sim, 0.95, [&](const Frame& f) {
            for (const Event& e : f.events)
                if (strike < 0 && e.kind == EventKind::Touch && e.time > 0.89 &&
                    e.text == "block 3 strikes block 0 (corner 3)")
                    strike = e.time;
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(strike > 0);
        const Event* fold2 = firstEvent(r.events, 2, EventKind::Fold, 0.89);
        const Event* lock3 = firstEvent(r.events, 3, EventKind::Lock, 0.89);
        QVERIFY(fold2 && lock3);
        qInfo("strike at %.9f s, hinge 2 folds at %.9f s, hinge 3 locks at %.9f s; pins within %.3g m", strike,
              fold2->time, lock3->time, r.worstResidual);
        QVERIFY(std::abs(strike - 0.8995) < 1e-4);
        QCOMPARE(fold2->time, strike);
        QCOMPARE(lock3->time, strike);
        QVERIFY(r.worstResidual <= 1e-10);
        QVERIFY(r.worstBalance < 2e-4 * energyScale(*sim));
    }

    // A resting contact that a change of structure leaves to the pins
    // alone parts (docs/model.md section 17.4). The wrong-way turn with
    // contact on and a fixed step of 1 ms: at 2.3869 s block 2 flips over
    // the far end of block 1 and block 3's corner 2, resting on block 0,
    // comes to lie on a line the pins hold (its share -3e-34). Kept, its
    // push was 1.2e17 N and the next step's projection failed; it leaves
    // block 0 at the flip's instant and the run goes on to its end.
    void aContactThePinsHoldByThemselvesParts() {
        SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/examples/wrong-way.yaml");
        QVERIFY(load.scene);
        load.scene->solver.blockContact = BlockContact::On;
        load.scene->solver.step = 1e-3;
        auto sim = std::move(Simulation::build(*load.scene).simulation);
        QVERIFY(sim);
        double leaves = -1;
        const Run r = runUntil(*sim, load.scene->duration, [&](const Frame& f) {
            for (const Event& e : f.events)
                if (leaves < 0 && e.time > 2.38 && e.text == "block 3 leaves block 0 (corner 2)") leaves = e.time;
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        const Event* flip = firstEvent(r.events, 2, EventKind::FlipFlop, 2.38);
        QVERIFY(flip);
        qInfo("block 2 flips at %.9f s, block 3 leaves block 0 at %.9f s; books %.3g J", flip->time, leaves,
              r.worstBalance);
        QCOMPARE(leaves, flip->time);
        QVERIFY(r.worstBalance < 2e-4 * energyScale(*sim));
    }

    // Every example: no two blocks that are not neighbours inside each
    // other by more than 0.05 mm after any step, and the books balanced as
    // the examples' own tests ask with contact off. The wrong-way
    // turn wedges blocks 0 and 3 against the hand near 0.90 s, each block's
    // corner on the other's plane with their ends flush: until a corner
    // was judged by the face it came through, it sank into block 0 with a
    // gap of zero all the way in (0.3 mm after a step) and the books missed
    // 2.5e-4 J.
    void noExampleHasBlocksInsideEachOther_data() {
        QTest::addColumn<QString>("file");
        for (const auto& entry : std::filesystem::directory_iterator(std::string(JL_SOURCE_DIR) + "/examples"))
            if (entry.path().extension() == ".yaml")
                QTest::newRow(entry.path().filename().string().c_str())
                    << QString::fromStdString(entry.path().filename().string());
    }
    void noExampleHasBlocksInsideEachOther() {
        QFETCH(QString, file);
        // Contact between blocks is on by default; on here whatever an
        // example may say.
        SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/examples/" + file.toStdString());
        QVERIFY(load.scene);
        load.scene->solver.blockContact = BlockContact::On;
        auto sim = std::move(Simulation::build(*load.scene).simulation);
        QVERIFY(sim);
        if (!sim->ladder()) return;
        double deepest = 0, when = 0;
        const Run r = runUntil(*sim, sim->scene().duration, [&](const Frame&) {
            const double d = deepestOverlap(*sim);
            if (d > deepest) deepest = d, when = sim->time();
        });
        const double scale = energyScale(*sim);
        qInfo("%s: deepest overlap %.3g mm at %.4f s; books %.3g J of %.3g J; pins %.3g m", qPrintable(file),
              deepest * 1e3, when, r.worstBalance, scale, r.worstResidual);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(r.worstBalance < 2e-4 * scale);
        QVERIFY(deepest <= 0.05e-3);
    }

    // The design map's 12-block row (docs/ripple-reach.md, "The map with
    // solid blocks"), each cell run for its whole time with contact on: no
    // two blocks inside each other by more than 0.05 mm after any step, the
    // books balanced as the examples' are. Without contact the bottom block
    // swings through block 8 in the two cells whose answers contact changes
    // (8 and 10 mm: 2.3 and 5.2 mm deep), and 0.3 mm into block 9 at 7 mm.
    void noDesignOfTwelveBlocksHasBlocksInsideEachOther_data() {
        QTest::addColumn<int>("millimetres");
        for (int t = 1; t <= 15; ++t) QTest::newRow(qPrintable(QString("%1 mm").arg(t))) << t;
    }
    void noDesignOfTwelveBlocksHasBlocksInsideEachOther() {
        QFETCH(int, millimetres);
        struct Deepest {
            double overlap = 0, scale = 0;
            Run run;
        };
        const auto deepestOf = [&](BlockContact contact) {
            Scene s = turnedLadder(12, 1e-3 * millimetres);
            s.solver.blockContact = contact;
            auto sim = std::move(Simulation::build(s).simulation);
            Deepest d;
            d.run = runUntil(*sim, rippleRunTime(s),
                             [&](const Frame&) { d.overlap = std::max(d.overlap, deepestOverlap(*sim)); });
            d.scale = energyScale(*sim);
            return d;
        };
        const Deepest solid = deepestOf(BlockContact::On), through = deepestOf(BlockContact::Off);
        qInfo("deepest overlap %.3g mm with contact, %.3g mm without; books %.3g J of %.3g J", solid.overlap * 1e3,
              through.overlap * 1e3, solid.run.worstBalance, solid.scale);
        QVERIFY2(solid.run.failure.empty(), solid.run.failure.c_str());
        QVERIFY(solid.run.worstBalance < 2e-4 * solid.scale);
        QVERIFY(solid.overlap <= 0.05e-3);
        if (millimetres == 8 || millimetres == 10) QVERIFY(through.overlap > 1e-3);
    }
};

QTEST_GUILESS_MAIN(BlockContactTest)
#include "test_block_contact.moc"
