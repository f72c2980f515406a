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

namespace jlui {

// Loads qrc:/shaders/<name>.vert and .frag. `pullForward`: drawn with a depth
// offset toward the eye, for strips lying on a face (no z-fighting).
// Registers resources/resources.qrc (compiled into this static library, so
// nothing registers it before first use); safe to call more than once.
void ensureResources();

Qt3DRender::QMaterial* shaderMaterial(const QString& name, Qt3DCore::QNode* parent, bool pullForward = false);

}  // namespace jlui
