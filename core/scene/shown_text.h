// Text from a scene file as a message shows it: characters that print as
// nothing (a zero-width space, a byte-order mark, a control) written as
// escapes, so that "unknown key 'format'; did you mean 'format'?" cannot
// happen.
#pragma once

#include <string>
#include <string_view>

namespace jl {

// `text` with every invisible character written \uXXXX (controls below
// U+0020 as \xXX); valid UTF-8 assumed (the loader has checked it).
std::string shownText(std::string_view text);

}  // namespace jl
