// Thin flat strips of one colour, rebuilt every frame: the line of the mouse
// spring, the scene's springs, the scale bar (the ribbons, many more, are instanced: ribbon_instances.h).
#pragma once

#include "jl/sim/frame.h"

#include <QColor>
#include <QVector3D>
#include <Qt3DCore/QEntity>

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

class StripEntity : public Qt3DCore::QEntity {
public:
    // `unlit`: a flat colour that reads well against anything (the drag line).
    StripEntity(Qt3DCore::QNode* parent, bool unlit);
    void setColor(const QColor& c);

    // Starts a new set of strips; then add quads and call commit().
    void clear() { data_.clear(); }
    bool empty() const { return data_.empty(); }  // nothing added since clear()
    // A quad from four corners (in order round it) with one normal.
    void addQuad(const QVector3D& a, const QVector3D& b, const QVector3D& c, const QVector3D& d, const QVector3D& n);
    void commit();

private:
    std::vector<float> data_;
    Qt3DCore::QBuffer* buffer_;
    std::vector<Qt3DCore::QAttribute*> attributes_;
    Qt3DRender::QGeometryRenderer* renderer_;
    Qt3DRender::QParameter* color_;
};

// The mouse spring from the grabbed point to the hand, as a bar facing the viewer.
void buildDragLine(StripEntity& strip, const jl::Frame& frame, float z, float width);

// The scene's springs (a general scene's), each a zigzag of bars `width`
// wide in the plane z (spring_coil.h).
void buildSprings(StripEntity& strip, const jl::Frame& frame, float z, float width);

}  // namespace jl::ui
