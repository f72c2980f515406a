#include "jl/base/xml_text.h"

#include <cstdint>
#include <cstdio>

namespace jl {

namespace {

// The next character of `s` from `i`: its code point and length in bytes,
// or length 0 when the bytes there are not UTF-8 (overlong forms and
// surrogates included).
struct Character {
    std::uint32_t code = 0;
    std::size_t length = 0;
};

Character decode(std::string_view s, std::size_t i) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(s[k]); };
    const unsigned char b0 = byte(i);
    if (b0 < 0x80) return {b0, 1};
    std::size_t n = 0;
    std::uint32_t code = 0, least = 0;
    if ((b0 & 0xE0) == 0xC0) {
        n = 2, code = b0 & 0x1F, least = 0x80;
    } else if ((b0 & 0xF0) == 0xE0) {
        n = 3, code = b0 & 0x0F, least = 0x800;
    } else if ((b0 & 0xF8) == 0xF0) {
        n = 4, code = b0 & 0x07, least = 0x10000;
    } else {
        return {};
    }
    if (i + n > s.size()) return {};
    for (std::size_t k = 1; k < n; ++k) {
        if ((byte(i + k) & 0xC0) != 0x80) return {};
        code = (code << 6) | (byte(i + k) & 0x3F);
    }
    if (code < least || code > 0x10FFFF || (code >= 0xD800 && code <= 0xDFFF)) return {};
    return {code, n};
}

// XML 1.0's Char production.
bool allowed(std::uint32_t c) {
    return c == 0x9 || c == 0xA || c == 0xD || (c >= 0x20 && c <= 0xD7FF) || (c >= 0xE000 && c <= 0xFFFD) ||
           (c >= 0x10000 && c <= 0x10FFFF);
}

}  // namespace

std::string xmlTextProblem(std::string_view text) {
    for (std::size_t i = 0; i < text.size();) {
        const Character c = decode(text, i);
        char what[96];
        if (c.length == 0) {
            std::snprintf(what, sizeof what, "byte 0x%02x at %zu is not UTF-8",
                          static_cast<unsigned>(static_cast<unsigned char>(text[i])), i + 1);
            return what;
        }
        if (!allowed(c.code)) {
            std::snprintf(what, sizeof what, "character U+%04X at %zu is one XML cannot hold",
                          static_cast<unsigned>(c.code), i + 1);
            return what;
        }
        i += c.length;
    }
    return {};
}

std::string xmlEscaped(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (std::size_t i = 0; i < text.size();) {
        const Character c = decode(text, i);
        if (c.length == 0 || !allowed(c.code)) {
            out += "\xEF\xBF\xBD";  // U+FFFD, the replacement character
            i += c.length == 0 ? 1 : c.length;
            continue;
        }
        const char ch = text[i];
        if (ch == '<')
            out += "&lt;";
        else if (ch == '>')
            out += "&gt;";
        else if (ch == '&')
            out += "&amp;";
        else if (ch == '\'')
            out += "&apos;";
        else if (ch == '"')
            out += "&quot;";
        else
            out.append(text.substr(i, c.length));
        i += c.length;
    }
    return out;
}

}  // namespace jl
