// Turns a parsed YAML tree into a Scene, checking every value and cross-reference.
#pragma once

#include <yaml-cpp/node/node.h>

#include <optional>

#include "jl/scene/scene.h"
#include "jl/scene/load_limits.h"
#include "problems.h"

namespace jl {

// Returns the scene only when no problem was found.
std::optional<Scene> readScene(const YAML::Node& root, const LoadLimits& limits, Problems& problems);

}  // namespace jl
