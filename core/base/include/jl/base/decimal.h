// A number as a person types it: a whole number of digits times a power of
// ten. Arithmetic on axes and units is done on these, and only the result is
// rounded to a double, so that 9 mm is the 0.009 m a scene file holding
// "0.009" reads, not 9 * 0.001 (0.009000000000000001).
#pragma once

#include <cstdint>
#include <optional>

namespace jl {

struct Decimal {
    std::int64_t digits = 0;
    int exponent = 0;  // the value is digits * 10^exponent
};

// The shortest decimal that reads back to x (the text std::to_chars gives);
// none for an infinity or a NaN.
std::optional<Decimal> shortestDecimal(double x);

// The double nearest the decimal: what reading its text gives.
double nearestDouble(const Decimal& d);

// a + i * step, exactly, then rounded once; none when the digits do not fit
// in 64 bits.
std::optional<Decimal> steppedDecimal(const Decimal& from, const Decimal& step, std::int64_t i);

}  // namespace jl
