#include "jl/base/decimal.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <system_error>

namespace jl {

std::optional<Decimal> shortestDecimal(double x) {
    if (!std::isfinite(x)) return std::nullopt;
    char text[64];
    const auto written = std::to_chars(text, text + sizeof text, x, std::chars_format::scientific);
    // "-d.ddde+XX": the digits without the point, the exponent less one per
    // digit after the point.
    Decimal d;
    const char* p = text;
    const bool negative = *p == '-';
    if (negative) ++p;
    int after = -1;  // digits after the point, once the point is passed
    for (; p < written.ptr && *p != 'e'; ++p) {
        if (*p == '.') {
            after = 0;
            continue;
        }
        d.digits = 10 * d.digits + (*p - '0');
        if (after >= 0) ++after;
    }
    std::from_chars(p + 1 + (p[1] == '+'), written.ptr, d.exponent);
    d.exponent -= std::max(after, 0);
    if (negative) d.digits = -d.digits;
    return d;
}

double nearestDouble(const Decimal& d) {
    char text[64];
    std::snprintf(text, sizeof text, "%lde%d", static_cast<long>(d.digits), d.exponent);
    // strtod rounds correctly (glibc), and past the range gives an infinity
    // or zero where from_chars gives nothing.
    return std::strtod(text, nullptr);
}

namespace {

// digits * 10^shift, or none past 64 bits.
std::optional<std::int64_t> shifted(std::int64_t digits, int shift) {
    for (; shift > 0; --shift)
        if (__builtin_mul_overflow(digits, std::int64_t{10}, &digits)) return std::nullopt;
    return digits;
}

}  // namespace

std::optional<Decimal> steppedDecimal(const Decimal& from, const Decimal& step, std::int64_t i) {
    const int exponent = std::min(from.exponent, step.exponent);
    const auto a = shifted(from.digits, from.exponent - exponent);
    const auto s = shifted(step.digits, step.exponent - exponent);
    std::int64_t is = 0, sum = 0;
    if (!a || !s || __builtin_mul_overflow(i, *s, &is) || __builtin_add_overflow(*a, is, &sum)) return std::nullopt;
    return Decimal{sum, exponent};
}

}  // namespace jl
