// Pictures of the 3-D view as it is drawn. QWidget::grab misses the 3-D area
// (a window of its own, drawn by Qt3D), so they come from the capture node at
// the top of the view's frame graph.
#pragma once

#include "ui/teaching/exporter.h"

#include <QImage>

namespace jl::ui {

class LadderView;

// What the view shows now, at its size in device pixels; a null image when
// nothing came within `timeoutMs` (a view that is not on screen draws nothing).
QImage captureView(LadderView* view, int timeoutMs = 15000);

// Draws each frame with the view (its camera, its size) for an image sequence
// or a video (Exporter): the 3-D view in place of the side view.
FramePainter viewPainter(LadderView* view);

}  // namespace jl::ui
