// Turns a parsed YAML tree into a Scene, checking every value and cross-reference.
#pragma once

#include <yaml-cpp/node/node.h>

#include <optional>

#include "core/problems.h"
#include "core/scene.h"
#include "core/scene_io.h"

namespace jl {

// Returns the scene only when no problem was found.
std::optional<Scene> readScene(const YAML::Node& root, const LoadLimits& limits, Problems& problems);

}  // namespace jl
