// The ribbons of one kind (the outer pairs, or the middle ribbons) in one
// instanced draw call, as the blocks are drawn: a ribbon path is an
// instance of five points, and the shader lays the strips over them
// (resources/shaders/ribbons.vert). Built as a list of quads, the three
// ribbons of 10,000 hinges were 17 MB of vertices made and uploaded at
// every frame shown.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame.h"

#include <QColor>
#include <QMatrix4x4>
#include <Qt3DCore/QEntity>

#include <span>
#include <vector>

namespace Qt3DCore {
class QBuffer;
class QAttribute;
}  // namespace Qt3DCore
namespace Qt3DRender {
class QGeometryRenderer;
class QParameter;
}  // namespace Qt3DRender

namespace jl::ui {

class RibbonInstances : public Qt3DCore::QEntity {
public:
    // `central`: the middle ribbons (one lane, at z = 0); otherwise the outer pairs.
    RibbonInstances(Qt3DCore::QNode* parent, bool central);
    // Colour, widths and lanes from the scene (z is the blocks' width direction).
    void setSpec(const jl::RibbonSpec& spec, double blockWidth);
    // The visible ribbons of this kind; an empty list draws none.
    void showRibbons(const std::vector<jl::RibbonFrame>& ribbons);
    int drawnCount() const { return drawn_; }

private:
    bool central_;
    std::vector<float> data_;  // kept: its room serves frame after frame
    int drawn_ = 0;
    Qt3DCore::QBuffer* instances_;
    std::vector<Qt3DCore::QAttribute*> instanceAttributes_;
    Qt3DRender::QGeometryRenderer* renderer_;
    Qt3DRender::QParameter* color_;
    Qt3DRender::QParameter* halfWidth_;
    Qt3DRender::QParameter* laneOffset_;
};

// The blocks, first to last, whose ribbons may show in a view of this
// view-projection: those whose centre is within `reach` (m) of the view's
// frustum, the sides and the near plane (a block's ribbons lie within its
// length of its centre). None (first > last) when no block is that near.
struct BlockSpan {
    int first = 0, last = -1;
    bool operator==(const BlockSpan&) const = default;
};
BlockSpan blocksNearView(const QMatrix4x4& viewProjection, std::span<const jl::Pose> poses, float reach);

}  // namespace jl::ui
