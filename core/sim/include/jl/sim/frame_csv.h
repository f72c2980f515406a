// Recorded frames as CSV tables for spreadsheets: block poses (one row per
// block per frame) and the energy books (one row per frame). Shared by the
// command line (jladder run/export), which writes them frame by frame as a
// run goes, and the desktop program's exports.
#pragma once

#include "jl/sim/frame.h"

#include <ostream>
#include <vector>

namespace jl {

// "t,block,x,y,theta": m and rad, 17 significant digits (they read back exactly).
void writePosesCsv(std::ostream& out, const std::vector<Frame>& frames);
// "t,kinetic,potential,total,held_work,user_work,impact_loss,damping_loss,balance": J.
void writeEnergyCsv(std::ostream& out, const std::vector<Frame>& frames);

// The same tables a frame at a time: the header line, then each frame's rows.
void writePosesCsvHeader(std::ostream& out);
void writePosesCsvRows(std::ostream& out, const Frame& frame);
void writeEnergyCsvHeader(std::ostream& out);
void writeEnergyCsvRow(std::ostream& out, const Frame& frame);

}  // namespace jl
