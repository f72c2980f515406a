#include "jl/sim/event_json.h"

#include <nlohmann/json.hpp>

namespace jl {

void writeEventsJsonStart(std::ostream& out) { out << "["; }

// Keys in the order given; a time that is not finite is null (JSON has no NaN).
void writeEventJson(std::ostream& out, const Event& e, bool first) {
    const nlohmann::ordered_json json{
        {"t", e.time}, {"hinge", e.hinge}, {"event", toString(e.kind)}, {"corner", e.corner}, {"text", e.text}};
    out << (first ? "\n " : ",\n ") << json.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

void writeEventsJsonEnd(std::ostream& out) { out << "\n]\n"; }

void writeEventsJson(std::ostream& out, const std::vector<Event>& events) {
    writeEventsJsonStart(out);
    for (size_t i = 0; i < events.size(); ++i) writeEventJson(out, events[i], i == 0);
    writeEventsJsonEnd(out);
}

}  // namespace jl
