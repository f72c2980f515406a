// The event log as CSV (one row per event, RFC 4180 quoting), for
// spreadsheets: the desktop program's export; the command line may share it.
#pragma once

#include "jl/sim/frame.h"

#include <ostream>
#include <string>
#include <vector>

namespace jl {

// Header "t,hinge,event,corner,text"; times with 17 significant digits so
// they read back bit for bit; `event` is toString(EventKind).
void writeEventsCsv(std::ostream& out, const std::vector<Event>& events);
// A field quoted when it must be: a comma, a quote or a line break inside.
std::string csvField(const std::string& text);

}  // namespace jl
