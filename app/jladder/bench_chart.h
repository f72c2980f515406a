// Line charts with logarithmic axes for the benchmark report, drawn the same
// way into SVG (text) and PNG (our own rasteriser, no plotting library).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jl::cli {

struct ChartSeries {
    std::string name;
    std::vector<std::pair<double, double>> points;  // (x, y); non-positive or NaN skipped
    bool dashed = false;
};

struct Chart {
    std::string title, xLabel, yLabel;
    std::vector<ChartSeries> series;
};

// Writes DIR/NAME.svg and DIR/NAME.png; false if a file could not be written.
bool writeChart(const Chart& chart, const std::filesystem::path& dir, const std::string& name);

}  // namespace jl::cli
