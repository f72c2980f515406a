// One chart against simulated time: its curves, the events as marks, a
// cursor at the frame on screen; a click in the plot asks to see that moment.
#pragma once

#include "jl/sim/frame.h"

#include <QChartView>
#include <QFont>
#include <QPixmap>
#include <QPointF>
#include <QRegion>

#include <limits>
#include <memory>
#include <vector>

class QLineSeries;
class QValueAxis;

namespace jl::ui {

class TimeChart : public QChartView {
    Q_OBJECT
public:
    explicit TimeChart(const QString& title, const QString& unit, QWidget* parent = nullptr);

    // A curve of the chart; its points are set by setPoints.
    QLineSeries* addCurve(const QString& name, const QColor& color, qreal width = 2.0,
                          Qt::PenStyle style = Qt::SolidLine);
    // Hidden curves keep their points; the legend shows them struck out.
    void setCurveShown(QLineSeries* curve, bool shown);
    void setPoints(QLineSeries* curve, const std::vector<QPointF>& points);
    // The time axis [t0, t1]; the value axis fits what is drawn (at least `minSpan` high).
    void setTimeRange(double t0, double t1);
    void fitValues(double minSpan);
    // A fixed value axis instead (fold angles: 0 to 180 degrees), ticks every `tick`.
    void setValueRange(double lo, double hi, double tick);
    void setCursorTime(double t);
    void setEvents(std::shared_ptr<const std::vector<jl::Event>> events);
    // Large fonts and lines for a projector (presentation mode).
    void setLarge(bool large);
    // The legend's type, smaller while its entries would not fit the
    // chart's height (eight energy curves in a low dock): every name shows.
    void fitLegend();

    double timeAtViewPoint(const QPointF& viewPoint) const;
    QPointF viewPointOf(double t, double value) const;
    // Stacked charts line their plots up by widening their margins: where the
    // plot's edges would be without that, and the widening to apply.
    double naturalLeft() const;
    double naturalRight() const;
    void setExtraMargins(double left, double right);

    QValueAxis* timeAxis() const { return timeAxis_; }
    QValueAxis* valueAxis() const { return valueAxis_; }

signals:
    void seekRequested(double time);

protected:
    void drawForeground(QPainter* painter, const QRectF& rect) override;
    void paintEvent(QPaintEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;

private:
    static constexpr QSize kMinimumSize{0, 120};  // a chart still readable in a low dock
    void seekAt(const QPointF& viewPoint);
    // The cursor, painted over the scene (painter in scene coordinates).
    void drawCursor(QPainter* painter);

    QValueAxis* timeAxis_;
    QValueAxis* valueAxis_;
    double cursor_ = 0;
    double paintedCursorX_ =
        std::numeric_limits<double>::quiet_NaN();  // in the viewport, where drawForeground last drew the cursor
    bool large_ = false;
    bool fixedValues_ = false;
    std::pair<double, double> extra_{0, 0};
    struct Fonts {
        QFont title, legend, labels, axisTitle;
    } fonts_;  // the theme's, scaled in presentation mode
    std::shared_ptr<const std::vector<jl::Event>> events_;
    // The chart as last drawn whole, without the cursor: a repaint of the
    // strips the cursor left and entered alone is copied from it. Drawn
    // again, the scene strokes every curve in full whatever the strip
    // (clipping comes after the stroke): 60 times a second, that was a
    // third of the UI thread's time while a 1,000-block ladder played.
    QPixmap picture_;
    // New points: the picture is out of date whatever region the scene
    // asks to repaint (a curve grown under the cursor's strips alone was
    // never drawn).
    bool pictureStale_ = true;
    QRegion cursorStrips_;  // asked for by setCursorTime since the last paint
    bool drawingPicture_ = false;
};

}  // namespace jl::ui
