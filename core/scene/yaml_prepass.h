// Checks a scene file's text before any YAML tree is built: encoding, syntax, duplicate keys, aliases, size.
#pragma once

#include "problems.h"

#include <cstddef>
#include <string_view>

namespace jl {

// The text must be UTF-8 without control characters other than tab, CR, LF.
// Returns false (after reporting) when it is not.
bool checkText(std::string_view text, Problems& problems);

// Streams the YAML events once, in constant memory per nesting level, so an
// absurd file is refused before yaml-cpp builds a tree for it. Duplicate keys
// are reported here because yaml-cpp 0.7 keeps both silently. Returns false
// when the file must not be read further (syntax error, alias, too many
// nodes, several documents, nothing at all); duplicates alone return true.
bool checkStructure(std::string_view text, std::size_t maxNodes, Problems& problems);

}  // namespace jl
