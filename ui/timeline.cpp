#include "ui/timeline.h"

#include <QMouseEvent>
#include <QPainter>

#include <algorithm>
#include <cmath>

namespace jl::ui {

namespace {
QColor markColor(jl::EventKind k) {
    switch (k) {
    case jl::EventKind::FlipFlop: return QColor(214, 96, 40);
    case jl::EventKind::Fold: return QColor(60, 120, 200);
    case jl::EventKind::Lock: return QColor(90, 150, 70);
    case jl::EventKind::Unlock:
    case jl::EventKind::Unfold: return QColor(130, 130, 130);
    default: return QColor(150, 90, 170);
    }
}
}  // namespace

Timeline::Timeline(QWidget* parent) : QWidget(parent) {
    setObjectName("timeline");
    setMinimumHeight(40);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setToolTip(tr("Simulated time: the shaded part is recorded; press or drag to see any moment. "
                  "Marks: orange flip-flop, blue fold, green lock, grey unlock or unfold."));
}

void Timeline::setDuration(double seconds) {
    duration_ = std::max(0.1, seconds);
    update();
}

void Timeline::setState(double cursor, double recorded, std::shared_ptr<const std::vector<jl::Event>> events) {
    if (cursor == cursor_ && recorded == recorded_ && events == events_) return;
    cursor_ = cursor;
    recorded_ = recorded;
    events_ = std::move(events);
    update();
}

// The scale grows in whole steps as the run goes past the scene's length.
double Timeline::span() const {
    double s = duration_;
    while (recorded_ > s * 0.98) s *= 1.5;
    return s;
}

QRectF Timeline::track() const { return QRectF(8, 6, width() - 16, height() - 24); }
double Timeline::xOf(double t) const { return track().left() + track().width() * std::clamp(t / span(), 0.0, 1.0); }
double Timeline::timeAt(int x) const {
    return std::clamp((x - track().left()) / track().width(), 0.0, 1.0) * span();
}

void Timeline::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = track();
    const QPalette pal = palette();
    p.fillRect(r, pal.color(QPalette::Base));
    p.fillRect(QRectF(r.left(), r.top(), xOf(recorded_) - r.left(), r.height()), pal.color(QPalette::Highlight).lighter(170));
    p.setPen(pal.color(QPalette::Mid));
    p.drawRect(r);

    // Ticks every 0.1, 0.5, 1, 5 ... s so labels never crowd.
    const double sp = span();
    double tick = 0.1;
    while (r.width() * tick / sp < 48) tick *= (QString::number(tick).contains('5') ? 2 : 5);
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    p.setFont(f);
    for (double t = 0; t <= sp + 1e-9; t += tick) {
        const double x = xOf(t);
        p.setPen(pal.color(QPalette::Mid));
        p.drawLine(QPointF(x, r.bottom()), QPointF(x, r.bottom() + 3));
        p.setPen(pal.color(QPalette::WindowText));
        p.drawText(QRectF(x - 30, r.bottom() + 3, 60, 14), Qt::AlignHCenter | Qt::AlignTop,
                   QString::number(t, 'g', 4) + " s");
    }
    if (events_) {
        for (const jl::Event& e : *events_) {
            const double x = xOf(e.time);
            p.setPen(QPen(markColor(e.kind), 2));
            p.drawLine(QPointF(x, r.top() + r.height() * 0.45), QPointF(x, r.bottom() - 1));
        }
    }
    const double cx = xOf(cursor_);
    p.setPen(QPen(QColor(200, 30, 30), 2));
    p.drawLine(QPointF(cx, r.top() - 3), QPointF(cx, r.bottom() + 2));
    p.setBrush(QColor(200, 30, 30));
    p.drawPolygon(QPolygonF({QPointF(cx - 5, r.top() - 5), QPointF(cx + 5, r.top() - 5), QPointF(cx, r.top() + 2)}));
}

void Timeline::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton) emit seekRequested(timeAt(int(e->position().x())));
}

void Timeline::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & Qt::LeftButton) emit seekRequested(timeAt(int(e->position().x())));
}

}  // namespace jl::ui
