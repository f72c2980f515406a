#include "jl/design/ripple_map.h"

#include "jl/base/csv_writer.h"
#include "jl/base/xml_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <limits>
#include <sstream>
#include <thread>

namespace jl {

RippleMap computeRippleMap(const Scene& base, const DesignAxis& x, const DesignAxis& y, int jobs,
                           const std::atomic<bool>* cancel, const std::function<void(int, int)>& progress,
                           std::pair<std::size_t, std::size_t> cells, RippleStop stop) {
    RippleMap m{x, y, axisValues(x), axisValues(y), {}, false};
    m.cells.resize(m.xs.size() * m.ys.size());
    // A cell never started says so: cancelled until its run has written it.
    for (RippleReach& r : m.cells) r.cancelled = true;
    const size_t total = std::min(cells.second, m.cells.size());
    const size_t first = std::min(cells.first, total);
    std::atomic<size_t> next{first};
    std::atomic<int> done{0};
    auto work = [&] {
        for (size_t k = next++; k < total; k = next++) {
            if (cancel && cancel->load(std::memory_order_relaxed)) return;
            const size_t i = k % m.xs.size(), j = k / m.xs.size();
            const Scene s = withParameter(withParameter(base, x.parameter, m.xs[i]), y.parameter, m.ys[j]);
            // A design the engine cannot hold (memory for a huge ladder) is
            // that cell's failure, not the end of the program.
            try {
                m.cells[k] = firstRippleReach(s, cancel, std::numeric_limits<double>::infinity(), stop);
            } catch (const std::exception& e) {
                m.cells[k] = RippleReach{};
                m.cells[k].hinges = s.ladder ? s.ladder->blocks - 1 : 0;
                m.cells[k].failure = e.what();
            }
            const int d = ++done;
            if (progress) progress(d, int(total - first));
        }
    };
    if (jobs < 1) jobs = int(std::max(1u, std::thread::hardware_concurrency()));
    jobs = int(std::min<size_t>(size_t(jobs), std::max<size_t>(total - first, 1)));
    std::vector<std::thread> workers;
    for (int t = 1; t < jobs; ++t) workers.emplace_back(work);
    work();
    for (std::thread& t : workers) t.join();
    m.cancelled = cancel && cancel->load();
    return m;
}

namespace {

std::string fixed(double v, int digits) {
    char s[64];
    std::snprintf(s, sizeof s, "%.*f", digits, v);
    return s;
}

// Values on the map's picture: a count whole, else 6 significant digits (SI).
std::string value(DesignParameter p, double v) {
    if (p == DesignParameter::Blocks) return std::to_string(std::lround(v));
    char s[64];
    std::snprintf(s, sizeof s, "%.6g", v);
    return s;
}

bool isLength(DesignParameter p) {
    return p == DesignParameter::Thickness || p == DesignParameter::Length || p == DesignParameter::Width;
}

// Values as a reader of the map wants them: lengths in mm.
std::string shown(DesignParameter p, double v) { return value(p, isLength(p) ? 1000 * v : v); }

std::string axisTitle(const DesignAxis& a) {
    const DesignParameterWord& w = describe(a.parameter);
    const std::string unit = isLength(a.parameter) ? "mm" : std::string(w.unit);
    return std::string(w.label) + (unit.empty() ? "" : " (" + unit + ")");
}

// White (nothing flipped) through yellow to dark green (every hinge).
std::string colour(double fraction) {
    const double f = std::clamp(fraction, 0.0, 1.0);
    const int r = int(std::lround(255 - f * (255 - 26)));
    const int g = int(std::lround(255 - f * (255 - 120)));
    const int b = int(std::lround(224 - f * (224 - 50)));
    char s[8];
    std::snprintf(s, sizeof s, "#%02x%02x%02x", r, g, b);
    return s;
}

// Each column names its SI unit as the other tables do ("thickness [m]"); a count has none.
std::string columnOf(DesignParameter p) {
    const DesignParameterWord& w = describe(p);
    return std::string(w.word) + (w.unit.empty() ? "" : " [" + std::string(w.unit) + "]");
}

// A count whole; every other number the shortest text that reads back to
// the same double (jl/base/csv_writer.h): the design simulated, exactly.
void axisCell(CsvWriter& csv, DesignParameter p, double v) {
    if (p == DesignParameter::Blocks)
        csv.cell(std::lround(v));
    else
        csv.cell(v);
}

}  // namespace

// The counts of the run say how long they counted: until the cell stopped.
std::string rippleMapColumns(const RippleMap& m) {
    return columnOf(m.x.parameter) + ',' + columnOf(m.y.parameter) +
           ",hinges,reached,mean_time_between_flips [s],flips_elsewhere_until_stop,events_until_stop,"
           "quick_row_until_stop,stopped_at [s],stopped_by,failure";
}

void writeRippleMapCells(CsvWriter& csv, const RippleMap& m, std::size_t k) {
    const size_t i = k % m.xs.size(), j = k / m.xs.size();
    const RippleReach& r = m.cells[k];
    axisCell(csv, m.x.parameter, m.xs[i]);
    axisCell(csv, m.y.parameter, m.ys[j]);
    csv.cell(r.hinges);
    csv.cell(r.reached);
    csv.cell(r.meanTimeBetweenFlips);  // not finite (no two flips): an empty field
    csv.cell(r.flipsElsewhere);
    csv.cell(r.events);
    csv.cell(r.quickRow);
    csv.cell(r.until);
    csv.cell(rippleEndWord(r.end));
    csv.cell(r.cancelled ? "cancelled" : r.failure);
}

std::string rippleMapCsv(const RippleMap& m) {
    std::ostringstream out;
    out << rippleMapColumns(m) << '\n';
    CsvWriter csv(out);
    for (size_t k = 0; k < m.cells.size(); ++k) {
        writeRippleMapCells(csv, m, k);
        csv.end();
    }
    return out.str();
}

std::string rippleMapSvg(const RippleMap& m, const std::string& title) {
    constexpr double cell = 44, left = 110, top = 56, legendWidth = 150;
    const double width = left + cell * double(m.xs.size()) + 30 + legendWidth;
    const double height = top + cell * double(m.ys.size()) + 70;
    std::ostringstream s;
    s << "<svg xmlns='http://www.w3.org/2000/svg' width='" << fixed(width, 0) << "' height='" << fixed(height, 0)
      << "' font-family='sans-serif' font-size='12'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << "<text x='" << fixed(left, 0) << "' y='24' font-size='15'>" << xmlEscaped(title) << "</text>\n";
    // Rows from the bottom up, as a plot's y axis runs.
    for (size_t j = 0; j < m.ys.size(); ++j) {
        const double y0 = top + cell * double(m.ys.size() - 1 - j);
        s << "<text x='" << fixed(left - 8, 0) << "' y='" << fixed(y0 + cell / 2 + 4, 1) << "' text-anchor='end'>"
          << shown(m.y.parameter, m.ys[j]) << "</text>\n";
        for (size_t i = 0; i < m.xs.size(); ++i) {
            const RippleReach& r = m.at(i, j);
            const double x0 = left + cell * double(i);
            const double fraction = r.hinges > 0 ? double(r.reached) / r.hinges : 0;
            const bool failed = !r.failure.empty() || r.cancelled;
            s << "<rect x='" << fixed(x0, 1) << "' y='" << fixed(y0, 1) << "' width='" << fixed(cell, 0) << "' height='"
              << fixed(cell, 0) << "' fill='" << (failed ? "#d0d0d0" : colour(fraction)) << "' stroke='white'><title>"
              << r.reached << " of " << r.hinges << " hinges"
              << (failed ? "; " + xmlEscaped(r.cancelled ? "cancelled" : r.failure) : "") << "</title></rect>\n"
              << "<text x='" << fixed(x0 + cell / 2, 1) << "' y='" << fixed(y0 + cell / 2 + 4, 1)
              << "' text-anchor='middle' fill='" << (fraction > 0.6 ? "white" : "black") << "'>"
              << (failed ? std::string("!") : std::to_string(r.reached)) << "</text>\n";
        }
    }
    const double bottom = top + cell * double(m.ys.size());
    for (size_t i = 0; i < m.xs.size(); ++i)
        s << "<text x='" << fixed(left + cell * (double(i) + 0.5), 1) << "' y='" << fixed(bottom + 16, 1)
          << "' text-anchor='middle'>" << shown(m.x.parameter, m.xs[i]) << "</text>\n";
    s << "<text x='" << fixed(left + cell * double(m.xs.size()) / 2, 1) << "' y='" << fixed(bottom + 40, 1)
      << "' text-anchor='middle'>" << xmlEscaped(axisTitle(m.x)) << "</text>\n"
      << "<text transform='translate(18 " << fixed(top + cell * double(m.ys.size()) / 2, 1)
      << ") rotate(-90)' text-anchor='middle'>" << xmlEscaped(axisTitle(m.y)) << "</text>\n";
    // The legend: the fraction of hinges the first ripple flips.
    const double lx = left + cell * double(m.xs.size()) + 30;
    s << "<text x='" << fixed(lx, 1) << "' y='" << fixed(top - 8, 1) << "'>hinges flipped</text>\n";
    for (int k = 0; k <= 4; ++k) {
        const double f = 1.0 - k / 4.0, ly = top + 24 * k;
        s << "<rect x='" << fixed(lx, 1) << "' y='" << fixed(ly, 1) << "' width='20' height='20' fill='" << colour(f)
          << "' stroke='#999'/>\n<text x='" << fixed(lx + 28, 1) << "' y='" << fixed(ly + 14, 1) << "'>"
          << int(std::lround(100 * f)) << " %</text>\n";
    }
    s << "<rect x='" << fixed(lx, 1) << "' y='" << fixed(top + 24 * 5, 1)
      << "' width='20' height='20' fill='#d0d0d0' stroke='#999'/>\n<text x='" << fixed(lx + 28, 1) << "' y='"
      << fixed(top + 24 * 5 + 14, 1) << "'>run failed (!)</text>\n</svg>\n";
    return s.str();
}

}  // namespace jl
