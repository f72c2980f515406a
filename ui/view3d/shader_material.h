// A Qt3D material running one of our GLSL 3.3 programs from resources/shaders,
// in the forward renderer's pass.
#pragma once

#include <QString>

namespace Qt3DCore {
class QNode;
}
namespace Qt3DRender {
class QMaterial;
}

namespace jl::ui {

// Registers resources/resources.qrc (compiled into this static library, so
// nothing registers it before first use); safe to call more than once.
void ensureResources();

enum class ShaderOptions {
    Solid,            // closed surfaces: back faces culled
    TwoSided,         // flat strips, seen from either side
    TwoSidedOnAFace,  // and drawn with a depth offset toward the eye, lying on a face without z-fighting
};

// Loads qrc:/shaders/<name>.vert and .frag (or <fragment>.frag, when given).
Qt3DRender::QMaterial* shaderMaterial(const QString& name, Qt3DCore::QNode* parent,
                                      ShaderOptions options = ShaderOptions::Solid, const QString& fragment = {});

}  // namespace jl::ui
