#include "core/frame_csv.h"

namespace jl {

void writePosesCsv(std::ostream& out, const std::vector<Frame>& frames) {
    const auto precision = out.precision(17);
    out << "t,block,x,y,theta\n";
    for (const Frame& f : frames)
        for (size_t i = 0; i < f.blocks.size(); ++i)
            out << f.time << ',' << i << ',' << f.blocks[i].position.x() << ',' << f.blocks[i].position.y() << ','
                << f.blocks[i].angle << '\n';
    out.precision(precision);
}

void writeEnergyCsv(std::ostream& out, const std::vector<Frame>& frames) {
    const auto precision = out.precision(17);
    out << "t,kinetic,potential,total,held_work,user_work,impact_loss,damping_loss,balance\n";
    for (const Frame& f : frames) {
        const EnergyFrame& e = f.energy;
        out << f.time << ',' << e.kinetic << ',' << e.potential << ',' << e.total() << ',' << e.heldWork << ','
            << e.userWork << ',' << e.impactLoss << ',' << e.dampingLoss << ',' << e.balance() << '\n';
    }
    out.precision(precision);
}

}  // namespace jl
