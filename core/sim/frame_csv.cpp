#include "jl/sim/frame_csv.h"

#include "jl/base/csv_writer.h"

namespace jl {

void writePosesCsvHeader(std::ostream& out) { out << "t,block,x,y,theta\n"; }

void writePosesCsvRows(std::ostream& out, const Frame& f) {
    const auto precision = out.precision(17);
    CsvWriter csv(out);
    for (size_t i = 0; i < f.poses.size(); ++i)
        csv.row(f.time, i, f.poses[i].position.x(), f.poses[i].position.y(), f.poses[i].angle);
    out.precision(precision);
}

void writeEnergyCsvHeader(std::ostream& out) {
    out << "t,kinetic,potential,total,held_work,user_work,impact_loss,damping_loss,balance\n";
}

void writeEnergyCsvRow(std::ostream& out, const Frame& f) {
    const auto precision = out.precision(17);
    const EnergyFrame& e = f.energy;
    CsvWriter(out).row(f.time, e.kinetic, e.potential, e.total(), e.heldWork, e.userWork, e.impactLoss, e.dampingLoss,
                       e.balance());
    out.precision(precision);
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
