// Line charts with logarithmic axes for the benchmark report, as SVG (text,
// shown by any browser and by the repository's Markdown viewer).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace jl::bench {

struct ChartSeries {
    std::string name;
    std::vector<std::pair<double, double>> points;  // (x, y); non-positive or NaN skipped
    bool dashed = false;
};

struct Chart {
    std::string title, xLabel, yLabel;
    std::vector<ChartSeries> series;
};

// Writes DIR/NAME.svg; false if it could not be written.
bool writeChart(const Chart& chart, const std::filesystem::path& dir, const std::string& name);

}  // namespace jl::bench
