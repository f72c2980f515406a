// labels: ui;timing
// The real-time factor in the status bar is simulated time gained per
// second of the clock over the stretch it names (the last 2 s of playing):
// the estimator fed known times, and the window's label against the time
// on screen as this test sees it go by.
#include "playback_fixture.h"
#include "ui/play/rate_window.h"

#include <QLabel>
#include <QRegularExpression>

using namespace jl::test;

namespace {

// (wall s, simulated s) as this test saw the frame on screen change.
struct Seen {
    std::vector<std::pair<double, double>> samples;
    // The time on screen at wall time `w`, on the line between the two
    // samples around it.
    double simulatedAt(double w) const {
        auto after = std::lower_bound(samples.begin(), samples.end(), std::make_pair(w, -1e300));
        if (after == samples.begin()) return samples.front().second;
        if (after == samples.end()) return samples.back().second;
        const auto& [w0, s0] = *(after - 1);
        const auto& [w1, s1] = *after;
        return s0 + (w - w0) / (w1 - w0) * (s1 - s0);
    }
};

}  // namespace

class RealTimeFactorTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void aSteadyRateIsReadExactly() {
        RateWindow r;
        for (int i = 0; i <= 100; ++i) r.add(0.05 * i, 0.35 * 0.05 * i, 1000.0 * i);
        QCOMPARE(r.span(), RateWindow::kSpan);
        QVERIFY(std::abs(*r.simulatedPerSecond() - 0.35) < 1e-12);
        QVERIFY(std::abs(*r.stepsPerSecond() - 20000.0) < 1e-9);
    }

    // 1x for 3 s, then 0.25x for 1 s: over the last 2 s, (1 + 0.25) / 2.
    void aChangeCountsOverTheLastTwoSeconds() {
        RateWindow r;
        double simulated = 0;
        for (int i = 0; i <= 400; ++i) {
            r.add(0.01 * i, simulated, 0);
            simulated += i < 300 ? 0.01 : 0.0025;
        }
        QVERIFY(std::abs(*r.simulatedPerSecond() - 0.625) < 1e-12);
    }

    // Frames of a long ladder come seconds apart: the window's start is
    // read between the samples around it, not at the older one.
    void sparseSamplesStillSpanTwoSeconds() {
        RateWindow r;
        for (int i = 0; i <= 10; ++i) r.add(0.7 * i, 0.3 * 0.7 * i, 0);
        QCOMPARE(r.span(), RateWindow::kSpan);
        QVERIFY(std::abs(*r.simulatedPerSecond() - 0.3) < 1e-12);
    }

    // After a restart (Play, a seek) the time before is not counted, and a
    // stretch shorter than kShortest gives no rate at all.
    void aRestartForgetsTheTimeBefore() {
        RateWindow r;
        for (int i = 0; i <= 50; ++i) r.add(0.02 * i, 0.0, 0);  // paused: no time gained
        r.restart();
        r.add(1.0, 0.0, 0);
        r.add(1.2, 0.2, 0);
        QVERIFY(!r.simulatedPerSecond());
        r.add(1.5, 0.5, 0);
        QCOMPARE(r.span(), 0.5);
        QVERIFY(std::abs(*r.simulatedPerSecond() - 1.0) < 1e-12);
    }

    // A small ladder played from a pause at 1x, then at 0.5x: every factor
    // the status bar shows is within 10 % of the time gained on screen over
    // the stretch it names, as this test measured it.
    void theStatusBarSaysTheRateOnScreen() {
        jl::Scene scene = jl::test::swingingLadder();
        scene.duration = 30;
        Fixture f(scene);
        QVERIFY(QTest::qWaitForWindowExposed(&f.window));
        auto* label = f.window.findChild<QLabel*>("rate");
        QVERIFY(label);
        QTest::qWait(1000);  // paused a while: no part of the factor
        QElapsedTimer clock;
        clock.start();
        Seen seen;
        const auto see = [&] {
            const auto s = f.sim->status();
            if (s->frame && (seen.samples.empty() || s->frame->time != seen.samples.back().second))
                seen.samples.emplace_back(clock.nsecsElapsed() / 1e9, s->frame->time);
        };
        see();
        QVERIFY(jl::test::clickToolButton(f.window, "&Play"));
        const double playedAt = clock.nsecsElapsed() / 1e9;
        const QRegularExpression factor(QString::fromUtf8("^([0-9.]+)× real time(?: over ([0-9.]+) s)?"));
        int compared = 0;
        for (double next = playedAt + 0.2; clock.elapsed() < 6000; QTest::qWait(5)) {
            see();
            if (f.sim->status()->speed == 1.0 && clock.elapsed() > 3000) f.window.setSpeed(0.5);
            const double now = clock.nsecsElapsed() / 1e9;
            if (now < next) continue;
            next += 0.25;
            const auto m = factor.match(label->text());
            if (!m.hasMatch()) continue;  // no number yet
            // The stretch it names, or (saying none) the last 2 s of playing.
            const double span = m.captured(2).isEmpty() ? std::min(2.0, now - playedAt) : m.captured(2).toDouble();
            const double truth = (seen.simulatedAt(now) - seen.simulatedAt(now - span)) / span;
            const double shown = m.captured(1).toDouble();
            QVERIFY2(std::abs(shown - truth) <= 0.1 * truth,
                     qPrintable(QString("at %1 s after Play the status bar said %2 (over %3 s); the time on "
                                        "screen gained %4 s per s")
                                    .arg(now - playedAt, 0, 'f', 2)
                                    .arg(label->text())
                                    .arg(span)
                                    .arg(truth, 0, 'f', 3)));
            ++compared;
        }
        QVERIFY2(compared >= 16, qPrintable(QString("%1 readings").arg(compared)));
    }
};

QTEST_MAIN(RealTimeFactorTest)
#include "test_real_time_factor.moc"
