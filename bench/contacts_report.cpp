// The section "Block contacts" of docs/performance.md, from contactsStudy.
#include "bench/contacts_report.h"

#include "bench/csv_columns.h"
#include "bench/report_text.h"
#include "bench/save_text.h"
#include "jl/base/csv_writer.h"
#include "jl/ladder/block_contact.h"

#include <algorithm>
#include <sstream>

namespace jl::bench {

namespace {

std::string broadTable(const ContactsStudy& s) {
    if (s.broad.empty()) return "Not measured (no classic.yaml among the examples).\n";
    std::ostringstream md;
    md << "| N | still tail from block | pairs tested | calls timed | CPU per search | per block | per moving block | "
          "per moving block, pairs kept |\n"
       << "|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    // Ladders of up to BlockPairs::kDirect blocks compare their pairs
    // directly: the flatness is the grid's, from the first row that uses it.
    double lo = 1e300, hi = 0, direct = 0;
    int firstGrid = 0;
    for (const BroadPhaseRow& r : s.broad) {
        const int moving = r.stillFrom < 0 ? r.blocks : r.stillFrom;
        const double perMoving = r.perBlock * r.blocks / moving;
        md << "| " << r.blocks << " | " << (r.stillFrom < 0 ? std::string("none") : std::to_string(r.stillFrom))
           << " | " << r.pairs << " | " << r.calls << " | " << cpuTime(r.perBlock * r.blocks) << " | "
           << sig(1e9 * r.perBlock, 3) << " ns | " << sig(1e9 * perMoving, 3) << " ns | "
           << (size_t(r.blocks) <= BlockPairs::kDirect ? std::string("—")
                                                       : sig(1e9 * r.perBlockKept * r.blocks / moving, 3) + " ns")
           << " |" << (r.failure.empty() ? "" : " failed: " + r.failure) << "\n";
        if (r.perBlock <= 0) continue;
        if (size_t(r.blocks) <= BlockPairs::kDirect) {
            direct = std::max(direct, perMoving);
            continue;
        }
        if (firstGrid == 0) firstGrid = r.blocks;
        lo = std::min(lo, perMoving), hi = std::max(hi, perMoving);
    }
    md << "\n- Cost per moving block of a search flat within 1.5x, N = " << firstGrid << " .. " << s.broad.back().blocks
       << " (the grid): max/min = " << sig(hi / lo, 3) << " — **" << (hi / lo <= 1.5 ? "met" : "missed")
       << "**. Per block of the whole ladder it falls as N grows: the still tail costs a box per segment.";
    if (direct > 0)
        md << " Up to " << BlockPairs::kDirect
           << " blocks every pair is compared directly, without the grid: " << sig(direct / lo, 2)
           << "x the grid's cheapest per moving block.";
    md << "\n";
    return md.str();
}

std::string examplesTable(const ContactsStudy& s) {
    if (!s.error.empty()) return "Not measured: " + s.error + ".\n";
    std::ostringstream md;
    md << "| scene | CPU s off | CPU s on | on / off | steps off / on | events off / on | strikes | events off against "
          "on "
          "| largest energy balance on (J) | failure on |\n"
       << "|---|---:|---:|---:|---:|---:|---:|---|---:|---|\n";
    int quiet = 0, quietMet = 0;
    for (const ContactExampleRow& r : s.examples) {
        const double ratio = r.ratio;
        md << "| " << r.scene << " | " << sig(r.cpuOff, 3) << " | " << sig(r.cpuOn, 3) << " | " << sig(ratio, 3)
           << " | " << r.stepsOff << " / " << r.stepsOn << " | " << r.eventsOff << " / " << r.eventsOn << " | "
           << r.touches << " | "
           << (r.sameSequence ? "same, times within " + sig(r.largestShift, 2) + " s"
                              : "part at " + sig(r.partAt, 4) + " s")
           << " | " << sig(r.balanceOn, 3) << " | " << r.failureOn << " |\n";
        if (r.touches == 0) {
            ++quiet;
            if (r.turns > 0 && ratio <= 1.1 && r.sameSequence && r.largestShift <= 1e-9) ++quietMet;
        }
    }
    md << "\n- Where no block strikes another, at most 1.1x, and the same events at the same times to 1e-9 s: "
       << quietMet << " of " << quiet << " — **" << (quietMet == quiet ? "met" : "missed") << "**.\n";
    return md.str();
}

}  // namespace

std::string contactsSection(const ContactsStudy& s, bool quick, bool& ok) {
    return filled(
        "contacts",
        {{"quick_flag", quick ? " --quick" : ""},
         {"quick_note", quick ? " **Quick run**: 1 s of simulated time, N up to 10,000, one repetition." : ""},
         {"min_time", quick ? "20 ms" : "0.2 s"},
         {"horizon", quick ? "1" : "3"},
         {"repetitions", quick ? "one run" : "at least three runs, taken until each side has run 0.5 s of CPU time"},
         {"broad", broadTable(s)},
         {"examples", examplesTable(s)}},
        ok);
}

bool writeContactsCsv(const ContactsStudy& s, const std::filesystem::path& dir) {
    std::ostringstream broad;
    broad << kBroadPhaseColumns << '\n';
    CsvWriter b(broad, 6);
    for (const BroadPhaseRow& r : s.broad)
        b.row(r.blocks, r.stillFrom, r.pairs, r.calls, r.perBlock, r.perBlockKept, r.buildCpu, r.failure);
    std::ostringstream examples;
    examples << kContactExamplesColumns << '\n';
    CsvWriter e(examples, 6);
    for (const ContactExampleRow& r : s.examples)
        e.row(r.scene, r.asked, r.cpuOff, r.cpuOn, r.ratio, r.turns, r.stepsOff, r.stepsOn, r.eventsOff, r.eventsOn,
              r.touches, r.sameSequence, r.largestShift, r.partAt, r.balanceOn, r.failureOff, r.failureOn);
    return saveText(dir / "contacts_broad_phase.csv", broad.str()) &&
           saveText(dir / "contacts_examples.csv", examples.str());
}

bool writeContactsReport(const ContactsStudy& s, bool quick, const std::filesystem::path& report) {
    bool ok = true;
    const std::string text = contactsSection(s, quick, ok);
    return writeSection("contacts", quick, report, text, ok);
}

}  // namespace jl::bench
