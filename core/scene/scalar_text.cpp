// Numbers are written in the shortest form that reads back bit for bit, so a
// saved scene loads equal to the one in memory and files diff well.
#include "jl/scene/scalar_text.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <system_error>

namespace jl {

std::string formatNumber(double value) {
    char buffer[64];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::optional<double> parseNumber(std::string_view text, bool* outOfRange) {
    if (outOfRange) *outOfRange = false;
    // One sign: from_chars takes no '+', so it is dropped here, and a '-'
    // after it ("+-9.81") is a second sign, not a negative number.
    const bool plus = !text.empty() && text.front() == '+';
    if (plus) text.remove_prefix(1);
    // from_chars would accept "inf" and "nan"; a scene file must not.
    if (text.empty() || !(std::isdigit(static_cast<unsigned char>(text.front())) || text.front() == '.' ||
                          (text.front() == '-' && !plus)))
        return std::nullopt;
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error == std::errc::result_out_of_range) {
        if (outOfRange) *outOfRange = true;
        return std::nullopt;
    }
    if (error != std::errc{} || end != text.data() + text.size() || !std::isfinite(value)) return std::nullopt;
    return value;
}

std::optional<double> parseAngle(std::string_view text) {
    double scale = 1.0;
    if (text.ends_with("deg")) {
        scale = std::numbers::pi / 180.0;
        text.remove_suffix(3);
    } else if (text.ends_with("rad")) {
        text.remove_suffix(3);
    }
    const auto value = parseNumber(text);
    if (!value) return std::nullopt;
    const double radians = *value * scale;
    if (!std::isfinite(radians)) return std::nullopt;
    return radians;
}

std::string formatAngle(double radians) {
    // Most authored angles are whole or simple degrees; keep them readable
    // when that costs nothing in precision.
    const double degrees = std::round(radians * 180.0 / std::numbers::pi * 1e6) / 1e6;
    if (std::isfinite(degrees)) {
        const std::string text = formatNumber(degrees) + "deg";
        const auto back = parseAngle(text);
        if (back && *back == radians && text.size() <= 14) return text;
    }
    return formatNumber(radians);
}

namespace {

int hexDigit(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

}  // namespace

std::optional<Color> parseColor(std::string_view text) {
    if (text.size() != 7 || text[0] != '#') return std::nullopt;
    int channel[3];
    for (int i = 0; i < 3; ++i) {
        const int hi = hexDigit(text[1 + 2 * i]), lo = hexDigit(text[2 + 2 * i]);
        if (hi < 0 || lo < 0) return std::nullopt;
        channel[i] = hi * 16 + lo;
    }
    return Color{static_cast<std::uint8_t>(channel[0]), static_cast<std::uint8_t>(channel[1]),
                 static_cast<std::uint8_t>(channel[2])};
}

std::string formatColor(const Color& color) {
    char buffer[8];
    std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", color.r, color.g, color.b);
    return buffer;
}

}  // namespace jl
