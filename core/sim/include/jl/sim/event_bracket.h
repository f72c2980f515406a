// Narrowing the instant an event function turns negative inside a step:
// regula falsi with the Illinois correction (a few trials where halving
// takes twenty), halving when the low end's value is not strictly positive.
#pragma once

#include <algorithm>

namespace jl {

// f(lo) = flo >= 0 (the event has not happened), f(hi) = fhi < 0 (it has).
struct EventBracket {
    double lo = 0, flo = 0, hi = 0, fhi = 0;
    double width() const { return hi - lo; }
};

// Shrinks b until its width is at most `tolerance`; f(x) gives the event
// function at x (negative when the event has happened). Returns the trials made.
template <class F>
int narrow(EventBracket& b, double tolerance, F&& f) {
    int trials = 0;
    int kept = 0;  // which end stayed put last time: -1 low, +1 high
    while (b.width() > tolerance) {
        const double width = b.width();
        double mid = b.flo > 0 ? b.hi - b.fhi * width / (b.fhi - b.flo) : b.lo + 0.5 * width;
        if (!(mid > b.lo && mid < b.hi)) mid = b.lo + 0.5 * width;
        mid = std::clamp(mid, b.lo + 0.25 * tolerance, b.hi - 0.25 * tolerance);
        const double fm = f(mid);
        ++trials;
        if (fm < 0) {
            b.hi = mid;
            b.fhi = fm;
            if (kept == -1) b.flo *= 0.5;
            kept = -1;
        } else {
            b.lo = mid;
            b.flo = fm;
            if (kept == 1) b.fhi *= 0.5;
            kept = 1;
        }
    }
    return trials;
}

}  // namespace jl
