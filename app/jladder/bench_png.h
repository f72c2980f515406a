// A small RGB raster with lines, dots and a 3x5 pixel font, saved as PNG
// (the rows deflated with zlib).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace jl::cli {

struct Rgb {
    std::uint8_t r = 0, g = 0, b = 0;
};

class Raster {
public:
    Raster(int width, int height, Rgb background);
    void line(double x0, double y0, double x1, double y1, Rgb c, double thickness, bool dashed = false);
    void dot(double x, double y, double radius, Rgb c);
    // Text of height 5*scale pixels; anchor 0 left, 1 centre, 2 right at x.
    void text(double x, double y, const std::string& s, int scale, int anchor, Rgb c);
    static int textWidth(const std::string& s, int scale) { return int(s.size()) * 4 * scale; }
    bool savePng(const std::filesystem::path& path) const;

private:
    void set(int x, int y, Rgb c);
    int width_, height_;
    std::vector<Rgb> pixels_;
};

}  // namespace jl::cli
