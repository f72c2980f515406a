// labels: physics;ladder
// The whole ladder (docs/model.md sections 8 and 14.7): the classic cascade,
// the wrong-way turn, the ladder left alone at rest, event times under step
// refinement, and a 1,000-block ladder turned over.
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>

using namespace jl;
using namespace jl::test;

namespace {

std::string ladderScene(int blocks, const char* turn, const char* extra = "") {
    return std::string("format: jacobs-ladder/1\nladder: {blocks: ") + std::to_string(blocks) + ", held: [0]}\n" +
           extra +
           (turn[0] ? std::string("script: [{at: 0.2, turn: {block: 0, by: ") + turn + ", duration: 0.3}}]\n"
                    : std::string());
}

// The classic cascade with every length times `s` and every time of the
// script times sqrt(s): the same motion in time scaled by sqrt(s) (lengths
// L, g fixed: the only time scale is sqrt(L / g)).
std::string scaledClassic(double s) {
    char text[512];
    const double r = std::sqrt(s);
    std::snprintf(
        text, sizeof text,
        "format: jacobs-ladder/1\n"
        "ladder: {blocks: 6, held: [0], block: {length: %.17g, thickness: %.17g, width: %.17g, density: 600}}\n"
        "script: [{at: %.17g, turn: {block: 0, by: 180deg, duration: %.17g}}]\n",
        0.06 * s, 0.012 * s, 0.045 * s, 0.2 * r, 0.3 * r);
    return text;
}

// How long hinge 4 stays locked the first time, in the scaled time t / sqrt(s).
double firstLockSpan(double s) {
    auto sim = simulate(scaledClassic(s));
    if (!sim) return -1;
    const Run r = runUntil(*sim, 0.55 * std::sqrt(s));
    double locked = -1;
    for (const Event& e : r.events) {
        if (e.hinge != 4) continue;
        if (e.kind == EventKind::Lock && locked < 0) locked = e.time;
        if (e.kind == EventKind::Unlock && locked >= 0) return (e.time - locked) / std::sqrt(s);
    }
    return -1;
}

double firstFoldTime(const std::string& yaml) {
    auto sim = simulate(yaml);
    if (!sim) return -1;
    const Run r = runUntil(*sim, 0.7);
    for (const Event& e : r.events)
        if (e.kind == EventKind::Fold && e.hinge == 1) return e.time;
    return -1;
}

}  // namespace

class CascadeTest : public QObject {
    Q_OBJECT
private slots:
    // The contact tests scale with the ladder (docs/model.md section 8.4):
    // the classic cascade from 0.6 mm to 3 m blocks keeps hinge 4's first
    // lock for the same scaled time. With absolute thresholds (1e-9 N,
    // 1e-9 N s, 1e-9 rad/s) the 0.6 mm ladder held it 1.6e-4 scaled seconds
    // too long.
    void contactTestsScaleWithTheLadder() {
        const double reference = firstLockSpan(1.0);
        QVERIFY(reference > 0.02 && reference < 0.04);
        for (double s : {0.01, 0.05, 10.0, 50.0}) {
            const double span = firstLockSpan(s);
            QVERIFY2(
                std::abs(span - reference) < 6e-5,
                qPrintable(QString("scale %1: locked %2 (scaled s), full size %3").arg(s).arg(span).arg(reference)));
        }
    }

    // Turned the right way, every hinge folds and flips, top to bottom, the
    // first ones about 0.13 s apart (the independent reference's figure).
    void classicCascadeFlipsEveryHingeInOrder() {
        auto sim = simulateFile("examples/classic.yaml");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 2.5);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QCOMPARE(firstFlipOrder(r.events), (std::vector<int>{1, 2, 3, 4, 5}));
        std::vector<double> at;
        for (const Event& e : r.events)
            if (e.kind == EventKind::FlipFlop && int(at.size()) < e.hinge) at.push_back(e.time);
        QVERIFY2(at[1] - at[0] > 0.10 && at[1] - at[0] < 0.17, qPrintable(QString::number(at[1] - at[0])));
        QVERIFY2(at[2] - at[1] > 0.10 && at[2] - at[1] < 0.17, qPrintable(QString::number(at[2] - at[1])));
        // Every flip was preceded by the fold of the same hinge.
        for (size_t i = 0; i < r.events.size(); ++i)
            if (r.events[i].kind == EventKind::FlipFlop) {
                bool folded = false;
                for (size_t k = 0; k < i; ++k)
                    folded = folded || (r.events[k].hinge == r.events[i].hinge && r.events[k].kind == EventKind::Fold);
                QVERIFY(folded);
            }
        QVERIFY2(r.worstBalance < 1e-6, qPrintable(QString::number(r.worstBalance)));
        QVERIFY(r.worstResidual <= 1e-10 * 1.0000001);
        QVERIFY(r.impactLossNeverFell);
    }

    // Turned the other way, block 1 is pressed end to end: hinge 1 locks
    // first and never flips; there is no ripple.
    void wrongWayLocksHingeOneAndMakesNoRipple() {
        auto sim = simulateFile("examples/wrong-way.yaml");
        QVERIFY(sim);
        const Run r = runUntil(*sim, 2.5);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(!r.events.empty());
        QCOMPARE(r.events[0].kind, EventKind::Lock);
        QCOMPARE(r.events[0].hinge, 1);
        const std::vector<int> order = firstFlipOrder(r.events);
        QVERIFY(std::find(order.begin(), order.end(), 1) == order.end());
        QVERIFY2(r.worstBalance < 1e-5, qPrintable(QString::number(r.worstBalance)));
    }

    // The default ladder starts in the equilibrium the engine computed:
    // left alone for 10 s nothing moves and no event creeps in.
    void restingLadderStaysPutForTenSeconds() {
        auto sim = simulate(ladderScene(6, ""));
        QVERIFY(sim);
        const Frame start = sim->frame();
        QVERIFY(start.events.empty());
        // Fold angles as docs/model.md section 2.5 gives them for equal blocks.
        const double a = std::atan(0.012 / 0.06);
        QVERIFY(std::abs(start.hinges[0].foldAngle - a) < 1e-12);
        for (size_t j = 1; j < start.hinges.size(); ++j) QVERIFY(std::abs(start.hinges[j].foldAngle - 2 * a) < 1e-12);
        const Run r = runUntil(*sim, 10.0);
        QVERIFY(r.events.empty());
        const Frame end = sim->frame();
        double moved = 0;
        for (size_t i = 0; i < end.poses.size(); ++i)
            moved = std::max(moved, (end.poses[i].position - start.poses[i].position).norm());
        QVERIFY2(moved < 1e-9, qPrintable(QString::number(moved)));
    }

    // Located events converge with the integrator as the step shrinks; the
    // paper's end-of-step policy is late by up to one step.
    void eventTimesConvergeAsTheStepShrinks() {
        const std::string reference = ladderScene(6, "180deg", "solver: {integrator: rk4, step: 6.25e-5}\n");
        const double t0 = firstFoldTime(reference);
        QVERIFY(t0 > 0);
        std::vector<double> errors;
        for (const char* h : {"4e-3", "2e-3", "1e-3"}) {
            const double t = firstFoldTime(
                ladderScene(6, "180deg", (std::string("solver: {integrator: rk4, step: ") + h + "}\n").c_str()));
            errors.push_back(std::abs(t - t0));
            qInfo("step %s s: first fold at %.9f s, error %.2e s", h, t, errors.back());
        }
        QVERIFY(errors[2] < errors[0]);
        const double order = std::log2(errors[0] / errors[2]) / 2;
        qInfo("observed order of the event time: %.2f", order);
        QVERIFY2(order > 2.5, qPrintable(QString::number(order)));
        QVERIFY(errors[2] < 1e-6);
        const double late =
            firstFoldTime(ladderScene(6, "180deg", "solver: {integrator: rk4, step: 1e-3, events: end_of_step}\n")) -
            t0;
        qInfo("end of step: %.2e s late", late);
        QVERIFY2(late >= 0 && late <= 1e-3 + 1e-6, qPrintable(QString::number(late)));
    }

    // A 1,000-block ladder turned over: no failure, the pins closed to the
    // projection tolerance after every step and event.
    void thousandBlockLadderTurnedOver() {
        auto sim = simulate(ladderScene(1000, "180deg", "solver: {integrator: rk4, step: 2.5e-4}\n"));
        QVERIFY(sim);
        const Run r = runUntil(*sim, 0.6);
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QVERIFY(r.worstResidual <= 1e-10 * 1.0000001);
        QVERIFY(!r.events.empty());
        // The books balance to a millionth of the ladder's potential energy
        // (5.7 kJ below the origin: 1,000 blocks hang 60 m deep).
        const double scale = std::abs(sim->frame().energy.initial);
        QVERIFY2(r.worstBalance < 1e-5 * scale, qPrintable(QString("%1 of %2 J").arg(r.worstBalance).arg(scale)));
    }
};

QTEST_GUILESS_MAIN(CascadeTest)
#include "test_cascade.moc"
