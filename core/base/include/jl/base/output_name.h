// What a name given for an output stands for, resolved once and the same way
// for the check that an output is not the input (or another output) and for
// the writer (jl/base/output_file.h): were they to resolve it differently, a
// name the check passed could make the writer replace the input.
#pragma once

#include <optional>
#include <string>

namespace jl {

struct OutputName {
    // The name a rename replaces, every symbolic link followed (the last one
    // may point to a file not made yet), in a directory given without links;
    // or, for one of the process's open descriptors, the name that gave it.
    std::string path;
    std::optional<int> descriptor;  // /dev/stdout, /dev/fd/N, /proc/self/fd/N
    // errno when the name cannot be resolved (ELOOP: more than 40 links, or
    // a loop; ENOTDIR, EACCES, ENAMETOOLONG): such a name is refused, since
    // no one can say which file writing it would replace.
    int error = 0;
};

OutputName resolveOutputName(const std::string& path);

// The same file, or, for names of files not made yet, the same name.
// False when either cannot be resolved (refuse those first).
bool sameOutput(const OutputName& a, const OutputName& b);

}  // namespace jl
