// labels: physics;reference
// The engine's hinge events against an independent implementation of the
// same model (core/reference/reduced_ladder*.cpp: reduced coordinates, a
// dense mass matrix, RK4 and event location of its own; docs/model.md
// sections 14.8 and 15): every event in the same order, same hinge and
// kind, within 1e-6 s. The reference is first checked on its own against
// known answers: the hanging equilibrium and the energy books.
#include "jl/reference/reduced_ladder.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

using namespace jl;
using namespace jl::test;

namespace {

// The engine tight enough that its event times are good to well below the
// 1e-6 s compared (Dormand-Prince at 1e-12, events to 1e-12 s).
Scene tightScene(const std::string& path) {
    SceneLoad load = loadScene(std::string(JL_SOURCE_DIR) + "/" + path);
    if (!load.scene) return {};
    Scene scene = *load.scene;
    // The paper's model, the one the reference implements: blocks that are
    // not neighbours pass through each other.
    scene.solver.blockContact = BlockContact::Off;
    scene.solver.integrator = Integrator::DormandPrince45;
    scene.solver.tolerance = 1e-12;
    scene.solver.eventTolerance = 1e-12;
    return scene;
}

// The 12-block, 60 x 6 mm ladder of docs/model.md section 15, turned over
// once: examples/two-ripples.yaml without its turn back.
Scene twelveThinBlocks() {
    Scene scene = tightScene("examples/two-ripples.yaml");
    if (scene.script.size() == 2) scene.script.pop_back();
    return scene;
}

EventKind engineKind(ReducedEvent::Kind k) {
    switch (k) {
        case ReducedEvent::Kind::Lock:
            return EventKind::Lock;
        case ReducedEvent::Kind::Unlock:
            return EventKind::Unlock;
        case ReducedEvent::Kind::Fold:
            return EventKind::Fold;
        case ReducedEvent::Kind::Unfold:
            return EventKind::Unfold;
        case ReducedEvent::Kind::FlipFlop:
            return EventKind::FlipFlop;
    }
    return EventKind::Script;
}

struct Agreement {
    std::string difference;  // empty when every event compared agrees
    int events = 0;
    double largest = 0;                      // s, the largest time difference of the events compared
    std::vector<int> firstFlips, reference;  // hinges by first flip: the engine's, the reference's
};

std::vector<int> firstFlips(const std::vector<ReducedEvent>& events) {
    std::vector<int> order;
    for (const ReducedEvent& e : events)
        if (e.kind == ReducedEvent::Kind::FlipFlop && std::find(order.begin(), order.end(), e.hinge) == order.end())
            order.push_back(e.hinge);
    return order;
}

// Both runs to `until`: the engine's hinge events against the reference's,
// one by one to `closeUntil`, to the first that differs in hinge, kind, or
// time by more than 1e-6 s; and the order in which hinges first flip over
// the whole run.
Agreement compareEvents(const Scene& scene, double until, double closeUntil) {
    Agreement a;
    auto sim = Simulation::build(scene).simulation;
    if (!sim) {
        a.difference = "the engine did not build the scene";
        return a;
    }
    const Run run = runUntil(*sim, until);
    ReducedLadder reference(scene);
    if (!run.failure.empty() || !reference.error().empty() || !reference.advanceTo(until)) {
        a.difference = "engine: " + run.failure + "; reference: " + reference.error();
        return a;
    }
    std::vector<Event> engine, engineClose;
    std::vector<ReducedEvent> mine, mineClose;
    for (const Event& e : run.events)
        if (e.time <= until) (e.time <= closeUntil ? engineClose : engine).push_back(e);
    for (const ReducedEvent& e : reference.events())
        if (e.time <= until) (e.time <= closeUntil ? mineClose : mine).push_back(e);
    a.firstFlips = firstFlipOrder(engineClose);
    a.reference = firstFlips(mineClose);
    for (int j : firstFlipOrder(engine))
        if (std::find(a.firstFlips.begin(), a.firstFlips.end(), j) == a.firstFlips.end()) a.firstFlips.push_back(j);
    for (int j : firstFlips(mine))
        if (std::find(a.reference.begin(), a.reference.end(), j) == a.reference.end()) a.reference.push_back(j);
    for (size_t i = 0; i < std::min(engineClose.size(), mineClose.size()); ++i) {
        const Event& e = engineClose[i];
        const ReducedEvent& r = mineClose[i];
        if (e.hinge != r.hinge || e.kind != engineKind(r.kind) || std::abs(e.time - r.time) > 1e-6) {
            a.difference = "event " + std::to_string(i) + ": engine " + toString(e.kind) + " of hinge " +
                           std::to_string(e.hinge) + " at " + std::to_string(e.time) + " s, reference " +
                           toString(r.kind) + " of hinge " + std::to_string(r.hinge) + " at " + std::to_string(r.time) +
                           " s";
            return a;
        }
        a.largest = std::max(a.largest, std::abs(e.time - r.time));
        ++a.events;
    }
    if (engineClose.size() != mineClose.size())
        a.difference = std::to_string(engineClose.size()) + " events in the engine, " +
                       std::to_string(mineClose.size()) + " in the reference";
    return a;
}

std::string listed(const std::vector<int>& hinges) {
    std::string s;
    for (int j : hinges) {
        if (!s.empty()) s += ' ';
        s += std::to_string(j);
    }
    return s;
}

// The comparison, said in the test's output.
Agreement compare(const char* name, const Scene& scene, double until, double closeUntil = -1) {
    if (closeUntil < 0) closeUntil = until;
    const Agreement a = compareEvents(scene, until, closeUntil);
    qInfo("%s to %.1f s: %d events to %.1f s agree, largest time difference %.2e s; hinges by first flip: %s", name,
          until, a.events, closeUntil, a.largest, listed(a.firstFlips).c_str());
    return a;
}

// How far the first ripple goes: hinges 1, 2, ..., k each flip, each after
// the one above it (docs/ripple-reach.md).
int rippleReach(const std::vector<int>& order) {
    int k = 0;
    for (int j : order)
        if (j == k + 1) ++k;
    return k;
}

}  // namespace

class ReducedLadderTest : public QObject {
    Q_OBJECT
private slots:
    // docs/model.md section 2.5: fold angles atan(T/L), then 2 atan(T/L).
    void hangsInTheEquilibrium() {
        const Scene scene = tightScene("examples/classic.yaml");
        const ReducedLadder reference(scene);
        QVERIFY2(reference.error().empty(), reference.error().c_str());
        QVERIFY(reference.events().empty());
        const double one = std::atan(0.012 / 0.06);
        QVERIFY(std::abs(reference.foldAngle(1) - one) < 1e-14);
        for (int j = 2; j < 6; ++j) QVERIFY(std::abs(reference.foldAngle(j) - 2 * one) < 1e-14);
    }

    // Once the hand stops (0.5 s) nothing works on the ladder: its energy
    // is constant between events and can only fall at one (plastic
    // impacts, docs/model.md section 12.3).
    void energyOnlyFallsAtEvents() {
        const Scene scene = tightScene("examples/classic.yaml");
        ReducedLadder reference(scene);
        QVERIFY(reference.advanceTo(0.5));
        double drift = 0, rise = 0, fall = 0;
        for (int i = 1; i <= 200; ++i) {
            const double before = reference.energy();
            const size_t events = reference.events().size();
            QVERIFY2(reference.advanceTo(0.5 + 0.01 * i), reference.error().c_str());
            const double change = reference.energy() - before;
            if (reference.events().size() == events)
                drift = std::max(drift, std::abs(change));
            else
                rise = std::max(rise, change), fall = std::min(fall, change);
        }
        qInfo(
            "energy from 0.5 s to 2.5 s: drift between events %.2e J, largest rise over events %.2e J, "
            "largest fall %.2e J",
            drift, rise, fall);
        QVERIFY(drift < 1e-12);
        QVERIFY(rise < 1e-12);
        QVERIFY(fall < -1e-6);  // the impacts do dissipate
    }

    // Every fold angle stays in 0 <= phi <= pi (docs/model.md section 7.1),
    // through the tangle at 0.96 s in heavy-middle.yaml where hinges 4 and 5
    // fold and flip within 0.2 ms of each other. Snapping hinge 4 by turning
    // block 4 alone left hinge 5 past pi, where it stayed for 84 ms.
    void foldAnglesStayAdmissible() {
        const Scene scene = tightScene("examples/heavy-middle.yaml");
        ReducedLadder reference(scene);
        double worst = 0;
        for (int i = 1; i <= 1200; ++i) {
            QVERIFY2(reference.advanceTo(0.001 * i), reference.error().c_str());
            for (int j = 1; j < scene.ladder->blocks; ++j) {
                const double phi = reference.foldAngle(j);
                worst = std::max({worst, -phi, phi - std::numbers::pi});
            }
        }
        qInfo("heavy-middle.yaml to 1.2 s: fold angles at most %.1e rad past a limit", worst);
        QVERIFY(worst < 1e-9);
    }

    void classicCascadeAgrees() {
        const Scene scene = tightScene("examples/classic.yaml");
        const Agreement a = compare("classic.yaml", scene, scene.duration);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
        QCOMPARE(a.firstFlips, (std::vector<int>{1, 2, 3, 4, 5}));
    }

    // To 3.4 s, the whole run `jladder reach` makes of a 12-block design
    // (1 + 0.2 N s; this design's reach is not settled before its end). Past it the two drift apart: 4e-13 s at the
    // first fold grows past 1e-6 s at 3.823 s, at a pace set by the engine's tolerance (docs/model.md section 14.8).
    void twelveBlockRippleAgrees() {
        const Scene scene = twelveThinBlocks();
        QCOMPARE(scene.script.size(), size_t(1));
        const Agreement a = compare("12 blocks, 60 x 6 mm", scene, 3.4);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
        QCOMPARE(a.firstFlips, (std::vector<int>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11}));
    }

    // The 25-block designs of docs/model.md section 15, run for 6 s as
    // `jladder reach --whole-runs` runs them (JL_SOAK=1; about a minute each): 60 x 4 mm
    // agrees event by event throughout and its first ripple flips 7 of 24
    // hinges; 60 x 3 mm agrees event by event to 1.5 s (past 2.1 s the two
    // drift apart by more than 1e-6 s, as the 12-block ladder does past
    // 3.8 s) and both flip 23 of 24, in the same order. The short form
    // compares the 4 mm ladder to 1 s.
    void twentyFiveBlockRipples() {
        Scene scene = tightScene("examples/classic.yaml");
        scene.ladder->blocks = 25;
        scene.ladder->block.thickness = 0.004;
        const bool soak = std::getenv("JL_SOAK") && std::string(std::getenv("JL_SOAK")) == "1";
        Agreement a = compare("25 blocks, 60 x 4 mm", scene, soak ? 6.0 : 1.0);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
        if (!soak) return;
        QCOMPARE(rippleReach(a.firstFlips), 7);
        scene.ladder->block.thickness = 0.003;
        a = compare("25 blocks, 60 x 3 mm", scene, 6.0, 1.5);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
        QCOMPARE(a.firstFlips, a.reference);
        QCOMPARE(rippleReach(a.firstFlips), 23);
    }

    // The same with 60 x 12 mm blocks (classic.yaml with 12 blocks): the
    // first ripple flips hinge 1 and dies (docs/model.md section 15); the
    // bottom block whips round over hinge 11.
    void twelveThickBlocksAgree() {
        Scene scene = tightScene("examples/classic.yaml");
        scene.ladder->blocks = 12;
        const Agreement a = compare("12 blocks, 60 x 12 mm", scene, 3.4);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
        QCOMPARE(a.firstFlips, (std::vector<int>{1, 11}));
    }

    // Turned the wrong way: hinge 2 folds and tips over its far end within
    // the impact (its near end's impulse would pull), which needs the
    // motion before the impact, not the angle rates (a flip-flop moves the
    // hinge, and the same rates then mean another motion).
    void wrongWayAgrees() {
        const Scene scene = tightScene("examples/wrong-way.yaml");
        const Agreement a = compare("wrong-way.yaml", scene, scene.duration);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
    }

    // The two ripples: contacts become held (docs/model.md section 8.6),
    // and the turn back runs a second ripple into the first.
    void twoRipplesAgree() {
        const Scene scene = tightScene("examples/two-ripples.yaml");
        const Agreement a = compare("two-ripples.yaml", scene, scene.duration);
        QVERIFY2(a.difference.empty(), a.difference.c_str());
    }
};

QTEST_GUILESS_MAIN(ReducedLadderTest)
#include "test_reduced_ladder.moc"
