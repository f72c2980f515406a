// The text forms of numbers, angles and colours in scene files, shared by the reader and the writer.
#pragma once

#include "jl/scene/scene.h"

#include <optional>
#include <string>
#include <string_view>

namespace jl {

// Shortest text that reads back as exactly the same double ("0.06", "1e-10").
std::string formatNumber(double value);

// Strict parse of a whole decimal number; no "inf"/"nan", no trailing text.
// Sets `outOfRange` when the text is a number too large for a double.
std::optional<double> parseNumber(std::string_view text, bool* outOfRange = nullptr);

// An angle: a number of radians, or a number followed by "deg" or "rad".
std::optional<double> parseAngle(std::string_view text);
// Degrees ("180deg") when that reads back exactly, else radians.
std::string formatAngle(double radians);

// "#rrggbb", either case.
std::optional<Color> parseColor(std::string_view text);
std::string formatColor(const Color& color);

}  // namespace jl
