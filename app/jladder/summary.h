// The JSON summary `jladder run` prints of a recorded run (jl/sim/recording.h).
#pragma once

#include "jl/sim/recording.h"

#include <string>

namespace jl::cli {

std::string summaryJson(const Recording& r, const std::string& scenePath);

}  // namespace jl::cli
