// The event log as CSV (one row per event, jl/base/csv_writer.h), for
// spreadsheets: the desktop program's export; the command line may share it.
#pragma once

#include "jl/sim/frame.h"

#include <ostream>
#include <string>
#include <vector>

namespace jl {

// Header "t [s],hinge,event,corner,text"; times as the shortest text that
// reads back bit for bit; `event` is toString(EventKind).
void writeEventsCsv(std::ostream& out, const std::vector<Event>& events);

}  // namespace jl
