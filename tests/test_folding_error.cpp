// labels: io
// The folding chain's report: a run's errors against the reference (block
// centres, dissipated energy, first closings with the hinges missing or
// extra by each sample time), and the part of the report that says whether
// the second reference is there.
#include "bench/folding_report.h"

#include <QtTest>

#include <cmath>

using namespace jl::bench;
using jl::Vec2;

namespace {

// Three blocks (two hinges) at rest at their start, nothing dissipated.
FoldingRun restingRun() {
    FoldingRun r;
    r.engine = "test";
    r.method = "none";
    r.setting = "dt = 1 s";
    r.blocks = 3;
    for (auto& c : r.centres) c = {Vec2(0.03, 0), Vec2(0.09, 0), Vec2(0.15, 0)};
    r.dissipated = {0, 0, 0};
    r.firstClosing = {kNever, kNever};
    return r;
}

}  // namespace

class FoldingErrorTest : public QObject {
    Q_OBJECT
private slots:
    void centresAndEnergyAreTheLargestDifference() {
        const FoldingRun reference = restingRun();
        FoldingRun run = restingRun();
        run.centres[1][2] += Vec2(0.003, 0.004);  // 5 mm off at 0.5 s
        run.centres[2][0] += Vec2(0.001, 0);
        run.dissipated = {0, 0.25, -0.5};
        const FoldingError e = foldingError(run, reference);
        QCOMPARE(e.centre[0], 0.0);
        QVERIFY(std::abs(e.centre[1] - 0.005) < 1e-15);
        QVERIFY(std::abs(e.centre[2] - 0.001) < 1e-15);
        QCOMPARE(e.dissipated[1], 0.25);
        QCOMPARE(e.dissipated[2], 0.5);
    }

    void centresOfOtherBlocksAreNoDistance() {
        FoldingRun run = restingRun();
        run.centres[2].pop_back();
        QVERIFY(std::isnan(foldingError(run, restingRun()).centre[2]));
    }

    // Hinge 1 closes in both, hinge 2 only in the reference: by 0.25 s
    // nothing has closed, by 0.5 s hinge 1 (late in the run), by 1 s hinge 2
    // is missing; reversed, it is extra.
    void closingsCountOnlyWhatHasHappened() {
        FoldingRun reference = restingRun(), run = restingRun();
        reference.firstClosing = {0.4, 0.8};
        run.firstClosing = {0.45, kNever};
        const FoldingError e = foldingError(run, reference);
        QVERIFY(std::isnan(e.closing[0]));
        QVERIFY(std::abs(e.closing[1] - 0.05) < 1e-15);
        QCOMPARE(e.missing[1], 0);
        QCOMPARE(e.missing[2], 1);
        QCOMPARE(e.extra[2], 0);
        const FoldingError reversed = foldingError(reference, run);
        QCOMPARE(reversed.extra[2], 1);
        QCOMPARE(reversed.missing[2], 0);
    }

    void theReportSaysWhenSiconosIsMissing() {
        const FoldingRun ours = restingRun();
        const std::string alone = foldingPart({ours}, ours, nullptr, "bench");
        QVERIFY(alone.find("Siconos runs are missing") != std::string::npos);
        FoldingRun siconos = restingRun();
        siconos.engine = "siconos";
        const std::string both = foldingPart({ours, siconos}, ours, &siconos, "bench");
        QVERIFY(both.find("Siconos runs are missing") == std::string::npos);
        QVERIFY(both.find("against siconos") != std::string::npos);
        QVERIFY(both.find("bench/folding3_closing.svg") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(FoldingErrorTest)
#include "test_folding_error.moc"
