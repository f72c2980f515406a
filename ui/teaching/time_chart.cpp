#include "ui/teaching/time_chart.h"

#include "ui/teaching/event_colors.h"
#include "ui/window/presentation_mode.h"

#include <QChart>
#include <QFontMetricsF>
#include <QGraphicsLayout>
#include <QLegend>
#include <QLegendMarker>
#include <QLineSeries>
#include <QMouseEvent>
#include <QPaintEvent>
#include <QPainter>
#include <QValueAxis>

#include <algorithm>
#include <cmath>
#include <utility>

namespace jl::ui {

namespace {

// Ticks at round numbers (1, 2 or 5 times a power of ten), about
// `intervals` of them; the axis ends on ticks. Always the same for the
// same range (QValueAxis::applyNiceNumbers also changes the tick count, so
// calling it twice can give another axis).
void setNiceRange(QValueAxis* axis, double lo, double hi, int intervals = 5) {
    const double span = std::max(hi - lo, 1e-12);
    const double rough = span / intervals, power = std::pow(10.0, std::floor(std::log10(rough)));
    double step = power;
    for (double m : {1.0, 2.0, 5.0, 10.0})
        if (m * power >= rough * 0.75) {
            step = m * power;
            break;
        }
    const double from = std::floor(lo / step + 1e-9) * step, to = std::ceil(hi / step - 1e-9) * step;
    // Fixed ticks on multiples of the step (dynamic ticks ignore the label format in Qt 6.4).
    axis->setTickType(QValueAxis::TicksFixed);
    axis->setTickCount(int(std::lround((to - from) / step)) + 1);
    axis->setRange(from, to);
    // As many decimals as the step has, no more: 0.05 s, 45 degrees.
    const int decimals = std::max(0, int(-std::floor(std::log10(step) + 1e-9)));
    axis->setLabelFormat(QString("%.%1f").arg(decimals));
}

}  // namespace

TimeChart::TimeChart(const QString& title, const QString& unit, QWidget* parent) : QChartView(new QChart, parent) {
    setRenderHint(QPainter::Antialiasing);
    setRubberBand(QChartView::NoRubberBand);
    setMinimumSize(kMinimumSize);
    chart()->setTitle(title);
    chart()->setMargins(QMargins(4, 2, 4, 2));
    chart()->legend()->setAlignment(Qt::AlignRight);
    chart()->setAnimationOptions(QChart::NoAnimation);
    timeAxis_ = new QValueAxis(this);
    timeAxis_->setTitleText(tr("t (s)"));

    valueAxis_ = new QValueAxis(this);
    valueAxis_->setTitleText(unit);

    chart()->addAxis(timeAxis_, Qt::AlignBottom);
    chart()->addAxis(valueAxis_, Qt::AlignLeft);
    // The cursor and the event marks are painted over the scene, not items of
    // it: when the plot moves (a wider label, the margins that line the charts
    // up) or time is rescaled, the scene repaints only its own items, and
    // marks drawn where the plot was would stay on screen.
    connect(chart(), &QChart::plotAreaChanged, viewport(), qOverload<>(&QWidget::update));
    connect(timeAxis_, &QValueAxis::rangeChanged, viewport(), qOverload<>(&QWidget::update));
    fonts_ = {chart()->titleFont(), chart()->legend()->font(), timeAxis_->labelsFont(), timeAxis_->titleFont()};
    setToolTip(tr("Click to see that moment. Click a name in the legend to hide or show its curve."));
}

QLineSeries* TimeChart::addCurve(const QString& name, const QColor& color, qreal width, Qt::PenStyle style) {
    auto* s = new QLineSeries(chart());
    s->setName(name);
    QPen pen(color, large_ ? width * 2 : width, style);
    pen.setCapStyle(Qt::RoundCap);
    s->setPen(pen);
    chart()->addSeries(s);
    s->attachAxis(timeAxis_);
    s->attachAxis(valueAxis_);
    // A legend entry toggles its curve: students compare two at a time.
    for (QLegendMarker* m : chart()->legend()->markers(s))
        connect(m, &QLegendMarker::clicked, this, [this, s] { setCurveShown(s, !s->isVisible()); });
    return s;
}

void TimeChart::setCurveShown(QLineSeries* curve, bool shown) {
    curve->setVisible(shown);
    for (QLegendMarker* m : chart()->legend()->markers(curve)) {
        m->setVisible(true);  // hiding a series hides its marker too; keep it to click again
        QFont f = m->font();
        f.setStrikeOut(!shown);
        m->setFont(f);
    }
}

void TimeChart::setPoints(QLineSeries* curve, const std::vector<QPointF>& points) {
    curve->replace(QList<QPointF>(points.begin(), points.end()));
    pictureStale_ = true;
    viewport()->update();
}

void TimeChart::setTimeRange(double t0, double t1) { setNiceRange(timeAxis_, t0, std::max(t1, t0 + 1e-3)); }

void TimeChart::fitValues(double minSpan) {
    if (fixedValues_) return;
    double lo = INFINITY, hi = -INFINITY;
    for (QAbstractSeries* a : chart()->series()) {
        auto* s = static_cast<QLineSeries*>(a);
        if (!s->isVisible()) continue;
        for (const QPointF& p : s->points()) {
            lo = std::min(lo, p.y());
            hi = std::max(hi, p.y());
        }
    }
    if (!(lo <= hi)) lo = hi = 0;
    // A flat curve (the energy books) stays a flat line in the middle, not noise blown up.
    const double mid = (lo + hi) / 2, half = std::max((hi - lo) / 2 * 1.05, minSpan / 2);
    // A short chart (a low dock) gets fewer ticks, so their labels still fit.
    const int intervals = std::clamp(int(chart()->plotArea().height() / 32), 2, 5);
    setNiceRange(valueAxis_, mid - half, mid + half, intervals);
}

void TimeChart::setValueRange(double lo, double hi, double tick) {
    fixedValues_ = true;
    valueAxis_->setTickType(QValueAxis::TicksFixed);
    valueAxis_->setTickCount(int(std::lround((hi - lo) / tick)) + 1);
    valueAxis_->setRange(lo, hi);
    valueAxis_->setLabelFormat("%.0f");
}

void TimeChart::setCursorTime(double t) {
    if (t == cursor_) return;
    // Only the strips under the old and the new cursor: repainting whole
    // charts 60 times a second costs the window its responsiveness.
    // The old strip is where the cursor was painted, not where cursor_ maps
    // to now: the plot may have moved since.
    const QRect view = viewport()->rect();
    const int pad = large_ ? 4 : 3;
    for (double x : {paintedCursorX_, viewPointOf(t, 0).x()})
        if (std::isfinite(x)) {
            const QRect strip(int(x) - pad, view.top(), 2 * pad + 1, view.height());
            cursorStrips_ += strip;
            viewport()->update(strip);
        }
    cursor_ = t;
}

void TimeChart::setEvents(std::shared_ptr<const std::vector<jl::Event>> events) {
    if (events == events_) return;
    events_ = std::move(events);
    viewport()->update();
}

double TimeChart::naturalLeft() const { return chart()->plotArea().left() - extra_.first; }
double TimeChart::naturalRight() const { return chart()->plotArea().right() + extra_.second; }

void TimeChart::setExtraMargins(double left, double right) {
    if (std::abs(left - extra_.first) < 0.5 && std::abs(right - extra_.second) < 0.5) return;
    extra_ = {left, right};
    chart()->setMargins(QMargins(4 + int(std::lround(left)), 2, 4 + int(std::lround(right)), 2));
}

void TimeChart::setLarge(bool large) {
    if (large == large_) return;
    large_ = large;
    const double k = large ? 1.5 * presentationSize(this) : 1.0;
    auto scaled = [k](QFont f) {
        f.setPointSizeF(f.pointSizeF() * k);
        return f;
    };
    chart()->setTitleFont(scaled(fonts_.title));
    fitLegend();
    for (QValueAxis* a : {timeAxis_, valueAxis_}) {
        a->setLabelsFont(scaled(fonts_.labels));
        a->setTitleFont(scaled(fonts_.axisTitle));
    }
    // Time is the same on every chart and the timeline says it: in large type
    // its title gives its room to the tick labels.
    timeAxis_->setTitleVisible(!large);
    for (QAbstractSeries* a : chart()->series()) {
        auto* s = static_cast<QLineSeries*>(a);
        QPen pen = s->pen();
        pen.setWidthF(large ? pen.widthF() * 2 : pen.widthF() / 2);
        s->setPen(pen);
    }
    // QChartView raises its minimum size to the chart's on every resize and
    // never lowers it: the large type's minimum would outlast presentation
    // mode and hold the window taller than the screen.
    setMinimumSize(kMinimumSize);
}

void TimeChart::fitLegend() {
    QLegend* legend = chart()->legend();
    QFont font = fonts_.legend;
    font.setPointSizeF(font.pointSizeF() * (large_ ? 1.5 : 1.0));
    if (chart()->layout()) chart()->layout()->activate();
    // The legend's size hint does not follow its entries (Qt 6.4): one row
    // is a line of its type plus the marker's padding, 7 px.
    const double room = legend->geometry().height() - 8;
    const int rows = int(legend->markers().size());
    // Steps of 15 %, down to 7 points (smaller is not read from a desk).
    while (room > 0 && rows * (QFontMetricsF(font).height() + 7) > room && font.pointSizeF() * 0.85 >= 7)
        font.setPointSizeF(font.pointSizeF() * 0.85);
    legend->setFont(font);
}

void TimeChart::resizeEvent(QResizeEvent* e) {
    QChartView::resizeEvent(e);
    fitLegend();
}

QPointF TimeChart::viewPointOf(double t, double value) const {
    return mapFromScene(chart()->mapToScene(chart()->mapToPosition(QPointF(t, value))));
}

double TimeChart::timeAtViewPoint(const QPointF& viewPoint) const {
    return chart()->mapToValue(chart()->mapFromScene(mapToScene(viewPoint.toPoint()))).x();
}

void TimeChart::drawForeground(QPainter* painter, const QRectF& rect) {
    QChartView::drawForeground(painter, rect);
    const QRectF plot = chart()->mapToScene(chart()->plotArea()).boundingRect();
    const double t0 = timeAxis_->min(), t1 = timeAxis_->max();
    auto xOf = [&](double t) { return plot.left() + plot.width() * (t - t0) / (t1 - t0); };
    painter->save();
    if (events_) {
        // One mark per pixel column, and only where the view is being
        // repainted (the cursor's moves repaint thin strips): a long ladder
        // has thousands of events, and drawing every mark on every frame
        // took a third of the window's time. Upright lines need no antialiasing.
        int lastColumn = -1;
        for (const jl::Event& e : *events_) {
            if (e.time < t0 || e.time > t1) continue;
            const double x = std::round(xOf(e.time));
            if (int(x) == lastColumn || x < rect.left() - 2 || x > rect.right() + 2) continue;
            lastColumn = int(x);
            QColor c = eventColor(e.kind);
            c.setAlpha(110);
            // A filled column, not a stroked line: the raster engine's fast path.
            painter->fillRect(QRectF(x, plot.top(), large_ ? 2.0 : 1.0, plot.height()), c);
        }
    }
    painter->restore();
    if (!drawingPicture_) drawCursor(painter);
}

void TimeChart::drawCursor(QPainter* painter) {
    const QRectF plot = chart()->mapToScene(chart()->plotArea()).boundingRect();
    const double t0 = timeAxis_->min(), t1 = timeAxis_->max();
    painter->save();
    painter->setRenderHint(QPainter::Antialiasing);
    if (cursor_ >= t0 && cursor_ <= t1) {
        const double x = plot.left() + plot.width() * (cursor_ - t0) / (t1 - t0);
        paintedCursorX_ = mapFromScene(QPointF(x, plot.top())).x();
        painter->setPen(QPen(QColor(200, 30, 30), large_ ? 3.0 : 1.6));
        painter->drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    } else {
        paintedCursorX_ = std::numeric_limits<double>::quiet_NaN();
    }
    painter->restore();
}

void TimeChart::paintEvent(QPaintEvent* e) {
    const QRegion strips = std::exchange(cursorStrips_, QRegion());
    const qreal ratio = viewport()->devicePixelRatioF();
    const QSize pixels = viewport()->size() * ratio;
    // Anything but the cursor's strips (the curves, the axes, the marks, a
    // resize, an expose) draws the picture again, whole.
    if (pictureStale_ || picture_.size() != pixels || !e->region().subtracted(strips).isEmpty()) {
        pictureStale_ = false;
        picture_ = QPixmap(pixels);
        picture_.setDevicePixelRatio(ratio);
        picture_.fill(viewport()->palette().color(viewport()->backgroundRole()));
        QPainter p(&picture_);
        p.setRenderHints(renderHints());
        drawingPicture_ = true;
        render(&p, QRectF(viewport()->rect()), viewport()->rect());
        drawingPicture_ = false;
    }
    QPainter p(viewport());
    p.setClipRegion(e->region());
    p.drawPixmap(0, 0, picture_);
    p.setTransform(viewportTransform());
    drawCursor(&p);
}

void TimeChart::seekAt(const QPointF& viewPoint) {
    const QRectF plot = chart()->plotArea();
    const QPointF inChart = chart()->mapFromScene(mapToScene(viewPoint.toPoint()));
    if (!plot.adjusted(-2, -2, 2, 2).contains(inChart)) return;
    emit seekRequested(std::clamp(timeAtViewPoint(viewPoint), std::max(0.0, timeAxis_->min()), timeAxis_->max()));
}

void TimeChart::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) seekAt(e->position());
    QChartView::mousePressEvent(e);
}

void TimeChart::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & Qt::LeftButton) seekAt(e->position());
    QChartView::mouseMoveEvent(e);
}

}  // namespace jl::ui
