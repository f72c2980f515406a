// labels: physics;ladder
// No chattering (docs/model.md section 8.6): the slow-release rule, contacts
// held at the accumulation point of a Zeno sequence, and how a held contact
// opens again (its force crossing zero, the hand stopping, a push). Blocks
// are 60 x 12 x 45 mm, density 600.
#include "jl/ladder/ladder.h"
#include "tests/example_claims.h"
#include "tests/ladder_scenes.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <map>
#include <string>

using namespace jl;
using namespace jl::test;

namespace {

// 12 blocks 60 x 12 mm from the hanging equilibrium, block 0 turned +180
// degrees over 0.3 s at 0.2 s, integrated to 1e-12 with events located to
// 1e-12 s: `more` adds to the script.
std::unique_ptr<Simulation> twelveBlocksTurned(const std::string& more = {}) {
    return simulate(
        "format: jacobs-ladder/1\n"
        "solver: {integrator: dormand_prince45, tolerance: 1e-12, event_tolerance: 1e-12}\n"
        "ladder: {blocks: 12, held: [0]}\n"
        "script:\n"
        "  - {at: 0.2, turn: {block: 0, by: 180deg, duration: 0.3}}\n" +
        more);
}

// The cantilever of flatHeldBlock(1.4, "90deg") bouncing with restitution 0.5.
std::string bouncingCantilever() {
    std::string yaml = flatHeldBlock(1.4, "90deg");
    const std::string held = "  held: [0]\n";
    yaml.insert(yaml.find(held) + held.size(), "  hinges: {restitution: 0.5}\n");
    return yaml;
}

}  // namespace

class NoChatteringTest : public QObject {
    Q_OBJECT
private slots:
    // No chattering (docs/model.md, "No chattering"): impacts that would
    // part a pair slower than v_min keep it locked (the slow-release rule), and a contact
    // that closes again within the Zeno time of its release twice in a row
    // is held, so no hinge goes through more than three quick cycles (a
    // release and a close within 1 ms) in a row. Before locks were located
    // exactly and contacts held, the heavy-middle ladder without the slow-release rule made
    // about 490 quick cycles in 2.5 s, and the 12-block, 12 mm ladder
    // 1,400 within 20 ms. The books balance either way (RK4 at 0.25 ms: at
    // 1 ms the heavy block's swing near 1.8 s costs 1e-4 J of integration
    // error, events or not).
    void noHingeChattersMoreThanThreeTimesInARow_data() {
        QTest::addColumn<QString>("ladder");
        QTest::addColumn<double>("until");
        QTest::newRow("heavy middle, v_min = 1e-4 rad/s")
            << "{blocks: 6, hinges: {min_rebound_speed: 1e-4}, overrides: [{index: 3, mass: 0.2}], held: [0]}" << 2.5;
        QTest::newRow("heavy middle, v_min = 0")
            << "{blocks: 6, hinges: {min_rebound_speed: 0}, overrides: [{index: 3, mass: 0.2}], held: [0]}" << 2.5;
        QTest::newRow("12 blocks, 60 x 12 mm") << "{blocks: 12, held: [0]}" << 2.0;
        QTest::newRow("50 blocks, 60 x 3 mm") << "{blocks: 50, block: {thickness: 0.003}, held: [0]}" << 2.0;
    }
    void noHingeChattersMoreThanThreeTimesInARow() {
        QFETCH(QString, ladder);
        QFETCH(double, until);
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "solver: {step: 2.5e-4}\n"
            "ladder: " +
            ladder.toStdString() +
            "\n"
            "script: [{at: 0.2, turn: {block: 0, by: 180deg, duration: 0.3}}]\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, until);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        const Chatter c = chatter(r.events);
        qInfo("%zu events, %d quick cycles, at most %d of one hinge in a row", r.events.size(), c.cycles, c.longest);
        QVERIFY2(c.longest <= 3, qPrintable(QString::number(c.longest)));
        QVERIFY2(r.worstBalance < 1e-6, qPrintable(QString::number(r.worstBalance)));
    }

    // A contact held at the accumulation point of a Zeno sequence is an
    // ordinary closed contact otherwise: it opens where its force crosses
    // zero, located like any event. Hinges 8 and 11 of the turned 12-block
    // ladder trade impacts with shrinking rebounds (11 open 14.6 ms, 8 open
    // 0.87 ms, 11 open 0.125 ms) and are held from 0.90936 s; their contact
    // forces, followed step by step, cross zero at 0.929555 s and 0.948007 s.
    void aHeldContactOpensWhereItsForceCrossesZero() {
        auto sim = twelveBlocksTurned();
        QVERIFY(sim);
        bool heldBoth = false;
        const Run r = runUntil(*sim, 0.96, [&](const Frame& f) {
            if (f.time > 0.91 && f.time < 0.92)
                heldBoth = sim->ladder()->hinge(8).held && sim->ladder()->hinge(11).held;
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        const Event* lock8 = firstEvent(r.events, 8, EventKind::Lock, 0.909);
        const Event* lock11 = firstEvent(r.events, 11, EventKind::Lock, 0.909);
        QVERIFY(lock8 && lock11);
        QVERIFY2(std::abs(lock8->time - 0.909235) < 1e-6, qPrintable(QString::number(lock8->time, 'g', 12)));
        QVERIFY2(std::abs(lock11->time - 0.90936) < 1e-6, qPrintable(QString::number(lock11->time, 'g', 12)));
        QVERIFY(heldBoth);
        const Event* open8 = firstEvent(r.events, 8, EventKind::Unlock, lock11->time);
        const Event* open11 = firstEvent(r.events, 11, EventKind::Unlock, lock11->time);
        QVERIFY(open8 && open11);
        qInfo("hinge 8 opens at %.9f s, hinge 11 at %.9f s", open8->time, open11->time);
        QVERIFY2(std::abs(open8->time - 0.929555) < 1e-6, qPrintable(QString::number(open8->time, 'g', 12)));
        QVERIFY2(std::abs(open11->time - 0.948007) < 1e-6, qPrintable(QString::number(open11->time, 'g', 12)));
        for (const Event& e : r.events)  // closed from the hold to the opening
            QVERIFY(!((e.hinge == 8 && e.time > lock11->time && e.time < open8->time) ||
                      (e.hinge == 11 && e.time > lock11->time && e.time < open11->time)));
    }

    // One quick close is not a Zeno sequence. Turned back (-180 degrees over
    // 0.3 s at 0.6 s), hinge 8 opens at 1.028724 s by its force and is
    // closed again 50 us later by the impact of hinge 1's lock, at
    // 1.0287735 s; that impact's impulse would pull it, so it opens again at
    // that instant.
    void oneQuickCloseIsNotHeld() {
        auto sim = twelveBlocksTurned("  - {at: 0.6, turn: {block: 0, by: -180deg, duration: 0.3}}\n");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 1.04);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        const Event* lock1 = firstEvent(r.events, 1, EventKind::Lock, 1.028);
        QVERIFY(lock1);
        QVERIFY2(std::abs(lock1->time - 1.0287735) < 1e-6, qPrintable(QString::number(lock1->time, 'g', 12)));
        const Event* open8 = firstEvent(r.events, 8, EventKind::Unlock, lock1->time);
        QVERIFY(open8);
        qInfo("hinge 1 locks at %.9f s, hinge 8 opens at %.9f s", lock1->time, open8->time);
        QVERIFY2(std::abs(open8->time - 1.0287735) < 1e-6, qPrintable(QString::number(open8->time, 'g', 12)));
    }

    // Restitution 0.5: the cantilever bounces with rebounds halving (97 ms,
    // 49 ms, ...) until one lasts less than the Zeno time (0.77 ms, after
    // 1.54 ms): from there it is held, locked. The hand-worked unlock when
    // the hand stops (docs/model.md section 14.5) is at 1.5 s all the same;
    // and the upward push at 0.95 s, which would pull the contact, opens it.
    void aHeldCantileverUnlocksWhenTheHandStops() {
        auto sim = simulate(bouncingCantilever());
        QVERIFY(sim);
        bool held = false;
        const Run r = runUntil(*sim, 1.6, [&](const Frame& f) {
            if (f.time > 0.9 && f.time < 1.4) held = held || sim->ladder()->hinge(1).held;
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(held);
        const Event* open = firstEvent(r.events, 1, EventKind::Unlock, 0.9);
        QVERIFY(open);
        QVERIFY2(std::abs(open->time - 1.5) < 1e-9, qPrintable(QString::number(open->time, 'g', 12)));
        QVERIFY2(r.worstBalance < 1e-8, qPrintable(QString::number(r.worstBalance)));
    }
    void aPushOpensAHeldContact() {
        auto sim =
            simulate(bouncingCantilever() + "  - {at: 0.95, push: {block: 1, impulse: [0, 0.001], point: [0, 0]}}\n");
        QVERIFY(sim);
        bool held = false;
        const Run r = runUntil(*sim, 0.95, [&](const Frame& f) {
            if (f.time < 0.95) held = sim->ladder()->hinge(1).held;
        });
        QVERIFY(std::abs(sim->time() - 0.95) < 1e-12);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(held);  // up to the push
        const Event* open = firstEvent(r.events, 1, EventKind::Unlock, 0.9);
        QVERIFY(open);
        QCOMPARE(open->time, 0.95);
        QVERIFY(sim->ladder()->foldRate(sim->world(), 1) > 0);  // opening
    }

    // The contacts between blocks too (docs/model.md section 17.6): a
    // corner parted inside a face (held where it was met) keeps the gap it
    // parted at as its zero until a state the run keeps finds it clear, so
    // it does not strike the face again at once. The wrong-way turn of seven
    // blocks, contact on: with turns of 0.25, 0.32 and 0.35 s, block 0's
    // corner struck block 4 (or 3) and left it some 170,000 times, 0.95 ns
    // apart, while a step's end that an event then cut short found it clear
    // and forgot its zero. No corner may strike one block more than three
    // times in a row with less than 1 ms between, and the books balance as
    // the examples' do. The turn of 0.3 s missed that by 1.5e-4 J until a
    // step whose end nears RK4's stability limit was taken again (a
    // resting corner's push grows towards a dead point within the step,
    // docs/model.md section 17.7): now 3e-6 J.
    void noCornerStrikesABlockOverAndOver_data() {
        QTest::addColumn<double>("turn");
        for (double turn : {0.25, 0.3, 0.32, 0.35})
            QTest::newRow(qPrintable(QString("turn of %1 s").arg(turn))) << turn;
    }
    void noCornerStrikesABlockOverAndOver() {
        QFETCH(double, turn);
        auto sim = simulate(
            "format: jacobs-ladder/1\n"
            "solver: {block_contact: on}\n"
            "ladder: {blocks: 7, held: [0]}\n"
            "script: [{at: 0.2, turn: {block: 0, by: -180deg, duration: " +
            std::to_string(turn) + "}}]\n");
        QVERIFY(sim);
        std::map<std::string, std::pair<double, int>> last;  // strike: when, how many in a row
        int strikes = 0, longest = 0;
        const Run r = runUntil(*sim, 2.5, [&](const Frame& f) {
            for (const Event& e : f.events) {
                if (e.kind != EventKind::Touch) continue;
                ++strikes;
                auto [at, inRow] = last.contains(e.text) ? last[e.text] : std::pair{-1.0, 0};
                inRow = at >= 0 && e.time - at < 1e-3 ? inRow + 1 : 1;
                last[e.text] = {e.time, inRow};
                longest = std::max(longest, inRow);
            }
        });
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        const double scale = energyScale(*sim);
        qInfo("%d strikes, at most %d of one corner in a row; books %.3g J of %.3g J", strikes, longest, r.worstBalance,
              scale);
        QVERIFY2(longest <= 3, qPrintable(QString::number(longest)));
        QVERIFY(r.worstBalance < 2e-4 * scale);
    }
};

QTEST_GUILESS_MAIN(NoChatteringTest)
#include "test_no_chattering.moc"
