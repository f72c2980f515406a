// A measurement as a message quotes it: three significant digits ("1.65e+08",
// "0.00369"), enough to act on and short enough to read.
#pragma once

#include <cstdio>
#include <string>

namespace jl {

inline std::string shortNumber(double x) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", x);
    return text;
}

}  // namespace jl
