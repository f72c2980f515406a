#include "app/jladder/bench_png.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <zlib.h>

namespace jl::cli {

namespace {

// 3x5 glyphs, one row per 3 bits, top row first (bit 2 = left column).
struct Glyph {
    char c;
    std::array<std::uint8_t, 5> rows;
};
constexpr Glyph kFont[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'a', {2, 5, 7, 5, 5}}, {'b', {6, 5, 6, 5, 6}},
    {'c', {3, 4, 4, 4, 3}}, {'d', {6, 5, 5, 5, 6}}, {'e', {7, 4, 6, 4, 7}}, {'f', {7, 4, 6, 4, 4}},
    {'g', {3, 4, 5, 5, 3}}, {'h', {5, 5, 7, 5, 5}}, {'i', {7, 2, 2, 2, 7}}, {'j', {1, 1, 1, 5, 2}},
    {'k', {5, 5, 6, 5, 5}}, {'l', {4, 4, 4, 4, 7}}, {'m', {5, 7, 7, 5, 5}}, {'n', {6, 5, 5, 5, 5}},
    {'o', {2, 5, 5, 5, 2}}, {'p', {6, 5, 6, 4, 4}}, {'q', {2, 5, 5, 6, 3}}, {'r', {6, 5, 6, 5, 5}},
    {'s', {3, 4, 2, 1, 6}}, {'t', {7, 2, 2, 2, 2}}, {'u', {5, 5, 5, 5, 7}}, {'v', {5, 5, 5, 5, 2}},
    {'w', {5, 5, 7, 7, 5}}, {'x', {5, 5, 2, 5, 5}}, {'y', {5, 5, 2, 2, 2}}, {'z', {7, 1, 2, 4, 7}},
    {'-', {0, 0, 7, 0, 0}}, {'.', {0, 0, 0, 0, 2}}, {'_', {0, 0, 0, 0, 7}}, {'(', {2, 4, 4, 4, 2}},
    {')', {2, 1, 1, 1, 2}}, {'/', {1, 1, 2, 4, 4}}, {'=', {0, 7, 0, 7, 0}}, {',', {0, 0, 0, 2, 4}},
    {':', {0, 2, 0, 2, 0}}, {'+', {0, 2, 7, 2, 0}}, {'%', {5, 1, 2, 4, 5}}, {'*', {0, 5, 2, 5, 0}},
    {'^', {2, 5, 0, 0, 0}}, {'<', {1, 2, 4, 2, 1}}, {'>', {4, 2, 1, 2, 4}},
};

const Glyph* glyph(char c) {
    const char lower = char(std::tolower(static_cast<unsigned char>(c)));
    for (const Glyph& g : kFont)
        if (g.c == lower) return &g;
    return nullptr;
}

void put32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) out.push_back(std::uint8_t(v >> s));
}

void chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
    put32(out, std::uint32_t(data.size()));
    std::vector<std::uint8_t> body(type, type + 4);
    body.insert(body.end(), data.begin(), data.end());
    out.insert(out.end(), body.begin(), body.end());
    put32(out, std::uint32_t(::crc32(0, body.data(), uInt(body.size()))));
}

}  // namespace

Raster::Raster(int width, int height, Rgb background)
    : width_(width), height_(height), pixels_(size_t(width) * size_t(height), background) {}

void Raster::set(int x, int y, Rgb c) {
    if (x >= 0 && y >= 0 && x < width_ && y < height_) pixels_[size_t(y) * size_t(width_) + size_t(x)] = c;
}

void Raster::line(double x0, double y0, double x1, double y1, Rgb c, double thickness, bool dashed) {
    const double length = std::hypot(x1 - x0, y1 - y0);
    const int steps = std::max(1, int(std::ceil(length * 2)));
    const int r = std::max(0, int(std::lround(thickness / 2 - 0.5)));
    for (int i = 0; i <= steps; ++i) {
        const double s = double(i) / steps;
        if (dashed && std::fmod(s * length, 10.0) > 6.0) continue;
        const int x = int(std::lround(x0 + s * (x1 - x0))), y = int(std::lround(y0 + s * (y1 - y0)));
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx) set(x + dx, y + dy, c);
    }
}

void Raster::dot(double x, double y, double radius, Rgb c) {
    const int r = int(std::ceil(radius));
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
            if (dx * dx + dy * dy <= radius * radius) set(int(std::lround(x)) + dx, int(std::lround(y)) + dy, c);
}

void Raster::text(double x, double y, const std::string& s, int scale, int anchor, Rgb c) {
    int left = int(std::lround(x)) - (anchor == 1 ? textWidth(s, scale) / 2 : anchor == 2 ? textWidth(s, scale) : 0);
    const int top = int(std::lround(y)) - 5 * scale / 2;
    for (char ch : s) {
        if (const Glyph* g = glyph(ch))
            for (int row = 0; row < 5; ++row)
                for (int col = 0; col < 3; ++col)
                    if (g->rows[size_t(row)] & (4 >> col))
                        for (int dy = 0; dy < scale; ++dy)
                            for (int dx = 0; dx < scale; ++dx) set(left + col * scale + dx, top + row * scale + dy, c);
        left += 4 * scale;
    }
}

// PNG: 8-bit RGB, filter 0 per row, the rows deflated by zlib (a plot of
// flat colours shrinks ~50x, which keeps docs/ small).
bool Raster::savePng(const std::filesystem::path& path) const {
    std::vector<std::uint8_t> raw;
    raw.reserve(size_t(height_) * (1 + 3 * size_t(width_)));
    for (int y = 0; y < height_; ++y) {
        raw.push_back(0);
        for (int x = 0; x < width_; ++x) {
            const Rgb& p = pixels_[size_t(y) * size_t(width_) + size_t(x)];
            raw.insert(raw.end(), {p.r, p.g, p.b});
        }
    }
    uLongf size = compressBound(uLong(raw.size()));
    std::vector<std::uint8_t> z(size);
    if (compress2(z.data(), &size, raw.data(), uLong(raw.size()), Z_BEST_COMPRESSION) != Z_OK) return false;
    z.resize(size);
    std::vector<std::uint8_t> png{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    std::vector<std::uint8_t> header;
    put32(header, std::uint32_t(width_));
    put32(header, std::uint32_t(height_));
    header.insert(header.end(), {8, 2, 0, 0, 0});
    chunk(png, "IHDR", header);
    chunk(png, "IDAT", z);
    chunk(png, "IEND", {});
    std::ofstream f(path, std::ios::binary);
    f.write(reinterpret_cast<const char*>(png.data()), std::streamsize(png.size()));
    return bool(f);
}

}  // namespace jl::cli
