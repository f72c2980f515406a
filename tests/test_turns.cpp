// labels: engine
// The batched cosine and sine of the bodies' turns (libmvec where glibc has
// it): as accurate as the scalar functions for what a turn is used for, and
// the same bits for the same angle wherever it sits in the list. Every
// routine the machine can run is checked, not only the one it chooses.
// turns.h is private to the engine (no other part calls it); the test
// reaches into the engine's sources by the repository root, which every
// test has on its include path.
#include "core/engine/turns.h"

#include <QtTest>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

using namespace jl;

class TestTurns : public QObject {
    Q_OBJECT
private slots:
    // The routines on offer: the scalar one always, libmvec's SSE2 one on
    // any x86-64 with libmvec, the AVX2 one where the processor has it;
    // cosSinOf runs the first.
    void theFirstRoutineIsTheOneUsed() {
        const std::vector<TurnRoutine>& routines = turnRoutines();
        QVERIFY(!routines.empty());
        QCOMPARE(QString(routines.back().name), QString("scalar"));
        for (const TurnRoutine& r : routines) qInfo("turn routine: %s", r.name);
        std::vector<double> values(11);
        for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.37 * double(i) - 1.9;
        std::vector<Eigen::Vector2d> used(values.size()), first(values.size());
        cosSinOf(values.data(), 1, values.size(), used.data());
        routines.front().run(values.data(), 1, values.size(), first.data());
        for (std::size_t i = 0; i < values.size(); ++i) QCOMPARE(used[i], first[i]);
    }

    // Against std::cos and std::sin, for every length of list up to three
    // quads and a tail, packed and at the stride of the world's (x, y, angle).
    void agreesWithTheScalarFunctions() {
        for (const TurnRoutine& routine : turnRoutines()) {
            std::mt19937_64 random(7);
            std::uniform_real_distribution<double> angle(-40.0, 40.0);
            double worst = 0;
            for (std::ptrdiff_t stride : {1, 3}) {
                for (std::size_t n = 0; n <= 13; ++n) {
                    std::vector<double> values(n * std::size_t(stride) + 1, -1.0);
                    for (std::size_t i = 0; i < n; ++i) values[i * std::size_t(stride)] = angle(random);
                    if (n > 2) {
                        values[0] = 0.0;
                        values[std::size_t(stride)] = M_PI;
                        values[2 * std::size_t(stride)] = -M_PI / 2;
                    }
                    std::vector<Eigen::Vector2d> out(n + 1, Eigen::Vector2d(7, 7));
                    routine.run(values.data(), stride, n, out.data());
                    for (std::size_t i = 0; i < n; ++i) {
                        const double a = values[i * std::size_t(stride)];
                        worst = std::max({worst, std::abs(out[i][0] - std::cos(a)), std::abs(out[i][1] - std::sin(a))});
                    }
                    QCOMPARE(out[n], Eigen::Vector2d(7, 7));  // nothing written past the end
                }
            }
            // libmvec promises 4 units in the last place; a turn of a 60 mm
            // block by 1e-15 rad moves its corner by 6e-17 m.
            QVERIFY2(worst <= 4 * std::numeric_limits<double>::epsilon(),
                     qPrintable(QString("%1: %2").arg(routine.name).arg(worst)));
        }
    }

    // One angle gets one answer: first, in a full quad, in the tail.
    void sameBitsWhereverTheAngleSits() {
        for (const TurnRoutine& routine : turnRoutines()) {
            const double a = 2.718281828459045;
            for (std::size_t n = 1; n <= 9; ++n) {
                for (std::size_t at = 0; at < n; ++at) {
                    std::vector<double> values(n, 0.25);
                    values[at] = a;
                    std::vector<Eigen::Vector2d> out(n);
                    routine.run(values.data(), 1, n, out.data());
                    Eigen::Vector2d alone;
                    routine.run(&a, 1, 1, &alone);
                    QCOMPARE(out[at][0], alone[0]);
                    QCOMPARE(out[at][1], alone[1]);
                }
            }
        }
    }
};

QTEST_APPLESS_MAIN(TestTurns)
#include "test_turns.moc"
