// The design map: the first ripple's reach over two design parameters, one
// simulation per cell (stopped once its reach is settled, or run whole), the cells shared among worker threads (each
// run on one thread). The map is the same whatever the number of threads: each cell depends on its own design only and
// is written at its own index.
#pragma once

#include "jl/design/design_axis.h"
#include "jl/design/ripple_reach.h"

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace jl {

class CsvWriter;

struct RippleMap {
    DesignAxis x, y;
    std::vector<double> xs, ys;      // the axes' values
    std::vector<RippleReach> cells;  // row by row: cell (i, j) at j * xs.size() + i
    bool cancelled = false;          // then some cells say cancelled: cut short or never run
    const RippleReach& at(size_t i, size_t j) const { return cells[j * xs.size() + i]; }
};

// `progress(done, total)` is called from the workers as cells finish (it must
// be thread-safe); `cancel` is polled by every run. jobs < 1: one per core.
// A run that throws (no memory for a huge ladder) is its cell's failure.
// `cells` [first, last) limits the work to those cells (a share of the map,
// jl/design/map_share.h); the others stay cancelled, never run.
RippleMap computeRippleMap(const Scene& base, const DesignAxis& x, const DesignAxis& y, int jobs,
                           const std::atomic<bool>* cancel = nullptr,
                           const std::function<void(int done, int total)>& progress = {},
                           std::pair<std::size_t, std::size_t> cells = {0, SIZE_MAX},
                           RippleStop stop = RippleStop::WhenSettled);

// One row per cell: the two values (SI), the hinges, how many the first ripple
// flipped, the mean time between flips, then up to the cell's stop the flips
// elsewhere, events and chatter, the stop's time and why, failure. Each
// number the shortest text that reads back to it: the same map gives the same bytes.
std::string rippleMapCsv(const RippleMap& m);
// Its header line's columns, and the columns of cell k's row (no line end).
std::string rippleMapColumns(const RippleMap& m);
void writeRippleMapCells(CsvWriter& csv, const RippleMap& m, std::size_t k);

// A heat map: each cell coloured by the fraction of the hinges the first
// ripple flips and labelled with that count, axes with their units, a legend.
std::string rippleMapSvg(const RippleMap& m, const std::string& title);

}  // namespace jl
