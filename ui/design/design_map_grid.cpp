#include "ui/design/design_map_grid.h"

#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <array>
#include <cmath>

namespace jl::ui {

namespace {
constexpr int kLeft = 78, kBottom = 52, kTop = 12, kLegend = 92;

// Every k-th tick, so that labels of a long axis do not overlap.
int tickStride(int count, int room, int labelSize) {
    const int fit = std::max(1, room / std::max(1, labelSize));
    return std::max(1, int(std::ceil(double(count) / fit)));
}
}  // namespace

DesignMapGrid::DesignMapGrid(QWidget* parent) : QWidget(parent) {
    setObjectName("designMapGrid");
    setMouseTracking(true);
    setAttribute(Qt::WA_OpaquePaintEvent);
}

void DesignMapGrid::setAxes(const QString& xTitle, const QStringList& xTicks, const QString& yTitle,
                            const QStringList& yTicks) {
    xTitle_ = xTitle, yTitle_ = yTitle, xTicks_ = xTicks, yTicks_ = yTicks;
    cells_.assign(size_t(xTicks.size() * yTicks.size()), std::nullopt);
    current_ = {-1, -1};
    update();
}

void DesignMapGrid::setCell(int column, int row, const jl::RippleReach& reach) {
    cells_[size_t(index(column, row))] = reach;
    update(cellRect(column, row));
}

void DesignMapGrid::setCurrent(int column, int row) {
    current_ = {column, row};
    update();
}

// Viridis (perceptually even, readable in grey and by most colour-blind
// eyes): dark purple where the ripple stalls, yellow where it reaches the end.
QColor DesignMapGrid::colorOf(double fraction) {
    static const std::array<QColor, 5> stops{QColor(0x44, 0x01, 0x54), QColor(0x3b, 0x52, 0x8b),
                                             QColor(0x21, 0x91, 0x8c), QColor(0x5e, 0xc9, 0x62),
                                             QColor(0xfd, 0xe7, 0x25)};
    const double f = std::clamp(fraction, 0.0, 1.0) * double(stops.size() - 1);
    const int i = std::min(int(f), int(stops.size()) - 2);
    const double t = f - i;
    const QColor& a = stops[size_t(i)];
    const QColor& b = stops[size_t(i + 1)];
    return QColor::fromRgbF(float(a.redF() + t * (b.redF() - a.redF())),
                            float(a.greenF() + t * (b.greenF() - a.greenF())),
                            float(a.blueF() + t * (b.blueF() - a.blueF())));
}

QRect DesignMapGrid::plotRect() const {
    return QRect(kLeft, kTop, std::max(10, width() - kLeft - kLegend), std::max(10, height() - kTop - kBottom));
}

QRect DesignMapGrid::legendRect() const {
    const QRect p = plotRect();
    return QRect(p.right() + 22, p.top(), 18, p.height());
}

QRect DesignMapGrid::cellRect(int column, int row) const {
    const QRect p = plotRect();
    if (columns() == 0 || rows() == 0) return {};
    const double w = double(p.width()) / columns(), h = double(p.height()) / rows();
    // Row 0 at the bottom, as on a plot.
    const int x0 = p.left() + int(std::lround(column * w)), x1 = p.left() + int(std::lround((column + 1) * w));
    const int y1 = p.bottom() + 1 - int(std::lround(row * h)), y0 = p.bottom() + 1 - int(std::lround((row + 1) * h));
    return QRect(QPoint(x0, y0), QPoint(x1 - 1, y1 - 1));
}

std::optional<std::pair<int, int>> DesignMapGrid::cellAt(const QPoint& pos) const {
    for (int r = 0; r < rows(); ++r)
        for (int c = 0; c < columns(); ++c)
            if (cellRect(c, r).contains(pos)) return std::pair{c, r};
    return std::nullopt;
}

QString DesignMapGrid::cellText(int column, int row) const {
    QString text = QString("%1 = %2\n%3 = %4").arg(xTitle_, xTicks_[column], yTitle_, yTicks_[row]);
    const auto& c = cells_[size_t(index(column, row))];
    if (!c) return text + tr("\nnot computed yet");
    text += tr("\nthe first ripple reaches hinge %1 of %2").arg(c->reached).arg(c->hinges);
    if (c->reached >= 2) text += tr("\nmean time between flips %1 s").arg(c->meanTimeBetweenFlips, 0, 'f', 3);
    if (!c->failure.empty()) text += tr("\nfailure: %1").arg(QString::fromStdString(c->failure));
    if (std::pair{column, row} == current_) return text + tr("\nthe ladder being edited");
    return text + tr("\nclick to open this design");
}

void DesignMapGrid::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.fillRect(rect(), palette().window());
    paintCells(p);
    const QRect plot = plotRect();
    p.setPen(palette().color(QPalette::WindowText));
    p.drawRect(plot.adjusted(0, 0, -1, -1));
    if (current_.first >= 0) {  // the design being edited, framed black and white
        const QRect cell = cellRect(current_.first, current_.second);
        p.setPen(QPen(Qt::black, 3));
        p.drawRect(cell.adjusted(2, 2, -2, -2));
        p.setPen(QPen(Qt::white, 1));
        p.drawRect(cell.adjusted(2, 2, -2, -2));
        p.setPen(palette().color(QPalette::WindowText));  // the axes are text on the window
    }
    paintAxes(p, plot);
    paintLegend(p);
}

// Each cell in the colour of its reach, with the hinges its ripple flipped
// (of all) written on it where they fit; a cell not yet run is hatched, a
// failed run crossed out.
void DesignMapGrid::paintCells(QPainter& p) const {
    const QFontMetrics fm = fontMetrics();
    for (int r = 0; r < rows(); ++r)
        for (int c = 0; c < columns(); ++c) {
            const QRect cell = cellRect(c, r);
            const auto& reach = cells_[size_t(index(c, r))];
            if (!reach) {
                p.fillRect(cell, QColor(225, 225, 225));
                p.fillRect(cell, QBrush(QColor(190, 190, 190), Qt::BDiagPattern));
                continue;
            }
            const double f = fraction(*reach);
            p.fillRect(cell, colorOf(f));
            if (!reach->failure.empty()) {  // a failed run: crossed out in red
                p.setPen(QPen(QColor(0xd0, 0x10, 0x30), 2));
                p.drawLine(cell.topLeft() + QPoint(3, 3), cell.bottomRight() - QPoint(3, 3));
                p.drawLine(cell.topRight() + QPoint(-3, 3), cell.bottomLeft() + QPoint(3, -3));
            }
            const QString label = QString("%1/%2").arg(reach->reached).arg(reach->hinges);
            if (cell.width() > fm.horizontalAdvance(label) + 4 && cell.height() > fm.height()) {
                p.setPen(f > 0.6 ? Qt::black : Qt::white);
                p.drawText(cell, Qt::AlignCenter, label);
            }
        }
}

// Axes: ticks at cell centres, every k-th when they would overlap.
void DesignMapGrid::paintAxes(QPainter& p, const QRect& plot) const {
    const QFontMetrics fm = fontMetrics();
    int widest = 0;
    for (const QString& t : xTicks_) widest = std::max(widest, fm.horizontalAdvance(t) + 8);
    const int xStride = tickStride(columns(), plot.width(), widest);
    for (int c = 0; c < columns(); c += xStride) {
        const QRect cell = cellRect(c, 0);
        p.drawLine(cell.center().x(), plot.bottom(), cell.center().x(), plot.bottom() + 4);
        p.drawText(QRect(cell.center().x() - widest / 2, plot.bottom() + 6, widest, fm.height()), Qt::AlignCenter,
                   xTicks_[c]);
    }
    const int yStride = tickStride(rows(), plot.height(), fm.height() + 2);
    for (int r = 0; r < rows(); r += yStride) {
        const QRect cell = cellRect(0, r);
        p.drawLine(plot.left() - 4, cell.center().y(), plot.left(), cell.center().y());
        p.drawText(QRect(0, cell.center().y() - fm.height() / 2, plot.left() - 8, fm.height()),
                   Qt::AlignRight | Qt::AlignVCenter, yTicks_[r]);
    }
    p.drawText(QRect(plot.left(), plot.bottom() + 8 + fm.height(), plot.width(), fm.height() + 4), Qt::AlignCenter,
               xTitle_);
    p.save();
    p.translate(12, plot.center().y());
    p.rotate(-90);
    p.drawText(QRect(-plot.height() / 2, -fm.height() / 2, plot.height(), fm.height() + 2), Qt::AlignCenter, yTitle_);
    p.restore();
}

// The legend: the fraction of hinges the first ripple flips.
void DesignMapGrid::paintLegend(QPainter& p) const {
    const QFontMetrics fm = fontMetrics();
    const QRect legend = legendRect();
    for (int y = legend.top(); y <= legend.bottom(); ++y)
        p.fillRect(QRect(legend.left(), y, legend.width(), 1),
                   colorOf(double(legend.bottom() - y) / std::max(1, legend.height() - 1)));
    p.drawRect(legend.adjusted(0, 0, -1, -1));
    for (int k = 0; k <= 4; ++k) {
        const int y = legend.bottom() - int(std::lround(k / 4.0 * (legend.height() - 1)));
        p.drawLine(legend.right(), y, legend.right() + 3, y);
        p.drawText(QRect(legend.right() + 5, y - fm.height() / 2, kLegend, fm.height()),
                   Qt::AlignLeft | Qt::AlignVCenter, QString("%1%").arg(k * 25));
    }
    p.save();
    p.translate(legend.left() - 6, legend.center().y());
    p.rotate(-90);
    p.drawText(QRect(-legend.height() / 2, -fm.height(), legend.height(), fm.height()), Qt::AlignCenter,
               tr("hinges the first ripple flips"));
    p.restore();
}

bool DesignMapGrid::event(QEvent* e) {
    if (e->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(e);
        if (const auto c = cellAt(help->pos()))
            QToolTip::showText(help->globalPos(), cellText(c->first, c->second), this, cellRect(c->first, c->second));
        else
            QToolTip::hideText();
        return true;
    }
    return QWidget::event(e);
}

void DesignMapGrid::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton) return QWidget::mouseReleaseEvent(e);
    if (const auto c = cellAt(e->position().toPoint())) emit cellClicked(c->first, c->second);
}

}  // namespace jl::ui
