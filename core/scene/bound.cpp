#include "jl/scene/bound.h"

#include "jl/scene/scalar_text.h"

#include <charconv>
#include <cmath>

namespace jl {

namespace {

// As a person writes a limit: 100000 and 0.0001, but 1e-6 and 1e7 (no
// "1e+05" or "1e-06").
std::string limitText(double x) {
    const double magnitude = std::abs(x);
    if (magnitude == 0 || (magnitude >= 1e-4 && magnitude < 1e6)) {
        char buffer[64];
        const auto end = std::to_chars(buffer, buffer + sizeof buffer, x, std::chars_format::fixed).ptr;
        return std::string(buffer, end);
    }
    std::string text = formatNumber(x);  // shortest, may be "1e-06"
    const auto e = text.find('e');
    if (e == std::string::npos) return text;
    std::size_t digits = e + 1;
    if (digits < text.size() && text[digits] == '+') text.erase(digits, 1);
    if (digits < text.size() && text[digits] == '-') ++digits;
    while (digits + 1 < text.size() && text[digits] == '0') text.erase(digits, 1);
    return text;
}

}  // namespace

bool Bound::contains(double x) const { return (loOpen ? x > lo : x >= lo) && (hiOpen ? x < hi : x <= hi); }

std::string Bound::describe() const {
    const bool hasLo = std::isfinite(lo), hasHi = std::isfinite(hi);
    if (!hasLo && !hasHi) return "a number";
    if (!hasHi) return std::string("a number ") + (loOpen ? "> " : ">= ") + limitText(lo);
    if (!hasLo) return std::string("a number ") + (hiOpen ? "< " : "<= ") + limitText(hi);
    return "a number in " + std::string(loOpen ? "(" : "[") + limitText(lo) + ", " + limitText(hi) +
           (hiOpen ? ")" : "]");
}

}  // namespace jl
