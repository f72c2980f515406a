#include "bench/chart.h"

#include "bench/save_text.h"
#include "jl/base/xml_text.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace jl::bench {

namespace {

struct Rgb {
    unsigned char r = 0, g = 0, b = 0;
};

constexpr int kWidth = 860, kHeight = 520;
constexpr double kLegend = 280;  // the legend's column at the right
constexpr double kPad = 12;      // between the picture's edge and any text
constexpr int kTitleSize = 14, kLabelSize = 12, kTickSize = 10;
constexpr Rgb kPalette[] = {{31, 119, 180}, {214, 39, 40},   {44, 160, 44},   {255, 127, 14}, {148, 103, 189},
                            {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};

std::string hex(Rgb c) {
    char s[8];
    std::snprintf(s, sizeof s, "#%02x%02x%02x", c.r, c.g, c.b);
    return s;
}

// Decades spanned by the finite positive values of one coordinate.
std::pair<int, int> decades(const Chart& c, bool x) {
    double lo = INFINITY, hi = -INFINITY;
    for (const ChartSeries& s : c.series)
        for (auto [px, py] : s.points) {
            const double v = x ? px : py;
            if (std::isfinite(v) && v > 0) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        }
    if (!std::isfinite(lo)) return {0, 1};
    int a = int(std::floor(std::log10(lo))), b = int(std::ceil(std::log10(hi)));
    if (b <= a) b = a + 1;
    return {a, b};
}

// Text extents. The raster font is the wider of the two renderings (the SVG's
// sans-serif runs about 0.55 em a character), so a layout that keeps the
// raster text apart keeps the SVG text apart too.
// How much room text takes in a sans-serif font, from the font size in px:
// an average advance of 0.55 em, letters 0.75 em tall (the viewer's font
// decides the rest; the layout keeps a margin for it).
double textWidth(const std::string& s, int size) { return 0.55 * size * double(s.size()); }
double textHeight(int size) { return 0.75 * size; }

// Where everything goes: one row each for the title and the y-axis label
// above the plot, the x tick labels and the x-axis label below it, the y
// tick labels in a column wide enough for the widest, and tick strides
// that keep neighbouring tick labels apart.
struct Layout {
    int titleSize = kTitleSize;
    double titleX = 0, titleY = 0, yLabelY = 0, xLabelY = 0, xTickY = 0;
    double left = 0, right = 0, top = 0, bottom = 0;
    int xStride = 1, yStride = 1;
};

Layout layout(const Chart& c, std::pair<int, int> xs, std::pair<int, int> ys) {
    Layout l;
    if (textWidth(c.title, kTitleSize) > kWidth - 2 * kPad) l.titleSize = kLabelSize;
    l.titleY = kPad + textHeight(l.titleSize) / 2;
    l.yLabelY = l.titleY + textHeight(l.titleSize) / 2 + 8 + textHeight(kLabelSize) / 2;
    l.top = l.yLabelY + textHeight(kLabelSize) / 2 + 8 + textHeight(kTickSize) / 2;
    l.xLabelY = kHeight - kPad - textHeight(kLabelSize) / 2;
    // The x tick labels sit 10 px below the axis, clear of the lowest y tick
    // label, which is centred on it.
    l.bottom = l.xLabelY - textHeight(kLabelSize) / 2 - 8 - textHeight(kTickSize) - 10;
    l.xTickY = l.bottom + 10 + textHeight(kTickSize) / 2;
    auto widest = [](std::pair<int, int> range) {
        double w = 0;
        for (int d = range.first; d <= range.second; ++d)
            w = std::max(w, textWidth("1e" + std::to_string(d), kTickSize));
        return w;
    };
    const double xWidest = widest(xs);
    // Room for the y tick labels, and for half of the first x tick label.
    l.left = std::max(kPad + widest(ys) + 6, kPad + xWidest / 2);
    // The legend: a 24 px line, a 6 px gap and the longest name, inside the picture.
    double names = 0;
    for (const ChartSeries& series : c.series) names = std::max(names, textWidth(series.name, kTickSize));
    l.right = kWidth - std::max(kLegend, 16 + 24 + 6 + names + kPad);
    const double xStep = (l.right - l.left) / (xs.second - xs.first),
                 yStep = (l.bottom - l.top) / (ys.second - ys.first);
    while (l.xStride * xStep < xWidest + 8) ++l.xStride;
    while (l.yStride * yStep < textHeight(kTickSize) + 4) ++l.yStride;
    const double half = textWidth(c.title, l.titleSize) / 2;
    l.titleX = std::clamp((l.left + l.right) / 2, kPad + half, std::max(kPad + half, kWidth - kPad - half));
    return l;
}

// SVG elements, one per line.
struct SvgPen {
    std::ostringstream out;
    void line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) {
        out << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x1 << "' y2='" << y1 << "' stroke='" << hex(c)
            << "' stroke-width='" << width << "'" << (dashed ? " stroke-dasharray='6 4'" : "") << "/>\n";
    }
    void dot(double x, double y, Rgb c) {
        out << "<circle cx='" << x << "' cy='" << y << "' r='3' fill='" << hex(c) << "'/>\n";
    }
    void text(double x, double y, const std::string& s, int size, int anchor, Rgb c) {
        static const char* anchors[] = {"start", "middle", "end"};
        out << "<text x='" << x << "' y='" << y + size / 3.0 << "' font-size='" << size << "' text-anchor='"
            << anchors[anchor] << "' fill='" << hex(c) << "'>" << xmlEscaped(s) << "</text>\n";
    }
};

void draw(const Chart& c, SvgPen& pen) {
    const auto [x0, x1] = decades(c, true);
    const auto [y0, y1] = decades(c, false);
    const Layout l = layout(c, {x0, x1}, {y0, y1});
    const double pw = l.right - l.left, ph = l.bottom - l.top;
    auto X = [&](double v) { return l.left + (std::log10(v) - x0) / (x1 - x0) * pw; };
    auto Y = [&](double v) { return l.top + ph - (std::log10(v) - y0) / (y1 - y0) * ph; };
    const Rgb grid{225, 225, 225}, ink{40, 40, 40};
    for (int d = x0; d <= x1; d += l.xStride) {
        pen.line(X(std::pow(10, d)), l.top, X(std::pow(10, d)), l.bottom, grid, 1, false);
        pen.text(X(std::pow(10, d)), l.xTickY, "1e" + std::to_string(d), kTickSize, 1, ink);
    }
    for (int d = y0; d <= y1; d += l.yStride) {
        pen.line(l.left, Y(std::pow(10, d)), l.right, Y(std::pow(10, d)), grid, 1, false);
        pen.text(l.left - 6, Y(std::pow(10, d)), "1e" + std::to_string(d), kTickSize, 2, ink);
    }
    pen.line(l.left, l.bottom, l.right, l.bottom, ink, 1, false);
    pen.line(l.left, l.top, l.left, l.bottom, ink, 1, false);
    pen.text(l.titleX, l.titleY, c.title, l.titleSize, 1, ink);
    pen.text((l.left + l.right) / 2, l.xLabelY, c.xLabel, kLabelSize, 1, ink);
    pen.text(kPad, l.yLabelY, c.yLabel, kLabelSize, 0, ink);
    int index = 0;
    for (const ChartSeries& s : c.series) {
        const Rgb colour = kPalette[size_t(index) % std::size(kPalette)];
        std::vector<std::pair<double, double>> pts;
        for (auto p : s.points)
            if (std::isfinite(p.first) && std::isfinite(p.second) && p.first > 0 && p.second > 0) pts.push_back(p);
        std::sort(pts.begin(), pts.end());
        for (size_t i = 0; i + 1 < pts.size(); ++i)
            pen.line(X(pts[i].first), Y(pts[i].second), X(pts[i + 1].first), Y(pts[i + 1].second), colour, 2, s.dashed);
        for (auto p : pts) pen.dot(X(p.first), Y(p.second), colour);
        const double ly = l.top + 10 + 18 * index;
        pen.line(l.right + 16, ly, l.right + 40, ly, colour, 2, s.dashed);
        pen.text(l.right + 46, ly, s.name, kTickSize, 0, ink);
        ++index;
    }
}

}  // namespace

bool writeChart(const Chart& chart, const std::filesystem::path& dir, const std::string& name) {
    SvgPen svg;
    draw(chart, svg);
    std::ostringstream f;
    f << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kWidth << "' height='" << kHeight
      << "' font-family='sans-serif'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << svg.out.str() << "</svg>\n";
    return saveText(dir / (name + ".svg"), f.str());
}

}  // namespace jl::bench
