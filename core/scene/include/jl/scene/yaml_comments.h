// Whether a scene file's text holds YAML comments. The writer cannot keep
// them (it writes the scene, not the text), so the desktop program asks
// before it saves over a file that has some.
#pragma once

#include <string_view>

namespace jl {

// A '#' at the start of a line or after a space or tab, outside quotes.
bool hasComments(std::string_view yamlText);

}  // namespace jl
