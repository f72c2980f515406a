// The design map's picture: one cell per design of the two axes, coloured by
// the fraction of hinges the first ripple flips, with a colour legend, the
// numbers of a cell on hover, and a click to open that design.
#pragma once

#include "jl/design/design_axis.h"
#include "jl/design/ripple_reach.h"

#include <QStringList>
#include <QWidget>

#include <optional>
#include <vector>

class QPainter;

namespace jl::ui {

class DesignMapGrid : public QWidget {
    Q_OBJECT
public:
    explicit DesignMapGrid(QWidget* parent = nullptr);

    // A new grid of columns x rows empty cells; ticks are the axis values as
    // shown (x left to right, y bottom to top).
    void setAxes(const QString& xTitle, const QStringList& xTicks, const QString& yTitle, const QStringList& yTicks);
    void setCell(int column, int row, const jl::RippleReach& reach);
    // The cell of the ladder being edited, framed; (-1, -1) for none.
    void setCurrent(int column, int row);
    std::pair<int, int> current() const { return current_; }
    std::optional<jl::RippleReach> cell(int column, int row) const { return cells_[index(column, row)]; }
    int columns() const { return int(xTicks_.size()); }
    int rows() const { return int(yTicks_.size()); }
    QRect cellRect(int column, int row) const;
    QString cellText(int column, int row) const;  // the hover text

    // Reached / hinges, 0 (stalls at once) to 1 (all hinges flip).
    static double fraction(const jl::RippleReach& r) { return r.hinges > 0 ? double(r.reached) / r.hinges : 0.0; }
    static QColor colorOf(double fraction);

    QSize sizeHint() const override { return {720, 520}; }
    QSize minimumSizeHint() const override { return {360, 260}; }

signals:
    void cellClicked(int column, int row);

protected:
    void paintEvent(QPaintEvent* e) override;
    bool event(QEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;

private:
    int index(int column, int row) const { return row * columns() + column; }
    QRect plotRect() const;
    QRect legendRect() const;
    void paintCells(QPainter& p) const;
    void paintAxes(QPainter& p, const QRect& plot) const;
    void paintLegend(QPainter& p) const;
    std::optional<std::pair<int, int>> cellAt(const QPoint& p) const;

    QString xTitle_, yTitle_;
    QStringList xTicks_, yTicks_;
    std::vector<std::optional<jl::RippleReach>> cells_;
    std::pair<int, int> current_{-1, -1};
};

}  // namespace jl::ui
