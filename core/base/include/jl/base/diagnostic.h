// A problem found in an input file, located by line and column (both 1-based).
#pragma once

#include <string>

namespace jl {

struct Diagnostic {
    std::string file;
    int line = 0;    // 1-based; 0 when the problem concerns the whole file
    int column = 0;  // 1-based; 0 when the problem concerns the whole file
    std::string message;

    // "file:line:column: message", the form compilers use, so editors can
    // jump to it; a whole-file problem reads "file: message".
    std::string format() const {
        if (line <= 0) return file + ": " + message;
        return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": " + message;
    }
    bool operator==(const Diagnostic&) const = default;
};

}  // namespace jl
