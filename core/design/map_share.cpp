#include "jl/design/map_share.h"

#include "jl/base/csv_reader.h"
#include "jl/base/csv_writer.h"
#include "jl/design/design_check.h"
#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_io.h"

#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <tuple>

namespace jl {

std::pair<std::size_t, std::size_t> shareCells(std::size_t total, int index, int count) {
    if (count < 1 || index < 1 || index > count) return {0, 0};
    return {total * std::size_t(index - 1) / std::size_t(count), total * std::size_t(index) / std::size_t(count)};
}

namespace {

std::string axisName(const DesignAxis& a) {
    return std::string(describe(a.parameter).word) + "=" + formatNumber(a.from) + ":" + formatNumber(a.to) + ":" +
           formatNumber(a.step);
}

// 64-bit FNV-1a of the scene's file text: two bases that differ anywhere
// name two maps.
std::string digest(const Scene& base) {
    std::uint64_t h = 14695981039346656037ull;
    for (const unsigned char c : sceneToYaml(base)) h = (h ^ c) * 1099511628211ull;
    char text[17];
    std::snprintf(text, sizeof text, "%016" PRIx64, h);
    return text;
}

// "thickness=0.006:0.012:0.006" -> the axis, or nullopt.
std::optional<DesignAxis> axisNamed(const std::string& text) {
    const std::size_t eq = text.find('='), a = text.find(':'), b = text.find(':', a + 1);
    if (eq == std::string::npos || a == std::string::npos || b == std::string::npos || a < eq) return std::nullopt;
    const std::string word = text.substr(0, eq);
    const auto from = parseNumber(text.substr(eq + 1, a - eq - 1)), to = parseNumber(text.substr(a + 1, b - a - 1)),
               step = parseNumber(text.substr(b + 1));
    for (const DesignParameterWord& w : kDesignParameters)
        if (w.word == word && from && to && step) return DesignAxis{w.value, *from, *to, *step};
    return std::nullopt;
}

// The empty map a name describes: its axes and values, every cell cancelled.
std::optional<RippleMap> mapOfName(const std::string& name) {
    const std::size_t one = name.find(';'), two = name.find(';', one + 1);
    if (one == std::string::npos || two == std::string::npos) return std::nullopt;
    const auto x = axisNamed(name.substr(0, one)), y = axisNamed(name.substr(one + 1, two - one - 1));
    if (!x || !y || axisCount(*x) > double(kMostAxisValues) || axisCount(*y) > double(kMostAxisValues))
        return std::nullopt;
    RippleMap m{*x, *y, axisValues(*x), axisValues(*y), {}, false};
    m.cells.resize(m.xs.size() * m.ys.size());
    for (RippleReach& r : m.cells) r.cancelled = true;
    if (m.cells.empty()) return std::nullopt;
    return m;
}

// A count as the share writes it: digits only, at most nine of them.
std::optional<int> whole(const std::string& text) {
    if (text.empty() || text.size() > 9 || text.find_first_not_of("0123456789") != std::string::npos)
        return std::nullopt;
    return std::stoi(text);
}

// "2/4" -> {2, 4}.
std::optional<std::pair<int, int>> shareOf(const std::string& text) {
    const std::size_t slash = text.find('/');
    if (slash == std::string::npos) return std::nullopt;
    const auto k = whole(text.substr(0, slash)), n = whole(text.substr(slash + 1));
    if (!k || !n) return std::nullopt;
    return std::pair{*k, *n};
}

}  // namespace

std::string mapName(const Scene& base, const DesignAxis& x, const DesignAxis& y, RippleStop stop) {
    return axisName(x) + ";" + axisName(y) + ";scene=" + digest(base) +
           (stop == RippleStop::WholeRun ? ";whole-runs" : "");
}

std::string rippleShareCsv(const RippleMap& m, const std::string& name, int index, int count) {
    std::ostringstream out;
    out << "map,share,cell," << rippleMapColumns(m) << '\n';
    CsvWriter csv(out);
    const auto [first, last] = shareCells(m.cells.size(), index, count);
    for (std::size_t k = first; k < last; ++k) {
        csv.cell(name);
        csv.cell(std::to_string(index) + "/" + std::to_string(count));
        csv.cell(k);
        writeRippleMapCells(csv, m, k);
        csv.end();
    }
    return out.str();
}

namespace {

// map, share, cell, then the map's own 11 columns.
constexpr std::size_t kShareColumns = 14;

// Why a cell stopped, from its word.
std::optional<RippleEnd> endNamed(const std::string& word) {
    for (const RippleEnd e : {RippleEnd::RunEnd, RippleEnd::Bottom, RippleEnd::Order, RippleEnd::Energy})
        if (word == rippleEndWord(e)) return e;
    return std::nullopt;
}

// One share read: its map's name, K and N, and its rows' cells (the map's
// own columns), or `error` set.
struct ShareRead {
    std::string name;
    int index = 0, count = 0;
    std::vector<std::pair<std::size_t, CsvRow>> cells;
};

std::optional<ShareRead> readShare(const std::string& file, const std::string& text, std::string& error) {
    const auto rows = readCsv(text, error);
    if (!rows) {
        error = file + ": " + error;
        return std::nullopt;
    }
    if (rows->size() < 2 || rows->front().size() != kShareColumns || rows->front()[0] != "map") {
        error = file + " is not a share of a map (jladder reach --cells K/N writes them)";
        return std::nullopt;
    }
    ShareRead s;
    for (std::size_t r = 1; r < rows->size(); ++r) {
        const CsvRow& row = (*rows)[r];
        const auto share = row.size() == kShareColumns ? shareOf(row[1]) : std::nullopt;
        const auto cell = row.size() == kShareColumns ? whole(row[2]) : std::nullopt;
        if (!share || !cell || (r > 1 && (row[0] != s.name || *share != std::pair{s.index, s.count}))) {
            error = file + ": row " + std::to_string(r + 1) + " is not a row of the share the first row names";
            return std::nullopt;
        }
        s.name = row[0];
        std::tie(s.index, s.count) = *share;
        s.cells.emplace_back(std::size_t(*cell), CsvRow(row.begin() + 3, row.end()));
    }
    return s;
}

// The cell of a share's row, checked against the map's own row for it.
std::optional<RippleReach> cellOf(const RippleMap& m, std::size_t k, const CsvRow& row) {
    // The map's own values of this cell, written as the map writes them.
    const RippleMap one{m.x, m.y, {m.xs[k % m.xs.size()]}, {m.ys[k / m.xs.size()]}, {RippleReach{}}, false};
    std::ostringstream expected;
    CsvWriter csv(expected);
    writeRippleMapCells(csv, one, 0);
    const auto own = [&] {
        std::string error;
        return readCsv(expected.str(), error);
    }();
    const auto h = whole(row[2]), reached = whole(row[3]), elsewhere = whole(row[5]), events = whole(row[6]),
               quick = whole(row[7]);
    const auto mean = row[4].empty() ? std::optional<double>(std::nan("")) : parseNumber(row[4]);
    const auto until = parseNumber(row[8]);
    const auto end = endNamed(row[9]);
    if (!own || own->front()[0] != row[0] || own->front()[1] != row[1] || !h || !reached || !elsewhere || !events ||
        !quick || !mean || !until || !end)
        return std::nullopt;
    RippleReach r;
    r.hinges = *h;
    r.reached = *reached;
    r.meanTimeBetweenFlips = *mean;
    r.flipsElsewhere = *elsewhere;
    r.events = *events;
    r.quickRow = *quick;
    r.until = *until;
    r.end = *end;
    r.failure = row[10];
    return r;
}

}  // namespace

JoinedMap joinRippleShares(const std::vector<std::pair<std::string, std::string>>& shares) {
    JoinedMap out;
    std::map<int, std::string> fileOf;  // share index -> its file
    std::string firstFile;
    std::optional<ShareRead> first;
    for (const auto& [file, text] : shares) {
        const auto s = readShare(file, text, out.error);
        if (!s) return out;
        if (!first) {
            first = s;
            firstFile = file;
            out.map = mapOfName(s->name);
            if (!out.map) return {std::nullopt, file + ": its map '" + s->name + "' is not one jladder reach makes"};
        }
        if (s->name != first->name || s->count != first->count)
            return {std::nullopt, file + " is share " + std::to_string(s->index) + " of " + std::to_string(s->count) +
                                      " of the map " + s->name + ", but " + firstFile + " is share " +
                                      std::to_string(first->index) + " of " + std::to_string(first->count) +
                                      " of the map " + first->name + ": give the shares of one map"};
        if (const auto [at, fresh] = fileOf.emplace(s->index, file); !fresh)
            return {std::nullopt, at->second + " and " + file + " are both share " + std::to_string(s->index) + " of " +
                                      std::to_string(s->count) + ": give each share once"};
        const auto [lo, hi] = shareCells(out.map->cells.size(), s->index, s->count);
        if (s->cells.size() != hi - lo)
            return {std::nullopt, file + " has " + std::to_string(s->cells.size()) + " cells; share " +
                                      std::to_string(s->index) + " of " + std::to_string(s->count) + " has " +
                                      std::to_string(hi - lo)};
        for (std::size_t c = 0; c < s->cells.size(); ++c) {
            const auto& [k, row] = s->cells[c];
            const auto r = k == lo + c ? cellOf(*out.map, k, row) : std::nullopt;
            if (!r)
                return {std::nullopt, file + ": row " + std::to_string(c + 2) + " is not cell " +
                                          std::to_string(lo + c) + " of the map it names"};
            out.map->cells[k] = *r;
        }
    }
    if (!first) return {std::nullopt, "no shares given"};
    for (int k = 1; k <= first->count; ++k)
        if (!fileOf.count(k))
            return {std::nullopt, "share " + std::to_string(k) + " of " + std::to_string(first->count) +
                                      " is missing: give every share of the map"};
    return out;
}

}  // namespace jl
