// Every block of the scene in one instanced draw call: a unit cube and a
// per-instance buffer of pose, size and colour, rewritten each frame.
#pragma once

#include "jl/sim/frame.h"
#include "ui/block_shapes.h"

#include <Qt3DCore/QEntity>

#include <vector>

namespace Qt3DCore {
class QBuffer;
class QAttribute;
}  // namespace Qt3DCore
namespace Qt3DRender {
class QGeometryRenderer;
}

namespace jl::ui {

class BlockInstances : public Qt3DCore::QEntity {
public:
    explicit BlockInstances(Qt3DCore::QNode* parent);
    void setShapes(std::vector<BlockShape> shapes);
    // `grabbed`: the block under the mouse spring, drawn highlighted (-1: none);
    // `pointedAt`: blocks drawn half as highlighted (an event's hinge joins them).
    void showFrame(const jl::Frame& frame, int grabbed, const std::vector<int>& pointedAt = {});

private:
    std::vector<BlockShape> shapes_;
    Qt3DCore::QBuffer* instances_;
    std::vector<Qt3DCore::QAttribute*> instanceAttributes_;
    Qt3DRender::QGeometryRenderer* renderer_;
};

}  // namespace jl::ui
