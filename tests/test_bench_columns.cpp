// labels: io
// The benchmark's CSV tables name each column's unit as the run's tables do
// ("t [s]"): every column is a count, a name or a yes/no, or ends in its unit
// in brackets; and the tables in docs/bench carry the headers the benchmark
// writes.
#include "bench/csv_columns.h"

#include <QtTest>

#include <fstream>
#include <regex>
#include <set>
#include <string>
#include <vector>

using namespace jl::bench;

namespace {

std::vector<std::string> columnsOf(const std::string& header) {
    std::vector<std::string> out;
    std::string::size_type from = 0;
    for (auto comma = header.find(','); comma != std::string::npos; comma = header.find(',', from)) {
        out.push_back(header.substr(from, comma - from));
        from = comma + 1;
    }
    out.push_back(header.substr(from));
    return out;
}

// Columns with no unit: counts, names, yes/no (0/1) and pure numbers.
const std::set<std::string> kNoUnit{"study",
                                    "method",
                                    "blocks",
                                    "finished",
                                    "note",
                                    "steps",
                                    "events",
                                    "instants",
                                    "kinds",
                                    "repetitions",
                                    "repeatable",
                                    "plain_steps",
                                    "plain_repetitions",
                                    "plain_events",
                                    "event_share",
                                    "plain_steps_per_event",
                                    "turning_steps",
                                    "turning_events",
                                    "eventful_steps",
                                    "failure",
                                    "scene",
                                    "faster_than_real_time",
                                    "integrator",
                                    "adaptive",
                                    "tolerance",
                                    "automatic_step",
                                    "step_halvings",
                                    "hinge_events",
                                    "lanczos_steps",
                                    "hand_tension_factor",
                                    "peak_tension_factor",
                                    "dopri_steps",
                                    "dopri_rejected",
                                    "still_from",
                                    "pairs",
                                    "calls",
                                    "on_off_ratio",
                                    "turns",
                                    "steps_off",
                                    "steps_on",
                                    "events_off",
                                    "events_on",
                                    "strikes",
                                    "same_sequence",
                                    "failure_off",
                                    "failure_on",
                                    "engine",
                                    "setting",
                                    "stop_model",
                                    "missing",
                                    "extra"};

const std::pair<const char*, const char*> kTables[] = {
    {"pendulum", kWorkPrecisionPendulumColumns},
    {"chain10", kWorkPrecisionColumns},
    {"chain100", kWorkPrecisionColumns},
    {"chain1000", kWorkPrecisionColumns},
    {"ladder", kWorkPrecisionColumns},
    {"long_ladder", kWorkPrecisionColumns},
    {"models", kWorkPrecisionColumns},
    {"scaling", kScalingColumns},
    {"events", kEventCostColumns},
    {"examples", kExamplesColumns},
    {"stability", kStabilityColumns},
    {"contacts_broad_phase", kBroadPhaseColumns},
    {"contacts_examples", kContactExamplesColumns},
    {"folding", kFoldingColumns},
};

}  // namespace

class BenchColumnsTest : public QObject {
    Q_OBJECT
private slots:
    void everyColumnNamesItsUnitOrHasNone() {
        const std::regex withUnit(R"([a-z0-9_]+ \[[^\]]+\])");
        for (const auto& [table, header] : kTables)
            for (const std::string& c : columnsOf(header))
                QVERIFY2(kNoUnit.count(c) || std::regex_match(c, withUnit),
                         qPrintable(QString("%1: column \"%2\"").arg(table).arg(c.c_str())));
    }

    void theTablesInTheDocsCarryTheseHeaders() {
        for (const auto& [table, header] : kTables) {
            std::ifstream in(std::string(JL_SOURCE_DIR "/docs/bench/") + table + ".csv");
            std::string first;
            QVERIFY2(std::getline(in, first), table);
            QCOMPARE(first, std::string(header));
        }
    }
};

QTEST_APPLESS_MAIN(BenchColumnsTest)
#include "test_bench_columns.moc"
