// A scale bar in the 3-D view: a round length (1, 2 or 5 times a power of
// ten) drawn upright beside the point looked at, at its depth, with the
// length written under it. A long ladder framed whole is a thread in a
// room scaled to fit; the bar says how tall it is ("100 m"), and close up
// it says how small a block is ("2 cm").
#pragma once

#include <QVector3D>
#include <Qt3DCore/QEntity>

namespace Qt3DCore {
class QTransform;
}
namespace Qt3DExtras {
class QText2DEntity;
}

namespace jl::ui {

class StripEntity;
class ViewCamera;

class ScaleMark : public Qt3DCore::QEntity {
public:
    explicit ScaleMark(Qt3DCore::QNode* parent);
    // Placed for `camera` on a view `pixelsHigh` tall and `aspect` wide per high.
    void place(const ViewCamera& camera, int pixelsHigh, float aspect);
    double length() const { return length_; }  // m
    // The bar's ends, in the world.
    QVector3D top() const { return top_; }
    QVector3D bottom() const { return bottom_; }

private:
    StripEntity* bar_;
    Qt3DExtras::QText2DEntity* label_;
    Qt3DCore::QTransform* labelAt_;
    double length_ = 0;
    QVector3D top_, bottom_;
};

}  // namespace jl::ui
