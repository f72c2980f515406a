// Checks a scene file's text before any YAML tree is built: encoding, syntax, duplicate keys, aliases, size.
#pragma once

#include "jl/scene/load_limits.h"
#include "problems.h"

#include <cstddef>
#include <string_view>

namespace jl {

// The text must be UTF-8 without control characters other than tab, CR, LF,
// and no line longer than limits.maxLineBytes (the YAML reader takes seconds
// over a line of tens of megabytes). Returns false (after reporting) when not.
bool checkText(std::string_view text, const LoadLimits& limits, Problems& problems);

// Streams the YAML events once, in constant memory per nesting level, so an
// absurd file is refused before yaml-cpp builds a tree for it. Duplicate keys
// are reported here because yaml-cpp 0.7 keeps both silently. Returns false
// when the file must not be read further (syntax error, alias, too many
// nodes or a value too long for limits, several documents, nothing at all);
// duplicates alone return true.
bool checkStructure(std::string_view text, const LoadLimits& limits, Problems& problems);

}  // namespace jl
