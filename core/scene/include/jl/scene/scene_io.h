// Loading, validating and saving scene files (YAML, docs/scene-format.md); errors are values.
#pragma once

#include "jl/base/diagnostic.h"
#include "jl/scene/load_limits.h"
#include "jl/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jl {

// Either a whole scene (and no errors) or errors (and no scene): a load
// never half-applies.
struct SceneLoad {
    std::optional<Scene> scene;
    std::vector<Diagnostic> errors;  // in file order, file:line:column
};

SceneLoad loadScene(const std::string& path, const LoadLimits& limits = {});
// `fileNameForMessages` is what the diagnostics call the text.
SceneLoad parseScene(std::string_view text, const std::string& fileNameForMessages, const LoadLimits& limits = {});

// The file text: stable key order, only values that differ from the
// defaults (always `format`), numbers that read back bit for bit.
std::string sceneToYaml(const Scene& scene);

// Writes atomically (jl/base/output_file.h): a temporary file in the same
// directory, synced to disk, then renamed over `path` (a symbolic link stays
// a link to the new file). On failure the old file is untouched and the
// returned diagnostic says why.
std::optional<Diagnostic> saveScene(const Scene& scene, const std::string& path);

}  // namespace jl
