// The tables of docs/scene-format.md, written from the fields themselves.
#include "jl/scene/scene_fields.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace jl {

namespace {

// A number as a reader of the page writes it: whole numbers in full,
// others in the fewest digits that read back the same, "1e-6" not "1e-06".
std::string docNumber(double x) {
    char text[40];
    if (x == std::floor(x) && std::abs(x) < 1e7) {
        std::snprintf(text, sizeof text, "%.0f", x);
        return text;
    }
    for (int digits = 1; digits <= 17; ++digits) {
        std::snprintf(text, sizeof text, "%.*g", digits, x);
        if (std::strtod(text, nullptr) == x) break;
    }
    std::string out = text;
    for (const char* sign : {"e-0", "e+0"})
        if (const std::size_t at = out.find(sign); at != std::string::npos) out.erase(at + 2, 1);
    if (const std::size_t at = out.find("e+"); at != std::string::npos) out.erase(at + 1, 1);
    return out;
}

// "0.0001 .. 100" (closed), "[0, 1)" (open at an end): the range as a
// reader of the page expects it.
std::string allowed(const Bound& b) {
    const std::string lo = docNumber(b.lo), hi = docNumber(b.hi);
    if (!b.loOpen && !b.hiOpen) return lo + " .. " + hi;
    std::string out(b.loOpen ? "(" : "[");
    out += lo;
    out += ", ";
    out += hi;
    out += b.hiOpen ? ")" : "]";
    return out;
}

// Appended piece by piece: GCC 12's -Wrestrict misreads "`" + std::string.
std::string backticked(std::string_view s) {
    std::string out(1, '`');
    out += s;
    out += '`';
    return out;
}

// A default outside the range stands for "left out" (the step: chosen by
// the engine), as does an unset optional; the meaning says what happens then.
std::string defaultOf(double value, const Bound& b) {
    return b.contains(value) ? backticked(docNumber(value)) : "left out";
}
std::string defaultOf(const std::optional<double>& value, const Bound& b) {
    return value ? defaultOf(*value, b) : "left out";
}
std::string defaultOf(const Point2& p, const Bound&) {
    std::string point(1, '[');  // piece by piece, as backticked()
    point += docNumber(p[0]);
    point += ", ";
    point += docNumber(p[1]);
    point += ']';
    return backticked(point);
}

void header(std::ostringstream& out) {
    out << "| key | type | unit | default | allowed | meaning |\n|---|---|---|---|---|---|\n";
}

template <class Section, std::size_t N>
void numberRows(std::ostringstream& out, const NumberField<Section> (&numbers)[N]) {
    const Section d{};
    for (const NumberField<Section>& n : numbers) {
        const bool point = std::holds_alternative<Point2 Section::*>(n.member);
        const std::string fallback = visitValue(n, d, [&](const auto& v) { return defaultOf(v, n.range); });
        out << "| " << backticked(n.key) << " | "
            << (n.is(kAngle) ? "angle"
                : point      ? "point"
                             : "number")
            << " | " << n.unit << " | " << (n.is(kRequired) ? "*required*" : fallback) << " | "
            << (point ? "each " : "") << allowed(n.range) << " | " << n.meaning << " |\n";
    }
}

template <class E>
void wordRow(std::ostringstream& out, std::string_view key, std::span<const Word<E>> words, E fallback,
             std::string_view meaning) {
    out << "| " << backticked(key) << " | word | | " << backticked(wordOf(words, fallback)) << " | ";
    bool first = true;
    for (const Word<E>& w : words) {
        out << (first ? "" : ", ") << backticked(w.word);
        first = false;
    }
    out << " | " << meaning << " |\n";
}

// The rows of a section, from one table of numbers or more.
template <const auto&... numbers>
void rowsOf(std::ostringstream& out) {
    (numberRows(out, numbers), ...);
}

// The solver's choices, then its numbers.
void solverRows(std::ostringstream& out) {
    const SolverSpec d;
    wordRow<Integrator>(out, "integrator", kIntegrators, d.integrator,
                        "how the motion is integrated (docs/model.md section 6)");
    wordRow<EventPolicy>(out, "events", kEventPolicies, d.events, "event policy (docs/model.md section 9)");
    wordRow<RigidPairs>(out, "rigid_pairs", kRigidPairs, d.rigidPairs,
                        "a locked or folded pair is one body (`merge`, fewer unknowns) or two bodies held by a pin "
                        "and a weld (`weld`, for comparison)");
    wordRow<StillTail>(out, "still_tail", kStillTails, d.stillTail,
                       "the blocks of a ladder at rest that the motion has not reached hang as a few rigid "
                       "bodies until it comes near them (`joined`, docs/model.md section 3.7: the same motion for "
                       "much less work), or each block is its own body from the start (`separate`, the full model)");
    wordRow<BlockContact>(out, "block_contact", kBlockContacts, d.blockContact,
                          "a corner of a block meets the face of a block that is not its neighbour as a "
                          "frictionless contact that only pushes (`on`, docs/model.md section 17), or blocks "
                          "pass through one another (`off`, the paper's model)");
    numberRows(out, kSolverNumbers);
}

// Each documented section (kDocumentedSections) and its rows.
struct DocumentedTable {
    std::string_view section;
    void (*rows)(std::ostringstream&);
};
const DocumentedTable kTables[] = {
    {"top", rowsOf<kSceneNumbers>},
    {"ladder.block", rowsOf<kBlockNumbers>},
    {"ladder.overrides", rowsOf<kOverrideNumbers>},
    {"ladder.ribbons", rowsOf<kRibbonNumbers>},
    {"ladder.hinges", rowsOf<kHingeNumbers>},
    {"pose", rowsOf<kMotionNumbers<BlockState>>},
    {"bodies", rowsOf<kBodyNumbers, kMotionNumbers<BodySpec>>},
    {"particles", rowsOf<kParticleNumbers>},
    {"points", rowsOf<kPointRefNumbers>},
    {"pins", rowsOf<kPinNumbers>},
    {"springs", rowsOf<kSpringNumbers>},
    {"damping", rowsOf<kDampingNumbers>},
    {"solver", solverRows},
    {"script", rowsOf<kActionNumbers>},
    {"drags", rowsOf<kDragNumbers>},
    {"floor", rowsOf<kFloorNumbers>},
    {"view", rowsOf<kViewNumbers>},
};

}  // namespace

std::string fieldTable(std::string_view section) {
    std::ostringstream out;
    header(out);
    for (const DocumentedTable& t : kTables)
        if (t.section == section) t.rows(out);
    return out.str();
}

std::string withCurrentFieldTables(const std::string& page) {
    static const std::string kOpen = "<!-- fields: ", kClose = "<!-- end fields -->";
    std::string out;
    std::size_t at = 0;
    while (true) {
        const std::size_t open = page.find(kOpen, at);
        if (open == std::string::npos) break;
        const std::size_t nameEnd = page.find(" -->", open);
        const std::size_t close = page.find(kClose, open);
        if (nameEnd == std::string::npos || close == std::string::npos) break;
        const std::string name = page.substr(open + kOpen.size(), nameEnd - open - kOpen.size());
        out += page.substr(at, nameEnd + 4 - at);
        out += '\n';
        out += fieldTable(name);
        at = close;
    }
    return out + page.substr(at);
}

}  // namespace jl
