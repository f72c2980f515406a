#include "app/jladder/bench_chart.h"

#include "app/jladder/bench_png.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace jl::cli {

namespace {

constexpr int kWidth = 860, kHeight = 520;
constexpr double kLeft = 80, kRight = 280, kTop = 40, kBottom = 60;  // margins; the legend sits right
constexpr Rgb kPalette[] = {{31, 119, 180}, {214, 39, 40},  {44, 160, 44},  {255, 127, 14}, {148, 103, 189},
                            {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};

std::string hex(Rgb c) {
    char s[8];
    std::snprintf(s, sizeof s, "#%02x%02x%02x", c.r, c.g, c.b);
    return s;
}

std::string escape(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<') out += "&lt;";
        else if (c == '>') out += "&gt;";
        else if (c == '&') out += "&amp;";
        else out += c;
    }
    return out;
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

// Everything drawn, as calls on an abstract pen, so SVG and PNG agree.
struct Pen {
    virtual ~Pen() = default;
    virtual void line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) = 0;
    virtual void dot(double x, double y, Rgb c) = 0;
    virtual void text(double x, double y, const std::string& s, int size, int anchor, Rgb c) = 0;
};

void draw(const Chart& c, Pen& pen) {
    const auto [x0, x1] = decades(c, true);
    const auto [y0, y1] = decades(c, false);
    const double pw = kWidth - kLeft - kRight, ph = kHeight - kTop - kBottom;
    auto X = [&](double v) { return kLeft + (std::log10(v) - x0) / (x1 - x0) * pw; };
    auto Y = [&](double v) { return kTop + ph - (std::log10(v) - y0) / (y1 - y0) * ph; };
    const Rgb grid{225, 225, 225}, ink{40, 40, 40};
    const int xStride = (x1 - x0) > 8 ? 2 : 1, yStride = (y1 - y0) > 10 ? 2 : 1;
    for (int d = x0; d <= x1; d += xStride) {
        pen.line(X(std::pow(10, d)), kTop, X(std::pow(10, d)), kTop + ph, grid, 1, false);
        pen.text(X(std::pow(10, d)), kTop + ph + 14, "1e" + std::to_string(d), 10, 1, ink);
    }
    for (int d = y0; d <= y1; d += yStride) {
        pen.line(kLeft, Y(std::pow(10, d)), kLeft + pw, Y(std::pow(10, d)), grid, 1, false);
        pen.text(kLeft - 6, Y(std::pow(10, d)), "1e" + std::to_string(d), 10, 2, ink);
    }
    pen.line(kLeft, kTop + ph, kLeft + pw, kTop + ph, ink, 1, false);
    pen.line(kLeft, kTop, kLeft, kTop + ph, ink, 1, false);
    pen.text(kLeft + pw / 2, 20, c.title, 14, 1, ink);
    pen.text(kLeft + pw / 2, kHeight - 18, c.xLabel, 12, 1, ink);
    pen.text(12, kTop - 14, c.yLabel, 12, 0, ink);
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
        const double ly = kTop + 10 + 18 * index;
        pen.line(kWidth - kRight + 16, ly, kWidth - kRight + 40, ly, colour, 2, s.dashed);
        pen.text(kWidth - kRight + 46, ly, s.name, 10, 0, ink);
        ++index;
    }
}

struct SvgPen : Pen {
    std::ostringstream out;
    void line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) override {
        out << "<line x1='" << x0 << "' y1='" << y0 << "' x2='" << x1 << "' y2='" << y1 << "' stroke='" << hex(c)
            << "' stroke-width='" << width << "'" << (dashed ? " stroke-dasharray='6 4'" : "") << "/>\n";
    }
    void dot(double x, double y, Rgb c) override {
        out << "<circle cx='" << x << "' cy='" << y << "' r='3' fill='" << hex(c) << "'/>\n";
    }
    void text(double x, double y, const std::string& s, int size, int anchor, Rgb c) override {
        static const char* anchors[] = {"start", "middle", "end"};
        out << "<text x='" << x << "' y='" << y + size / 3.0 << "' font-size='" << size << "' text-anchor='"
            << anchors[anchor] << "' fill='" << hex(c) << "'>" << escape(s) << "</text>\n";
    }
};

struct RasterPen : Pen {
    Raster raster{kWidth, kHeight, Rgb{255, 255, 255}};
    void line(double x0, double y0, double x1, double y1, Rgb c, double width, bool dashed) override {
        raster.line(x0, y0, x1, y1, c, width, dashed);
    }
    void dot(double x, double y, Rgb c) override { raster.dot(x, y, 3, c); }
    void text(double x, double y, const std::string& s, int size, int anchor, Rgb c) override {
        raster.text(x, y, s, size >= 14 ? 3 : 2, anchor, c);
    }
};

}  // namespace

bool writeChart(const Chart& chart, const std::filesystem::path& dir, const std::string& name) {
    SvgPen svg;
    draw(chart, svg);
    std::ofstream f(dir / (name + ".svg"));
    f << "<svg xmlns='http://www.w3.org/2000/svg' width='" << kWidth << "' height='" << kHeight
      << "' font-family='sans-serif'>\n<rect width='100%' height='100%' fill='white'/>\n"
      << svg.out.str() << "</svg>\n";
    RasterPen png;
    draw(chart, png);
    return bool(f) && png.raster.savePng(dir / (name + ".png"));
}

}  // namespace jl::cli
