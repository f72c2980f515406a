#include "jl/sim/event_csv.h"

#include "jl/base/csv_writer.h"

namespace jl {

void writeEventsCsv(std::ostream& out, const std::vector<Event>& events) {
    out << "t [s],hinge,event,corner,text\n";
    CsvWriter csv(out);
    for (const Event& e : events) csv.row(e.time, e.hinge, toString(e.kind), e.corner, e.text);
}

}  // namespace jl
