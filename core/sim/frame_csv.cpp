#include "jl/sim/frame_csv.h"

#include "jl/base/csv_writer.h"

namespace jl {

// Each quantity's column names its unit, so that a table read alone says
// what its numbers are.
void writePosesCsvHeader(std::ostream& out) { out << "t [s],block,x [m],y [m],angle [rad]\n"; }

void writePosesCsvRows(std::ostream& out, const Frame& f) {
    CsvWriter csv(out);
    for (size_t i = 0; i < f.poses.size(); ++i)
        csv.row(f.time, i, f.poses[i].position.x(), f.poses[i].position.y(), f.poses[i].angle);
}

void writeEnergyCsvHeader(std::ostream& out) {
    out << "t [s],kinetic [J],potential [J],total [J],held_work [J],user_work [J],impact_loss [J],damping_loss [J],"
           "balance [J]\n";
}

void writeEnergyCsvRow(std::ostream& out, const Frame& f) {
    const EnergyFrame& e = f.energy;
    CsvWriter(out).row(f.time, e.kinetic, e.potential, e.total(), e.heldWork, e.userWork, e.impactLoss, e.dampingLoss,
                       e.balance());
}

void writePosesCsv(std::ostream& out, const std::vector<Frame>& frames) {
    writePosesCsvHeader(out);
    for (const Frame& f : frames) writePosesCsvRows(out, f);
}

void writeEnergyCsv(std::ostream& out, const std::vector<Frame>& frames) {
    writeEnergyCsvHeader(out);
    for (const Frame& f : frames) writeEnergyCsvRow(out, f);
}

}  // namespace jl
