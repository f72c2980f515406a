// labels: ladder
// Design questions over many runs: the axes and the scene of one design, the
// first ripple's reach on designs whose answer is known, and a map that is
// the same whatever the number of threads.
#include "jl/base/csv_reader.h"
#include "jl/base/xml_text.h"
#include "jl/design/design_axis.h"
#include "jl/design/design_check.h"
#include "jl/design/map_share.h"
#include "jl/design/ripple_map.h"
#include "jl/design/ripple_reach.h"
#include "jl/scene/scene_ranges.h"

#include <QtTest>

#include <atomic>
#include <cmath>
#include <limits>
#include <numbers>

using namespace jl;

class DesignTest : public QObject {
    Q_OBJECT
private slots:
    void axesGiveTheirValues() {
        const std::vector<double> v = axisValues({DesignParameter::TurnDuration, 0.1, 0.5, 0.1});
        QCOMPARE(int(v.size()), 5);  // 0.5 itself, despite 0.1 not being exact in binary
        QCOMPARE(v.back(), 0.1 + 4 * 0.1);
        QCOMPARE(int(axisValues({DesignParameter::Blocks, 6, 50, 2}).size()), 23);
        // The map of the measurement: 1.5 to 15 mm in ten steps, the last
        // one 15 mm within rounding.
        const std::vector<double> t = axisValues({DesignParameter::Thickness, 0.0015, 0.015, 0.0015});
        QCOMPARE(int(t.size()), 10);
        QCOMPARE(t.front(), 0.0015);
        QVERIFY(std::abs(t.back() - 0.015) < 1e-15);
        // Each value the double a scene file holding it as text reads: 9, 10,
        // 13 and 14 mm were 0.009000000000000001 m and so on as from + i step
        // in doubles.
        const std::vector<double> mm = axisValues({DesignParameter::Thickness, 0.001, 0.015, 0.001});
        QCOMPARE(int(mm.size()), 15);
        for (int i = 0; i < 15; ++i)  // exactly: QCOMPARE takes doubles within 1e-12 of each other
            QVERIFY2(mm[size_t(i)] == std::strtod((std::to_string(i + 1) + "e-3").c_str(), nullptr),
                     qPrintable(QString::number(mm[size_t(i)], 'g', 17)));
        QCOMPARE(axisValues({DesignParameter::Blocks, 5, 100, 5}).back(), 100.0);
        QCOMPARE(axisValues({DesignParameter::Density, 600, 600, 1}), std::vector<double>{600});  // one value
        QVERIFY(axisValues({DesignParameter::Blocks, 6, 5, 1}).empty());                          // backwards
        QVERIFY(axisValues({DesignParameter::Blocks, 6, 50, 0}).empty());                         // no step
    }

    void aDesignSetsOneParameter() {
        const Scene base = turnedLadder(6, 0.012);
        QCOMPARE(withParameter(base, DesignParameter::Blocks, 12.4).ladder->blocks, 12);
        QCOMPARE(withParameter(base, DesignParameter::Blocks, 1).ladder->blocks,
                 2);  // a ladder has two blocks at least
        QCOMPARE(withParameter(base, DesignParameter::Blocks, 1e300).ladder->blocks, range::kMostBlocks);
        QCOMPARE(withParameter(base, DesignParameter::Blocks, std::nan("")).ladder->blocks, range::kFewestBlocks);
        QCOMPARE(withParameter(base, DesignParameter::Length, 0.08).ladder->block.length, 0.08);
        QCOMPARE(withParameter(base, DesignParameter::Width, 0.05).ladder->block.width, 0.05);
        QCOMPARE(withParameter(base, DesignParameter::Density, 700).ladder->block.density, 700.0);
        QCOMPARE(withParameter(Scene{}, DesignParameter::Blocks, 9).ladder->blocks, 9);  // a ladder made if none
        QCOMPARE(withParameter(base, DesignParameter::Thickness, 0.003).ladder->block.thickness, 0.003);
        QCOMPARE(withParameter(base, DesignParameter::HingeDamping, 1e-5).ladder->hinges.damping, 1e-5);
        const Scene slow = withParameter(base, DesignParameter::TurnDuration, 0.6);
        QCOMPARE(slow.script.front().duration, 0.6);
        QCOMPARE(slow.ladder->blocks, 6);  // the rest as it was
        QCOMPARE(std::string(describe(DesignParameter::HingeDamping).word), std::string("hinge_damping"));
        // Read back: what withParameter set, for every parameter.
        const std::pair<DesignParameter, double> set[] = {
            {DesignParameter::Blocks, 9},        {DesignParameter::Thickness, 0.004},
            {DesignParameter::Length, 0.07},     {DesignParameter::Width, 0.05},
            {DesignParameter::Density, 700},     {DesignParameter::HingeDamping, 2e-5},
            {DesignParameter::TurnDuration, 0.4}};
        for (const auto& [p, v] : set) QCOMPARE(parameterValue(withParameter(base, p, v), p), v);
        QVERIFY(std::isnan(parameterValue(Scene{}, DesignParameter::Blocks)));
        Scene still = base;
        still.script.clear();
        QVERIFY(std::isnan(parameterValue(still, DesignParameter::TurnDuration)));
    }

    // The classic design: every hinge flips in order (the classic example's
    // lesson), the first soon after the turn ends at 0.5 s.
    void theClassicRipplesToTheBottom() {
        const RippleReach r = firstRippleReach(turnedLadder(6, 0.012));
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QCOMPARE(r.hinges, 5);
        QCOMPARE(r.reached, 5);
        QCOMPARE(int(r.flipTimes.size()), 5);
        QVERIFY(r.flipTimes.front() > 0.45 && r.flipTimes.front() < 0.6);
        for (size_t k = 1; k < r.flipTimes.size(); ++k) QVERIFY(r.flipTimes[k] > r.flipTimes[k - 1]);
        QCOMPARE(r.meanTimeBetweenFlips, (r.flipTimes.back() - r.flipTimes.front()) / 4);
    }

    // Twelve blocks 12 mm thick: hinge 1 flips and the weight of the blocks
    // below holds hinge 2 back (docs/model.md section 15: "1 of 11").
    void aThickLongLadderStopsAfterTheFirstHinge() {
        const RippleReach r = firstRippleReach(turnedLadder(12, 0.012));
        QVERIFY2(r.failure.empty(), r.failure.c_str());
        QCOMPARE(r.hinges, 11);
        QCOMPARE(r.reached, 1);
        QCOMPARE(int(r.flipTimes.size()), 1);
        QCOMPARE(r.meanTimeBetweenFlips, 0.0);  // one flip has no time between flips
        QCOMPARE(r.until, 1.0 + 0.2 * 12);      // the run of the fixed table in jladder reach
    }

    // The counts of docs/model.md section 15, which the independent
    // reduced-coordinate ladder gives too (tests/test_reduced_ladder.cpp).
    void theLongThinLaddersAgreeWithTheReference() {
        QCOMPARE(firstRippleReach(turnedLadder(25, 0.004)).reached, 7);
        QCOMPARE(firstRippleReach(turnedLadder(25, 0.003)).reached, 23);
    }

    // Without a turn, nothing flips: the ladder hangs at rest for its
    // whole run (which a run that stops when settled does not wait for:
    // tests/test_design_settled.cpp).
    void noTurnNoRipple() {
        Scene s = turnedLadder(8, 0.012);
        s.script.clear();
        const RippleReach r =
            firstRippleReach(s, nullptr, std::numeric_limits<double>::infinity(), RippleStop::WholeRun);
        QVERIFY(r.failure.empty());
        QCOMPARE(r.reached, 0);
        QCOMPARE(r.events, 0);
        QCOMPARE(r.until, 0.5 + 0.2 * 8);
    }

    void aCancelledRunSaysSo() {
        std::atomic<bool> cancel{true};
        QVERIFY(firstRippleReach(turnedLadder(6, 0.012), &cancel).cancelled);
    }

    // A map cancelled before it starts: every cell says so, none is a
    // design that simply did not ripple.
    void aCancelledMapSaysSoInEveryCell() {
        std::atomic<bool> cancel{true};
        const RippleMap m = computeRippleMap(turnedLadder(6, 0.012), {DesignParameter::Blocks, 4, 8, 2},
                                             {DesignParameter::Thickness, 0.006, 0.012, 0.006}, 2, &cancel);
        QVERIFY(m.cancelled);
        QCOMPARE(int(m.cells.size()), 6);
        for (const RippleReach& r : m.cells) QVERIFY(r.cancelled);
        QVERIFY(rippleMapCsv(m).find(",cancelled\n") != std::string::npos);
    }

    void aMapIsTheSameOnAnyNumberOfThreads() {
        const DesignAxis x{DesignParameter::Blocks, 4, 8, 2}, y{DesignParameter::Thickness, 0.006, 0.012, 0.006};
        std::atomic<int> calls{0};
        const RippleMap one = computeRippleMap(turnedLadder(6, 0.012), x, y, 1, nullptr, [&](int, int) { ++calls; });
        const RippleMap two = computeRippleMap(turnedLadder(6, 0.012), x, y, 2);
        QCOMPARE(calls.load(), 6);
        QCOMPARE(int(one.cells.size()), 6);
        QCOMPARE(rippleMapCsv(one), rippleMapCsv(two));
        QCOMPARE(rippleMapSvg(one, "t"), rippleMapSvg(two, "t"));
        // Cell (i, j) is the design of xs[i] and ys[j].
        QCOMPARE(one.at(2, 1).hinges, 7);
        QCOMPARE(one.at(0, 0).hinges, 3);
        const RippleReach alone =
            firstRippleReach(withParameter(turnedLadder(8, 0.012), DesignParameter::Thickness, 0.006));
        QCOMPARE(one.at(2, 0).reached, alone.reached);
        QCOMPARE(one.at(2, 0).flipTimes, alone.flipTimes);
        // Each column names its unit, and each number reads back to the
        // very double of the design and of its run.
        const std::string csv = rippleMapCsv(one);
        QVERIFY2(csv.starts_with("blocks,thickness [m],hinges,reached,mean_time_between_flips [s],"
                                 "flips_elsewhere_until_stop,events_until_stop,quick_row_until_stop,stopped_at [s],"
                                 "stopped_by,failure\n"),
                 csv.c_str());
        std::string error;
        const auto rows = readCsv(csv, error);
        QVERIFY2(rows && rows->size() == 7, error.c_str());
        int timed = 0;
        for (std::size_t k = 0; k < 6; ++k) {
            const CsvRow& row = (*rows)[k + 1];
            QCOMPARE(std::stod(row[0]), one.xs[k % 3]);
            QCOMPARE(std::stod(row[1]), one.ys[k / 3]);
            const double mean = one.cells[k].meanTimeBetweenFlips;
            QCOMPARE(row[4].empty(), !std::isfinite(mean));
            if (std::isfinite(mean)) QCOMPARE(std::stod(row[4]), mean);
            QCOMPARE(std::stod(row[8]), one.cells[k].until);
            QCOMPARE(row[9], std::string(rippleEndWord(one.cells[k].end)));
            timed += std::isfinite(mean);
        }
        QVERIFY(timed > 0);
    }

    // Shares of a map, joined, are the map: failure texts with commas,
    // quotes and line breaks read back as they were written, every cell at
    // its place; a missing share, a share twice and another map refused.
    void sharesJoinIntoTheMap() {
        const DesignAxis x{DesignParameter::Blocks, 4, 8, 2}, y{DesignParameter::Thickness, 0.006, 0.012, 0.006};
        RippleMap m{x, y, axisValues(x), axisValues(y), std::vector<RippleReach>(6), false};
        for (std::size_t k = 0; k < m.cells.size(); ++k) {
            m.cells[k].hinges = int(k) + 3;
            m.cells[k].reached = int(k);
            m.cells[k].meanTimeBetweenFlips = 0.125 * double(k);
            m.cells[k].events = 10 * int(k);
            m.cells[k].until = 0.5 + 0.001 * double(k);
            m.cells[k].end = k % 2 ? RippleEnd::Energy : RippleEnd::Order;
        }
        m.cells[1].failure = "the run failed at t = 0.5 s: a, \"b\"\nand c";
        m.cells[4].meanTimeBetweenFlips = std::nan("");
        const std::string name = mapName(turnedLadder(6, 0.012), x, y);
        std::vector<std::pair<std::string, std::string>> shares;
        for (int k : {3, 1, 2}) shares.emplace_back(std::to_string(k) + ".csv", rippleShareCsv(m, name, k, 3));
        const JoinedMap joined = joinRippleShares(shares);
        QVERIFY2(joined.map, joined.error.c_str());
        QCOMPARE(rippleMapCsv(*joined.map), rippleMapCsv(m));
        QCOMPARE(rippleMapSvg(*joined.map, "t"), rippleMapSvg(m, "t"));
        QCOMPARE(joined.map->cells[1].failure, m.cells[1].failure);
        QCOMPARE(joined.map->cells[3].until, m.cells[3].until);
        QCOMPARE(joined.map->cells[3].end, RippleEnd::Energy);

        const auto refusal = [](std::vector<std::pair<std::string, std::string>> s) {
            return joinRippleShares(s).error;
        };
        QVERIFY(refusal({shares[0], shares[1]}).find("share 2 of 3 is missing") != std::string::npos);
        QVERIFY(refusal({shares[0], shares[1], shares[2], shares[1]}).find("are both share 1 of 3") !=
                std::string::npos);
        const std::string other = mapName(turnedLadder(7, 0.012), x, y);
        QVERIFY(refusal({shares[0], shares[1], {"o", rippleShareCsv(m, other, 2, 3)}}).find("of one map") !=
                std::string::npos);
        // Whole runs count other events: their shares are another map's.
        const std::string whole = mapName(turnedLadder(6, 0.012), x, y, RippleStop::WholeRun);
        QVERIFY(refusal({shares[0], shares[1], {"w", rippleShareCsv(m, whole, 2, 3)}}).find("of one map") !=
                std::string::npos);
        QCOMPARE(shareCells(6, 1, 4), (std::pair<std::size_t, std::size_t>{0, 1}));
        QCOMPARE(shareCells(6, 4, 4), (std::pair<std::size_t, std::size_t>{4, 6}));
    }

    // An axis holds what a scene file may: the field table's ranges, whole
    // blocks counts, designs the loader accepts; too many values said so.
    void axesHoldOnlyWhatASceneFileMay() {
        const Scene base = turnedLadder(6, 0.012);
        QCOMPARE(axisProblem(base, {DesignParameter::Thickness, 0.002, 0.012, 0.002}, 200), std::string());
        QVERIFY(!axisProblem(base, {DesignParameter::Thickness, 0, 0.012, 0.002}, 200).empty());
        QVERIFY(!axisProblem(base, {DesignParameter::Blocks, 1, 4, 1}, 200).empty());
        QVERIFY(!axisProblem(base, {DesignParameter::Blocks, 2, 5, 1.5}, 200).empty());
        QVERIFY(!axisProblem(base, {DesignParameter::HingeDamping, -1, 0, 1}, 200).empty());
        QVERIFY(!axisProblem(base, {DesignParameter::TurnDuration, 0, 0.3, 0.1}, 200).empty());
        QVERIFY(axisProblem(base, {DesignParameter::Blocks, 2, 1e9, 1}, 200).find("more than the 200") !=
                std::string::npos);
        Scene held = base;
        held.ladder->held = {5};
        QVERIFY(axisProblem(held, {DesignParameter::Blocks, 4, 8, 2}, 200).find("not valid") != std::string::npos);
        QCOMPARE(parameterRange(DesignParameter::Density).lo, range::density.lo);
    }

    // XML 1.0 holds no C0 control but tab and line ends, no U+FFFE/U+FFFF and
    // nothing that is not UTF-8, escaped or not: the SVG gets U+FFFD there.
    void theMapsSvgHoldsOnlyWhatXmlCan() {
        QCOMPARE(xmlEscaped("a\x01<b>&'\"\xff\xef\xbf\xbe caf\xc3\xa9\t"),
                 std::string("a\xef\xbf\xbd&lt;b&gt;&amp;&apos;&quot;\xef\xbf\xbd\xef\xbf\xbd caf\xc3\xa9\t"));
        QVERIFY(xmlTextProblem("a < b & caf\xc3\xa9").empty());
        for (const char* bad : {"a\x01"
                                "b",
                                "caf\xe9",
                                "a\xef\xbf\xbf"
                                "b",
                                "\xc0\xaf", "\xed\xa0\x80"})
            QVERIFY2(!xmlTextProblem(bad).empty(), bad);
        const RippleMap m = computeRippleMap(turnedLadder(6, 0.012), {DesignParameter::Blocks, 4, 4, 1},
                                             {DesignParameter::Thickness, 0.012, 0.012, 1}, 1);
        const std::string svg = rippleMapSvg(m,
                                             "a\x01"
                                             "b\x1b");
        QVERIFY(svg.find('\x01') == std::string::npos && svg.find('\x1b') == std::string::npos);
    }
};

QTEST_APPLESS_MAIN(DesignTest)
#include "test_design.moc"
