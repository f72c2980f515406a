// The side view's scale bar and its legend of hinge modes, drawn last, in
// the bands the ladder's framing keeps clear.
#include "ui/teaching/side_view.h"
#include "ui/teaching/side_view_ink.h"
#include "ui/view3d/round_length.h"

#include <QPainter>

#include <algorithm>
#include <cmath>
#include <utility>

namespace jl::ui {

void SideView::paintScaleAndLegend(QPainter& p, const QRectF& target, double cellPixels, double cell, double ui) const {
    const QFont font = p.font();
    const QFontMetricsF m(font);
    const double pad = 8 * ui;
    // The scale bar: one grid cell, above the legend's row.
    {
        const bool legendRow = options_.legend && !frame_->hinges.empty();
        const QPointF a(target.left() + pad, target.bottom() - pad - (legendRow ? m.height() * 1.4 : 0));
        const QPointF b = a + QPointF(cellPixels, 0);
        p.setPen(QPen(kSideInk, 1.5 * ui));
        p.drawLine(a, b);
        p.drawLine(a, a - QPointF(0, 4 * ui));
        p.drawLine(b, b - QPointF(0, 4 * ui));
        // Its length right of it, or above its left end where the view is too narrow for that.
        const QString label = lengthText(cell);
        const QPointF at = b.x() + 4 * ui + m.horizontalAdvance(label) <= target.right() - pad
                               ? QPointF(b.x() + 4 * ui, a.y())
                               : QPointF(a.x(), a.y() - 6 * ui);
        p.drawText(at, label);
        scaleLabel_ = QRectF(at.x(), at.y() - m.ascent(), m.horizontalAdvance(label), m.height());
    }
    // The legend: one row at the bottom right, clear of the ladder (the
    // drawing keeps out of the top and bottom bands).
    if (options_.legend && !frame_->hinges.empty()) {
        const std::pair<jl::HingeMode, QString> items[] = {{jl::HingeMode::Free, tr("free")},
                                                           {jl::HingeMode::OpenLocked, tr("locked open")},
                                                           {jl::HingeMode::Folded, tr("folded")}};
        // Narrower than the row: smaller type, never cut.
        double fit = 1.0;
        {
            double width = 0;
            for (const auto& [mode, text] : items) width += (12 + 4 + 10) * ui + m.horizontalAdvance(text);
            fit = std::min(1.0, (target.width() - 2 * pad) / std::max(1.0, width - 10 * ui));
        }
        QFont small = font;
        small.setPixelSize(std::max(6, int(std::lround(font.pixelSize() * fit))));
        p.setFont(small);
        const QFontMetricsF ms(small);
        const double dot = 6 * ui * fit, gap = 10 * ui * fit, space = 4 * ui * fit;
        double width = 0;
        for (const auto& [mode, text] : items) width += 2 * dot + space + ms.horizontalAdvance(text) + gap;
        double x = target.right() - pad - width + gap;
        const double y = target.bottom() - pad - m.height() / 2;
        for (const auto& [mode, text] : items) {
            p.setPen(QPen(Qt::white, 1.2 * ui));
            p.setBrush(hingeColor(mode));
            p.drawEllipse(QPointF(x + dot, y), dot, dot);
            p.setPen(kSideInk);
            p.drawText(QPointF(x + 2 * dot + space, y + ms.ascent() / 2 - ms.descent() / 2), text);
            x += 2 * dot + space + ms.horizontalAdvance(text) + gap;
        }
        p.setFont(font);
    }
}

}  // namespace jl::ui
