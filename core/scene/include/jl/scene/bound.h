// The allowed range of a number, with the words that describe it: what the
// scene reader and the command line's options check numbers against.
#pragma once

#include <limits>
#include <string>

namespace jl {

struct Bound {
    double lo, hi;
    bool loOpen, hiOpen;
    static constexpr Bound any() {
        return {-std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), true, true};
    }
    static constexpr Bound positive() { return {0, std::numeric_limits<double>::infinity(), true, true}; }  // > 0
    static constexpr Bound nonNegative() { return {0, std::numeric_limits<double>::infinity(), false, true}; }
    static constexpr Bound halfOpen(double lo, double hi) { return {lo, hi, false, true}; }  // [lo, hi)
    static constexpr Bound closed(double lo, double hi) { return {lo, hi, false, false}; }   // [lo, hi]
    static constexpr Bound leftOpen(double lo, double hi) { return {lo, hi, true, false}; }  // (lo, hi]
    static constexpr Bound symmetric(double most) { return closed(-most, most); }            // [-most, most]
    bool contains(double x) const;
    std::string describe() const;  // "a number > 0", "a number in [0.0001, 100]"
};

}  // namespace jl
