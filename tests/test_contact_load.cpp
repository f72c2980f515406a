// labels: physics;ladder
// How small counts as zero for a hinge contact that holds up a long or
// heavy ladder (docs/model.md section 8.3). The known answer is a
// cantilever: block 0 held lying flat, block 1 locked end to end with it,
// and every other block hanging at rest from block 1's far end. Moments
// about hinge 1: N T = m g L / 2 + M g L, with M the mass hanging below.
// The contact's computed force carries rounding in proportion to that
// load; the threshold that decides whether it pulls must stay above it.
#include "jl/engine/dynamics.h"
#include "jl/ladder/ladder.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <cmath>
#include <numbers>
#include <sstream>
#include <string>

using namespace jl;
using namespace jl::test;

namespace {

constexpr double L = 0.06, T = 0.012, W = 0.045, kDensity = 600, g = 9.81;
constexpr double m = L * T * W * kDensity;

// n blocks; the last one of mass `last` kg (0: like the others).
std::string cantilever(int n, double last, const char* tail) {
    std::ostringstream s;
    s.precision(17);
    s << "format: jacobs-ladder/1\nsolver: {still_tail: " << tail << "}\nladder:\n  blocks: " << n << "\n";
    if (last > 0) s << "  overrides:\n    - {index: " << n - 1 << ", mass: " << last << "}\n";
    // Block 2 hangs from block 1's far end with its diagonal vertical, the
    // ones below it as in the hanging ladder (section 2.5).
    s << "  held: [0]\n  initial:\n    kind: fold_angles\n"
         "    poses: [{block: 0, position: [0, 0], angle: -90deg}]\n    fold_angles: [0";
    for (int j = 2; j < n; ++j) s << ", " << (j == 2 ? std::numbers::pi / 2 + std::atan(T / L) : 2 * std::atan(T / L));
    s << "]\n";
    return s.str();
}

struct Measured {
    double force = 0, exact = 0, threshold = 0, kinetic = 0;
};

Measured measure(int n, double last, const char* tail) {
    auto sim = simulate(cantilever(n, last, tail));
    if (!sim) return {};
    runUntil(*sim, 0.01);  // the lock is made in the first step
    World w = sim->world();
    Dynamics d;
    d.evaluate(w, sim->time());
    const Ladder& ladder = *sim->ladder();
    const HingeContact c = ladder.contact(w, d, 1);
    const double hanging = (n - 2) * m + (last > 0 ? last - m : 0);
    return {c.normal, (m * g * L / 2 + hanging * g * L) / T, ladder.pullThreshold(c, false),
            sim->frame().energy.kinetic};
}

}  // namespace

class ContactLoadTest : public QObject {
    Q_OBJECT
private slots:
    void theThresholdStandsAboveTheRoundingOfTheLoad_data() {
        QTest::addColumn<int>("blocks");
        QTest::addColumn<double>("last");
        QTest::addColumn<QString>("tail");
        // Before the threshold followed the load, the 10,000-block force was
        // off by 12 times it, and with a 1 mg last block (whose weight set
        // it) 100 blocks by 8 to 12 times and 1,000 by 810 to 3,500 times.
        for (const char* tail : {"separate", "joined"}) {
            QTest::addRow("12 blocks, %s", tail) << 12 << 0.0 << QString(tail);
            QTest::addRow("10000 blocks, %s", tail) << 10000 << 0.0 << QString(tail);
            QTest::addRow("100 blocks, 1 mg last, %s", tail) << 100 << 1e-6 << QString(tail);
            QTest::addRow("1000 blocks, 1 mg last, %s", tail) << 1000 << 1e-6 << QString(tail);
        }
    }
    void theThresholdStandsAboveTheRoundingOfTheLoad() {
        QFETCH(int, blocks);
        QFETCH(double, last);
        QFETCH(QString, tail);
        const Measured r = measure(blocks, last, tail.toUtf8().constData());
        const QString said = QString("N %1, exact %2, off by %3, threshold %4")
                                 .arg(r.force, 0, 'g', 17)
                                 .arg(r.exact, 0, 'g', 17)
                                 .arg(r.force - r.exact)
                                 .arg(r.threshold);
        QVERIFY2(r.kinetic < 1e-20 * r.exact, qPrintable(QString("not at rest: %1 J").arg(r.kinetic)));
        QVERIFY2(std::abs(r.force / r.exact - 1) < 1e-11, qPrintable(said));
        // A tenth: the rounding must not decide whether a contact pulls.
        QVERIFY2(std::abs(r.force - r.exact) < r.threshold / 10, qPrintable(said));
        // And the threshold is still far below anything physical.
        QVERIFY2(r.threshold < 1e-7 * r.exact, qPrintable(said));
    }
};

QTEST_GUILESS_MAIN(ContactLoadTest)
#include "test_contact_load.moc"
