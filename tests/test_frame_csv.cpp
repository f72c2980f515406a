// labels: io
// The CSV tables of a run (poses, energies, events) read back, by the
// program's own reader, to the very doubles that were written, and each
// column of a quantity names its unit.
#include "jl/base/csv_reader.h"
#include "jl/sim/event_csv.h"
#include "jl/sim/frame_csv.h"
#include "jl/sim/recording.h"
#include "tests/scene_run.h"

#include <QtTest>

#include <bit>
#include <charconv>
#include <cstdint>
#include <limits>
#include <sstream>
#include <utility>

using namespace jl;

namespace {

// The number a cell holds, parsed as strictly as std::from_chars does.
double numberIn(const std::string& cell) {
    double x = std::numeric_limits<double>::quiet_NaN();
    const auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), x);
    if (error != std::errc() || end != cell.data() + cell.size()) qWarning("not a number: '%s'", cell.c_str());
    return x;
}

bool sameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

std::vector<CsvRow> rowsOf(const std::string& text) {
    std::string error;
    const auto rows = readCsv(text, error);
    if (!rows) qFatal("the table does not read back: %s", error.c_str());
    return *rows;
}

// The classic ladder every 0.1 s over its first second, and one frame of
// numbers that a fixed number of digits gets wrong or writes long.
std::vector<Frame> framesToWrite() {
    auto sim = test::simulateFile("examples/classic.yaml");
    if (!sim) qFatal("examples/classic.yaml does not build");
    WholeRun whole;
    record(*sim, 1.0, FrameGrid{0, 0.1}, &whole);
    std::vector<Frame> frames = std::move(whole.frames);
    Frame awkward = frames.back();
    awkward.time = 0.1 + 0.2;
    awkward.poses[0].position = Vec2(std::numeric_limits<double>::denorm_min(), -0.0);
    awkward.poses[0].angle = 1.0 / 3.0;
    awkward.poses[1].position = Vec2(1e300, -std::numeric_limits<double>::max());
    awkward.energy.kinetic = std::numeric_limits<double>::min();
    frames.push_back(awkward);
    return frames;
}

}  // namespace

class TestFrameCsv : public QObject {
    Q_OBJECT
private slots:
    void posesReadBackBitForBit() {
        const std::vector<Frame> frames = framesToWrite();
        std::ostringstream text;
        writePosesCsv(text, frames);
        const std::vector<CsvRow> rows = rowsOf(text.str());
        QCOMPARE(rows.front(), (CsvRow{"t [s]", "block", "x [m]", "y [m]", "angle [rad]"}));
        std::size_t r = 1;
        for (const Frame& f : frames)
            for (std::size_t b = 0; b < f.poses.size(); ++b, ++r) {
                QVERIFY(r < rows.size());
                const CsvRow& row = rows[r];
                QCOMPARE(row.size(), std::size_t(5));
                QVERIFY(sameBits(numberIn(row[0]), f.time));
                QCOMPARE(row[1], std::to_string(b));
                QVERIFY2(sameBits(numberIn(row[2]), f.poses[b].position.x()), row[2].c_str());
                QVERIFY2(sameBits(numberIn(row[3]), f.poses[b].position.y()), row[3].c_str());
                QVERIFY2(sameBits(numberIn(row[4]), f.poses[b].angle), row[4].c_str());
            }
        QCOMPARE(r, rows.size());
        // The shortest text that reads back: 0.2 s is "0.2", not 0.20000000000000001.
        QCOMPARE(rows[2 * frames.front().poses.size() + 1][0], std::string("0.2"));
        QCOMPARE(rows.back().front(), std::string("0.30000000000000004"));
    }

    void energiesReadBackBitForBit() {
        const std::vector<Frame> frames = framesToWrite();
        std::ostringstream text;
        writeEnergyCsv(text, frames);
        const std::vector<CsvRow> rows = rowsOf(text.str());
        QCOMPARE(rows.front(), (CsvRow{"t [s]", "kinetic [J]", "potential [J]", "total [J]", "held_work [J]",
                                       "user_work [J]", "impact_loss [J]", "damping_loss [J]", "balance [J]"}));
        QCOMPARE(rows.size(), frames.size() + 1);
        for (std::size_t k = 0; k < frames.size(); ++k) {
            const EnergyFrame& e = frames[k].energy;
            const double written[] = {frames[k].time, e.kinetic,    e.potential,   e.total(),  e.heldWork,
                                      e.userWork,     e.impactLoss, e.dampingLoss, e.balance()};
            const CsvRow& row = rows[k + 1];
            QCOMPARE(row.size(), std::size(written));
            for (std::size_t c = 0; c < row.size(); ++c)
                QVERIFY2(sameBits(numberIn(row[c]), written[c]), row[c].c_str());
        }
    }

    void eventTimesReadBackBitForBit() {
        auto sim = test::simulateFile("examples/classic.yaml");
        QVERIFY(sim);
        WholeRun whole;
        record(*sim, 2.5, FrameGrid{}, &whole);
        const std::vector<Event>& events = whole.events;
        QVERIFY(events.size() >= 5);  // the five hinges flip within 2.5 s
        std::ostringstream text;
        writeEventsCsv(text, events);
        const std::vector<CsvRow> rows = rowsOf(text.str());
        QCOMPARE(rows.front(), (CsvRow{"t [s]", "hinge", "event", "corner", "text"}));
        QCOMPARE(rows.size(), events.size() + 1);
        for (std::size_t i = 0; i < events.size(); ++i) {
            QVERIFY2(sameBits(numberIn(rows[i + 1][0]), events[i].time), rows[i + 1][0].c_str());
            QCOMPARE(rows[i + 1][1], std::to_string(events[i].hinge));
            QCOMPARE(rows[i + 1][4], events[i].text);
        }
    }
};

QTEST_APPLESS_MAIN(TestFrameCsv)
#include "test_frame_csv.moc"
