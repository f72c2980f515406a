// Every block of the scene in one instanced draw call: a unit cube and a
// per-instance buffer of pose, size and colour, rewritten each frame.
// Blocks that would be drawn within a pixel of the block before them, and
// are themselves smaller than a pixel, are left out: a long ladder framed
// whole is a thread of a few hundred pixels, and drawing all of its 10,000
// blocks (as the software renderer does, a triangle at a time) cost more
// than simulating them.
#pragma once

#include "jl/sim/frame.h"
#include "ui/view3d/block_shapes.h"

#include <QMatrix4x4>
#include <QSize>
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
    // Where the camera looks from and the view's size in pixels: which
    // blocks are too small and close together to draw apart.
    void setView(const QMatrix4x4& viewProjection, QSize pixels);
    int drawnCount() const { return drawn_; }

private:
    void upload();
    std::vector<BlockShape> shapes_;
    // The frame's instances, every block, and those that must be drawn (held, highlighted).
    std::vector<float> all_;
    std::vector<bool> marked_;
    std::vector<float> drawnData_;  // those drawn (kept: a long ladder's frame is 0.5 MB)
    QMatrix4x4 viewProjection_;
    QSize pixels_;
    int drawn_ = 0;
    Qt3DCore::QBuffer* instances_;
    std::vector<Qt3DCore::QAttribute*> instanceAttributes_;
    Qt3DRender::QGeometryRenderer* renderer_;
};

}  // namespace jl::ui
