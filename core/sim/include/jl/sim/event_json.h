// The event log as JSON, beside its CSV form (jl/sim/event_csv.h): an array
// of {"t","hinge","event","corner","text"}, one event a line, what the
// command line's --events writes. Text is UTF-8: bytes of a text that are not
// are written as U+FFFD rather than break every reader.
#pragma once

#include "jl/sim/frame.h"

#include <ostream>
#include <vector>

namespace jl {

// The whole log: "[", each event on a line of its own, "]".
void writeEventsJson(std::ostream& out, const std::vector<Event>& events);

// The same an event at a time, for a run that writes them as they come:
// the opening, each event (`first`: no comma before it), the closing.
void writeEventsJsonStart(std::ostream& out);
void writeEventJson(std::ostream& out, const Event& e, bool first);
void writeEventsJsonEnd(std::ostream& out);

}  // namespace jl
