// Recorded frames as CSV tables for spreadsheets: block poses (one row per
// block per frame) and the energy books (one row per frame). Shared by the
// command line (jladder run/export), which writes them frame by frame as a
// run goes, and the desktop program's exports.
#pragma once

#include "jl/sim/frame.h"

#include <ostream>
#include <vector>

namespace jl {

// "t [s],block,x [m],y [m],angle [rad]": each number the shortest text that
// reads back to the same double (jl/base/csv_writer.h).
void writePosesCsv(std::ostream& out, const std::vector<Frame>& frames);
// "t [s],kinetic [J],potential [J],total [J],held_work [J],user_work [J],
// impact_loss [J],damping_loss [J],balance [J]".
void writeEnergyCsv(std::ostream& out, const std::vector<Frame>& frames);

// The same tables a frame at a time: the header line, then each frame's rows.
void writePosesCsvHeader(std::ostream& out);
void writePosesCsvRows(std::ostream& out, const Frame& frame);
void writeEnergyCsvHeader(std::ostream& out);
void writeEnergyCsvRow(std::ostream& out, const Frame& frame);

}  // namespace jl
