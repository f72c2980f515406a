// Text made safe inside an XML (SVG) element or quoted attribute: the one
// escape the SVG writers (the design map, the benchmark's charts) share.
// XML 1.0 cannot hold every character, escaped or not: no C0 control but
// tab, line feed and carriage return, no U+FFFE or U+FFFF, and nothing that
// is not UTF-8. Text that may hold them (a title the user gave) is checked
// with xmlTextProblem and refused; xmlEscaped puts U+FFFD in their place,
// so that what it writes is always well-formed.
#pragma once

#include <string>
#include <string_view>

namespace jl {

// Why `text` cannot be written in XML ("byte 0x01 at 2 is a control
// character XML cannot hold"), or "" when it can.
std::string xmlTextProblem(std::string_view text);

// `text` with < > & ' " escaped, and U+FFFD for what XML cannot hold.
std::string xmlEscaped(std::string_view text);

}  // namespace jl
