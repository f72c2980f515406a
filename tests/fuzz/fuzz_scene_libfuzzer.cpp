// libFuzzer entry for the scene loader: any bytes must give a scene or errors, never a crash.
#include "jl/scene/scene_io.h"

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    const jl::SceneLoad load = jl::parseScene(text, "fuzz.yaml");
    if (load.scene.has_value() == !load.errors.empty()) std::abort();  // exactly one of the two
    if (load.scene) {
        // A scene that loads must save and load back equal.
        const jl::SceneLoad back = jl::parseScene(jl::sceneToYaml(*load.scene), "saved.yaml");
        if (!back.scene || !(*back.scene == *load.scene)) std::abort();
    }
    return 0;
}
