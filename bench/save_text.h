// A table, chart or report of the benchmark written whole or not at all
// (through a temporary renamed into place, every write and the close
// checked); a failure is said on stderr.
#pragma once

#include "jl/base/output_file.h"

#include <cstdio>
#include <filesystem>
#include <string>

namespace jl::bench {

inline bool saveText(const std::filesystem::path& path, const std::string& text) {
    const std::string error = writeWholeFile(path.string(), text);
    if (error.empty()) return true;
    std::fprintf(stderr, "jladder bench: %s: %s\n", path.string().c_str(), error.c_str());
    return false;
}

}  // namespace jl::bench
