// Text made safe inside an XML (SVG) element or quoted attribute: the one
// escape the SVG writers (the design map, the benchmark's charts) share.
#pragma once

#include <string>
#include <string_view>

namespace jl {

inline std::string xmlEscaped(std::string_view s) {
    std::string out;
    out.reserve(s.size());
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else if (c == '\'')
            out += "&apos;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

}  // namespace jl
