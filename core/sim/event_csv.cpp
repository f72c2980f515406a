#include "jl/sim/event_csv.h"

namespace jl {

std::string csvField(const std::string& text) {
    if (text.find_first_of(",\"\r\n") == std::string::npos) return text;
    std::string out = "\"";
    for (char c : text) {
        if (c == '"') out += '"';  // a quote inside is doubled
        out += c;
    }
    return out + '"';
}

void writeEventsCsv(std::ostream& out, const std::vector<Event>& events) {
    const auto precision = out.precision(17);
    out << "t,hinge,event,corner,text\n";
    for (const Event& e : events)
        out << e.time << ',' << e.hinge << ',' << toString(e.kind) << ',' << e.corner << ',' << csvField(e.text)
            << '\n';
    out.precision(precision);
}

}  // namespace jl
