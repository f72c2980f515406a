// labels: ui
// The plots' samples (ui/teaching/run_traces.h): each hinge's fold and each block's
// unwrapped angle read back as the frames gave them, a rewound run cut
// back; and a frame of a 10,000-block ladder taken without an allocation
// per block (the UI thread takes one at every frame the run plays).
#include "tests/counting_new.h"
#include "ui/teaching/run_traces.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using jl::ui::RunTraces;

namespace {

// A ladder's frame at `time`: block i at angle base + i * 0.1, hinge j folded by j * 0.01.
jl::Frame ladderFrame(double time, int blocks, double base) {
    jl::Frame f;
    f.time = time;
    for (int i = 0; i < blocks; ++i) {
        jl::Pose p;
        p.angle = base + i * 0.1;
        f.poses.push_back(p);
    }
    for (int j = 1; j < blocks; ++j) {
        jl::HingeFrame h;
        h.foldAngle = j * 0.01 + time;
        f.hinges.push_back(h);
    }
    return f;
}

}  // namespace

class RunTracesTest : public QObject {
    Q_OBJECT
private slots:
    void foldsAndAnglesReadBackAsTheFramesGaveThem() {
        RunTraces traces;
        // Block 0 turns past pi between the second and third frame: its
        // angle goes on continuously, not back by 2 pi.
        const double bases[] = {3.0, 3.1, -3.1, -3.0};
        for (int k = 0; k < 4; ++k) traces.append(ladderFrame(0.1 * k, 3, bases[k]));
        QCOMPARE(traces.count(), 4);
        QCOMPARE(traces.hingeCount(), 2);
        QCOMPARE(traces.blockCount(), 3);
        const std::vector<double> angle = traces.angle(0);
        QCOMPARE(angle.size(), size_t(4));
        QCOMPARE(angle[1], 3.1);
        QVERIFY(std::abs(angle[2] - (2 * std::numbers::pi - 3.1)) < 1e-12);
        QVERIFY(std::abs(traces.angle(2)[3] - (2 * std::numbers::pi - 3.0 + 0.2)) < 1e-12);
        QCOMPARE(traces.fold(2)[3], 2 * 0.01 + 0.1 * 3);
        QVERIFY(std::abs(traces.angularSpeed(1)[1] - 1.0) < 1e-9);  // 0.1 rad in 0.1 s
        // A rewound run: the frame at 0.1 s again drops those after it.
        traces.append(ladderFrame(0.1, 3, 0.5));
        QCOMPARE(traces.count(), 2);
        QCOMPARE(traces.angle(1).back(), 0.5 + 1 * 0.1);
        // Another ladder starts afresh.
        traces.append(ladderFrame(0.2, 5, 0));
        QCOMPARE(traces.count(), 1);
        QCOMPARE(traces.blockCount(), 5);
        QCOMPARE(traces.fold(4).front(), 4 * 0.01 + 0.2);
    }

    void aLongLaddersFrameIsTakenWithoutAnAllocationPerBlock() {
        constexpr int kBlocks = 10000, kFrames = 20;
        std::vector<jl::Frame> frames;
        for (int k = 0; k < kFrames; ++k) frames.push_back(ladderFrame(k / 60.0, kBlocks, 0.001 * k));
        RunTraces traces;
        traces.append(frames[0]);
        const long long before = jl::test::allocations.load();
        for (int k = 1; k < kFrames; ++k) traces.append(frames[size_t(k)]);
        const long long made = jl::test::allocations.load() - before;
        qInfo("%d frames of %d blocks: %lld allocations", kFrames - 1, kBlocks, made);
        QCOMPARE(traces.count(), kFrames);
        QCOMPARE(traces.angle(kBlocks - 1).back(), 0.001 * (kFrames - 1) + (kBlocks - 1) * 0.1);
        // A row a frame, and the time and energy columns growing now and
        // then: 69 (before, each of the 19,999 curves grew on its own: 100,040).
        QVERIFY2(made <= 4 * kFrames, qPrintable(QString("%1 allocations").arg(made)));
    }
};

QTEST_APPLESS_MAIN(RunTracesTest)
#include "test_run_traces.moc"
