#include "ui/play/timeline.h"

#include "ui/teaching/events_panel.h"

#include <QFontMetricsF>
#include <QHelpEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>

#include <algorithm>
#include <cmath>

namespace jl::ui {

namespace {
constexpr double kMarkReach = 3;  // px either side of an event's mark that still hit it

QColor markColor(jl::EventKind k) {
    switch (k) {
        case jl::EventKind::FlipFlop:
            return QColor(214, 96, 40);
        case jl::EventKind::Fold:
            return QColor(60, 120, 200);
        case jl::EventKind::Lock:
            return QColor(90, 150, 70);
        case jl::EventKind::Unlock:
        case jl::EventKind::Unfold:
            return QColor(130, 130, 130);
        default:
            return QColor(150, 90, 170);
    }
}
}  // namespace

Timeline::Timeline(QWidget* parent) : QWidget(parent) {
    setObjectName("timeline");
    setMinimumHeight(40);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Fixed);
    setToolTip(
        tr("Simulated time: the shaded part is recorded; press or drag to see any moment. "
           "Marks: orange flip-flop, blue fold, green lock, grey unlock or unfold; press one to see that instant."));
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

void Timeline::setLoop(std::optional<std::pair<double, double>> loop) {
    loop_ = loop;
    update();
}

// The axis ends at the scene's length, or where the run has got to once it
// went on past it: an axis drawn further would promise time nobody asked for.
double Timeline::span() const { return std::max(duration_, recorded_); }

QFont Timeline::labelFont() const {
    QFont f = font();
    f.setPointSizeF(f.pointSizeF() * 0.85);
    return f;
}

// Below the track, a row for the labels as tall as their type (larger on a projector).
QRectF Timeline::track() const {
    const double labels = QFontMetricsF(labelFont()).height() + 5;
    return QRectF(8, 6, width() - 16, std::max(8.0, height() - 6 - labels));
}

QSize Timeline::sizeHint() const { return {600, int(std::ceil(6 + 20 + QFontMetricsF(labelFont()).height() + 5))}; }
double Timeline::xOf(double t) const { return track().left() + track().width() * std::clamp(t / span(), 0.0, 1.0); }
double Timeline::timeAt(int x) const { return std::clamp((x - track().left()) / track().width(), 0.0, 1.0) * span(); }

std::vector<Timeline::Label> Timeline::labels() const {
    const QRectF r = track();
    const QFontMetricsF m(labelFont());
    // Ticks every 0.1, 0.5, 1, 5 ... s, at least as far apart as the widest label.
    const double sp = span();
    const double room = std::max(48.0, m.horizontalAdvance(QString::number(sp, 'g', 4) + " s") + 12);
    double tick = 0.1;
    while (r.width() * tick / sp < room) tick *= (QString::number(tick).contains('5') ? 2 : 5);
    std::vector<Label> out;
    for (double t = 0; t <= sp + 1e-9; t += tick) {
        Label l;
        l.tick = xOf(t);
        l.text = QString::number(t, 'g', 4) + " s";
        // Centred under its tick, but never past either end of the widget
        // (the first and last labels would lose their outer halves).
        const double w = m.horizontalAdvance(l.text) + 2;
        const double left = std::clamp(l.tick - w / 2, 0.0, std::max(0.0, width() - w));
        l.box = QRectF(left, r.bottom() + 3, w, m.height());
        out.push_back(l);
    }
    return out;
}

void Timeline::changeEvent(QEvent* e) {
    QWidget::changeEvent(e);
    if (e->type() == QEvent::FontChange) updateGeometry();  // the labels' row follows the type
}

void Timeline::paintEvent(QPaintEvent*) {
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRectF r = track();
    const QPalette pal = palette();
    p.fillRect(r, pal.color(QPalette::Base));
    p.fillRect(QRectF(r.left(), r.top(), xOf(recorded_) - r.left(), r.height()),
               pal.color(QPalette::Highlight).lighter(170));
    p.setPen(pal.color(QPalette::Mid));
    p.drawRect(r);
    if (loop_) {
        // A tinted stretch with a bar along its top: what L ... L repeats.
        const QRectF band(QPointF(xOf(loop_->first), r.top()), QPointF(xOf(loop_->second), r.bottom()));
        QColor tint = kLoopColor;
        tint.setAlpha(50);
        p.fillRect(band, tint);
        p.fillRect(QRectF(band.left(), r.top() + 1, band.width(), 4), kLoopColor);
    }

    p.setFont(labelFont());
    for (const Label& l : labels()) {
        p.setPen(pal.color(QPalette::Mid));
        p.drawLine(QPointF(l.tick, r.bottom()), QPointF(l.tick, r.bottom() + 3));
        p.setPen(pal.color(QPalette::WindowText));
        p.drawText(l.box, Qt::AlignHCenter | Qt::AlignTop, l.text);
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

const jl::Event* Timeline::eventNear(double x) const {
    if (!events_ || events_->empty()) return nullptr;
    // Events are in time order: only those whose marks fall within reach.
    const double from = timeAt(int(std::floor(x - kMarkReach))), to = timeAt(int(std::ceil(x + kMarkReach)));
    auto it = std::lower_bound(events_->begin(), events_->end(), from,
                               [](const jl::Event& e, double t) { return e.time < t; });
    const jl::Event* best = nullptr;
    double bestDistance = kMarkReach;
    for (; it != events_->end() && it->time <= to; ++it)
        if (const double d = std::abs(xOf(it->time) - x); d <= bestDistance) {
            bestDistance = d;
            best = &*it;
            if (d == 0) break;
        }
    return best;
}

void Timeline::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton) return;
    const double x = e->position().x();
    if (const jl::Event* hit = eventNear(x))
        emit instantRequested(hit->time);
    else
        emit seekRequested(timeAt(int(x)));
}

bool Timeline::event(QEvent* e) {
    if (e->type() == QEvent::ToolTip) {
        const auto* help = static_cast<QHelpEvent*>(e);
        if (const jl::Event* hit = eventNear(help->pos().x())) {
            // Every event of that instant, as the Events dock says them.
            const auto at = [](const jl::Event& a, const jl::Event& b) { return a.time < b.time; };
            const auto [first, last] = std::equal_range(events_->begin(), events_->end(), *hit, at);
            const std::vector<jl::Event> same(first, last);
            QToolTip::showText(help->globalPos(), eventsInWords(same) + tr("\n(click: show this instant)"), this);
        } else {
            QToolTip::showText(help->globalPos(), toolTip(), this);
        }
        return true;
    }
    return QWidget::event(e);
}

void Timeline::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & Qt::LeftButton) emit seekRequested(timeAt(int(e->position().x())));
}

}  // namespace jl::ui
