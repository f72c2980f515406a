// What the side view's files share to draw and to hit-test: the mapping
// from the ladder's plane to a picture, and (side_view_paint.cpp) one
// picture being drawn with the sizes on screen that decide what it shows.
#pragma once

#include "ui/teaching/side_view.h"
#include "ui/view3d/block_shapes.h"

#include <QFont>
#include <QPainter>
#include <QPointF>
#include <QRectF>

#include <algorithm>
#include <vector>

namespace jl::ui {

// Plane (m, y up) to picture (pixels, y down): one scale for both axes, centred.
struct SideView::Mapping {
    double scale = 1;
    QPointF origin;  // pixel of the plane's point (0, 0)
    QPointF operator()(const jl::Vec2& v) const { return {origin.x() + scale * v.x(), origin.y() - scale * v.y()}; }
    Mapping(const QRectF& plane, const QRectF& target) {
        scale = std::min(target.width() / plane.width(), target.height() / plane.height());
        const QPointF c = target.center(), pc = plane.center();
        origin = {c.x() - scale * pc.x(), c.y() + scale * pc.y()};
    }
};

// One picture of a frame being drawn: `plane` shown in the `plot` part of
// `picture`, the first `bodies` bodies of the frame (those with a shape).
struct SideView::Sheet {
    Sheet(QPainter& painter, const QRectF& picture, double uiScale, const QRectF& plane, const QRectF& plot,
          const std::vector<BlockShape>& shapes, int bodies);
    QPainter& p;
    QRectF target;
    double ui;   // type and lines grow with the picture
    QFont font;  // the words', 12 px at ui 1; the numbers' fonts follow it
    Mapping map;
    int n;
    double blockPixels = 0, thicknessPixels = 0;  // the first block's length and thickness on screen
    bool thread = false;                          // too thin for faces: the ladder drawn as a line
    double hingeRadius = 0;                       // px
    double cornerFont = 0;                        // px, the corner numbers' size
};

}  // namespace jl::ui
