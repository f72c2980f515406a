#include "ui/window/screen_fit.h"

#include <QLayout>
#include <QScreen>
#include <QWidget>

#include <algorithm>

namespace jl::ui {

void fitToScreen(QWidget* window) {
    if (window->isFullScreen() || window->isMaximized() || !window->screen()) return;
    // The layout's pending growth first, or it would undo the fit.
    if (window->layout()) window->layout()->activate();
    const QRect available = window->screen()->availableGeometry();
    const QRect frame = window->frameGeometry();
    const QSize margins = frame.size() - window->geometry().size();
    const QSize inside(std::min(window->width(), available.width() - margins.width()),
                       std::min(window->height(), available.height() - margins.height()));
    if (inside != window->size()) window->resize(inside);
    // A window that cannot shrink further (its layout's minimum) keeps its
    // top-left corner on the screen, where its title bar can be grabbed.
    const QSize outside = inside + margins;
    const int x = std::max(available.left(), std::min(frame.left(), available.right() + 1 - outside.width()));
    const int y = std::max(available.top(), std::min(frame.top(), available.bottom() + 1 - outside.height()));
    if (QPoint(x, y) != frame.topLeft()) window->move(x, y);
}

}  // namespace jl::ui
