// The per-instance buffer of an instanced draw (the blocks, the ribbons),
// written with a frame's instances.
#pragma once

#include <QByteArray>
#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DRender/QGeometryRenderer>

#include <vector>

namespace jl::ui {

// `data` holds `perInstance` floats an instance; returns how many are drawn.
inline int uploadInstances(Qt3DCore::QBuffer* buffer, const std::vector<Qt3DCore::QAttribute*>& attributes,
                           Qt3DRender::QGeometryRenderer* renderer, const std::vector<float>& data, int perInstance) {
    const auto drawn = uint(data.size() / size_t(perInstance));
    buffer->setData(QByteArray(reinterpret_cast<const char*>(data.data()), qsizetype(data.size() * sizeof(float))));
    for (auto* a : attributes) a->setCount(drawn);
    renderer->setInstanceCount(int(drawn));
    return int(drawn);
}

}  // namespace jl::ui
