// Turns a parsed YAML tree into a Scene, checking every value and cross-reference.
#pragma once

#include "jl/scene/load_limits.h"
#include "jl/scene/scene.h"
#include "problems.h"

#include <yaml-cpp/node/node.h>

#include <optional>

namespace jl {

// Returns the scene only when no problem was found.
std::optional<Scene> readScene(const YAML::Node& root, const LoadLimits& limits, Problems& problems);

}  // namespace jl
