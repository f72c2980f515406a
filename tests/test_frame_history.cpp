// labels: engine
// The recorded run: frames are evenly spaced, eviction keeps the budget but
// never frame 0, the protected frame or a keyframe's snapshot, and an evicted
// frame re-simulated from the keyframe before it is the frame first recorded.
// A keyframe counts what its snapshot takes on the heap; keyframes that
// outgrow the budget are thinned evenly, never the first or the newest.
#include "jl/sim/frame_history.h"
#include "tests/scene_run.h"

#include <QtTest>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <algorithm>
#include <memory>

using namespace jl;

namespace {

const char* kLadder = R"(
format: jacobs-ladder/1
ladder:
  blocks: 6
  held: [0]
script:
  - {at: 0.1, turn: {block: 0, by: 180deg, duration: 0.3}}
)";

constexpr double kInterval = 0.02;

// What one keyframe of the test ladder takes.
std::size_t keyframeBytes() {
    auto sim = test::simulate(kLadder);
    if (!sim) qFatal("the test scene does not build");
    return snapshotBytes(*sim->snapshot());
}

// Records `frames` frames of the six-block ladder turned over, as the simulation thread does.
std::unique_ptr<Simulation> record(FrameHistory& h, int frames, std::size_t budget, int protect = -1) {
    auto sim = test::simulate(kLadder);
    if (!sim) qFatal("the test scene does not build");
    h.reset(kInterval, budget);
    for (int i = 0; i < frames; ++i) {
        if (i > 0) sim->advanceTo(i * kInterval);
        auto key = h.isKeyframeIndex(i) ? sim->snapshot() : nullptr;
        h.append(std::make_shared<const Frame>(sim->frame()), key, protect < 0 ? i : protect);
    }
    return sim;
}

}  // namespace

class TestFrameHistory : public QObject {
    Q_OBJECT
private slots:
    void framesAreEvenlySpaced() {
        FrameHistory h;
        record(h, 60, std::size_t(1) << 30);
        QCOMPARE(h.count(), 60);
        QCOMPARE(h.keyframeEvery(), 25);  // 0.5 s / 0.02 s
        QCOMPARE(h.indexAt(0.0), 0);
        QCOMPARE(h.indexAt(0.5), 25);
        QCOMPARE(h.indexAt(0.519), 25);
        QCOMPARE(h.indexAt(100.0), 59);  // past the head: the head
        QCOMPARE(h.indexAt(-1.0), 0);
        // advanceTo does not shorten its last step: a frame is at its time or
        // less than one step after it.
        for (int i = 0; i < h.count(); ++i) {
            const double late = h.frame(i)->time - i * kInterval;
            QVERIFY(late > -1e-12 && late < kInterval / 2);
        }
        QVERIFY(!h.frame(60));
        QVERIFY(!h.frame(-1));
    }

    void evictionKeepsTheBudgetAndWhatMustStay() {
        FrameHistory h;
        // Room for the five keyframes and a third of the frames.
        const std::size_t budget = 5 * keyframeBytes() + 30'000;
        record(h, 120, budget, 70);
        QVERIFY(h.bytes() <= budget);
        QVERIFY(h.frame(0));         // the scene as built
        QVERIFY(h.frame(70));        // the frame on screen
        QVERIFY(h.frame(h.head()));  // the newest
        QVERIFY(!h.frame(1));        // the oldest others went first
        for (int i = 0; i < h.count(); ++i) {
            const auto [k, snap] = h.keyframeAtOrBefore(i);
            QCOMPARE(k, i / 25 * 25);
            QVERIFY(snap);
        }
    }

    void anEvictedFrameComesBackTheSame() {
        FrameHistory h;
        record(h, 80, 40'000);
        const int i = 33;
        QVERIFY(!h.frame(i));
        // Recorded once more without a budget, to compare with.
        FrameHistory whole;
        record(whole, 80, std::size_t(1) << 30);
        const auto [k, snap] = h.keyframeAtOrBefore(i);
        auto sim = test::simulate(kLadder);
        sim->restore(*snap);
        for (int j = k + 1; j <= i; ++j) sim->advanceTo(j * kInterval);
        h.restoreFrame(i, std::make_shared<const Frame>(sim->frame()), i);
        QVERIFY(h.frame(i));
        const Frame& a = *h.frame(i);
        const Frame& b = *whole.frame(i);
        QVERIFY(a.poses[1].angle != whole.frame(0)->poses[1].angle);  // it moved
        QCOMPARE(a.poses.size(), b.poses.size());
        for (size_t p = 0; p < a.poses.size(); ++p) {
            QCOMPARE(a.poses[p].position.x(), b.poses[p].position.x());
            QCOMPARE(a.poses[p].position.y(), b.poses[p].position.y());
            QCOMPARE(a.poses[p].angle, b.poses[p].angle);
        }
    }

    // What the history counts for a keyframe is what its snapshot took from
    // the heap, read off glibc's books: a snapshot of a 1,000-block ladder is
    // about 1.3 MB (14 particles a block), five times its frame.
    void aKeyframeCountsWhatItsSnapshotTakes() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
        QSKIP("a sanitizer's allocator keeps books of its own; glibc's show nothing");
#elif defined(__GLIBC__)
        auto sim = test::simulate(R"(
format: jacobs-ladder/1
ladder: {blocks: 1000, held: [0]}
script:
  - {at: 0, turn: {block: 0, by: 180deg, duration: 0.3}}
)");
        QVERIFY(sim);
        sim->advanceTo(0.3);  // blocks moving, the still tail hanging
        const auto heap = [] {
            const struct mallinfo2 m = mallinfo2();
            return double(m.uordblks + m.hblkhd);
        };
        const double before = heap();
        const auto key = sim->snapshot();
        const double taken = heap() - before;
        QVERIFY2(taken > 1e6, qPrintable(QString::number(taken)));
        QVERIFY2(std::abs(double(snapshotBytes(*key)) - taken) < 0.02 * taken,
                 qPrintable(QString("counted %1, taken %2").arg(snapshotBytes(*key)).arg(taken)));
#else
        QSKIP("glibc's malloc statistics are what this reads");
#endif
    }

    // Twelve keyframes where four fit: the first and the newest stay, the
    // others left are spread evenly, and memory stays within the budget.
    void keyframesThinEvenlyPastTheBudget() {
        FrameHistory h;
        const std::size_t budget = 4 * keyframeBytes() + 5'000;
        record(h, 12 * 25 + 1, budget);
        QVERIFY2(h.bytes() <= budget, qPrintable(QString("%1 > %2").arg(h.bytes()).arg(budget)));
        std::vector<int> kept;
        for (int k = 0; k <= 12; ++k)
            if (h.keyframeAtOrBefore(k * 25).first == k * 25) kept.push_back(k);
        QVERIFY(kept.size() >= 3 && kept.size() <= 4);
        QCOMPARE(kept.front(), 0);
        QCOMPARE(kept.back(), 12);
        int longest = 0;
        for (size_t i = 1; i < kept.size(); ++i) longest = std::max(longest, kept[i] - kept[i - 1]);
        QVERIFY2(longest <= 2 * 12 / int(kept.size() - 1), qPrintable(QString::number(longest)));
        // Every frame can still be re-simulated from a keyframe before it.
        for (int i = 0; i < h.count(); ++i) QVERIFY(h.keyframeAtOrBefore(i).second);
        // A truncation gives back what the keyframes it drops took.
        const std::size_t before = h.bytes();
        h.truncateAfter(25 * 6);
        QVERIFY(h.bytes() < before);
    }

    void truncateDropsTheFuture() {
        FrameHistory h;
        record(h, 80, std::size_t(1) << 30);
        h.truncateAfter(40);
        QCOMPARE(h.count(), 41);
        QCOMPARE(h.keyframeAtOrBefore(80).first, 25);
        QVERIFY(!h.frame(41));
    }
};

QTEST_APPLESS_MAIN(TestFrameHistory)
#include "test_frame_history.moc"
