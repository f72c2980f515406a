// The side view's picture, in layers: the grid and the table, the blocks
// (or a thread, for a ladder too long to show block by block), the ribbons
// on their faces, the words on the blocks, the hinges and the contacts on
// top, then the drag line, the clock, the scale bar and the legend.
#include "jl/ladder/ladder.h"
#include "ui/teaching/events_panel.h"
#include "ui/teaching/side_view.h"
#include "ui/teaching/side_view_ink.h"
#include "ui/teaching/side_view_sheet.h"
#include "ui/view3d/round_length.h"
#include "ui/view3d/spring_coil.h"

#include <QPainter>
#include <QPainterPath>

#include <algorithm>
#include <cmath>

namespace jl::ui {

namespace {

const QColor kBackground(252, 252, 249);
const QColor kGrid(232, 232, 226);
const QColor kTable(214, 218, 224);       // the table top, slate as in the 3-D room
const QColor kCornerInk(90, 40, 120);     // corner numbers: apart from block numbers at a glance
const QColor kEventRing(200, 30, 30);     // round the hinge of an event at the instant on screen
const QColor kContactMark(170, 20, 150);  // a corner resting on a face: none of the hinges' colours

// Text with a pale halo, readable on wood, ribbon and background alike.
void haloText(QPainter& p, const QPointF& centre, const QString& text, const QColor& ink) {
    const QFontMetricsF m(p.font());
    const QRectF box(centre.x() - m.horizontalAdvance(text) / 2, centre.y() - m.height() / 2, m.horizontalAdvance(text),
                     m.height());
    QPainterPath path;
    path.addText(box.left(), box.top() + m.ascent(), p.font(), text);
    p.save();
    p.setPen(
        QPen(QColor(255, 255, 255, 220), std::max(2.0, m.height() / 5), Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    p.setBrush(Qt::NoBrush);
    p.drawPath(path);
    p.setPen(Qt::NoPen);
    p.setBrush(ink);
    p.drawPath(path);
    p.restore();
}

void arrow(QPainter& p, const QPointF& from, const QPointF& to, double head) {
    p.drawLine(from, to);
    const QPointF d = to - from;
    const double len = std::hypot(d.x(), d.y());
    if (len < 1e-9) return;
    const QPointF u = d / len, n(-u.y(), u.x());
    p.drawPolygon(QPolygonF({to, to - u * head + n * head * 0.5, to - u * head - n * head * 0.5}));
}

}  // namespace

QColor hingeColor(jl::HingeMode mode) {
    switch (mode) {
        case jl::HingeMode::Free:
            return {46, 160, 67};
        case jl::HingeMode::OpenLocked:
            return {31, 100, 200};
        case jl::HingeMode::Folded:
            return {220, 90, 20};
        case jl::HingeMode::Cut:
            return {150, 150, 150};
    }
    return kSideInk;
}

SideView::Sheet::Sheet(QPainter& painter, const QRectF& picture, double uiScale, const QRectF& plane,
                       const QRectF& plot, const std::vector<BlockShape>& shapes, int bodies)
    : p(painter), target(picture), ui(uiScale), font(painter.font()), map(plane, plot), n(bodies) {
    font.setPixelSize(int(std::lround(12 * ui)));
    blockPixels = shapes.empty() ? 0 : shapes.front().along * map.scale;
    thicknessPixels = shapes.empty() ? 0 : shapes.front().across * map.scale;
    // A long ladder seen whole is a thread: the blocks' centre lines, end to
    // end, one polyline per run of a colour; no ribbons (they would
    // coincide).
    thread = thicknessPixels < 2.5;
    // A hinge dot never hides the blocks it joins.
    hingeRadius = std::max(3.0, std::min(std::clamp(blockPixels * 0.06, 3.5, 8.0) * ui, thicknessPixels * 0.45));
    // Two corner numbers sit side by side across a block: their size follows the thickness.
    cornerFont = std::min(9.5 * ui, thicknessPixels * 0.42);
}

void SideView::paint(QPainter& p, const QRectF& target) const {
    p.save();
    p.setRenderHint(QPainter::Antialiasing);
    p.setRenderHint(QPainter::TextAntialiasing);
    p.fillRect(target, kBackground);
    if (framing_.isEmpty() || frame_->poses.empty()) {
        p.restore();
        return;
    }
    const double ui = uiScale(target);
    const Sheet s(p, target, ui, framing_, plotArea(target, ui), shapes_,
                  int(std::min(frame_->poses.size(), shapes_.size())));
    // A grid of round lengths, at least ~80 px apart: the scale at a glance.
    const double cell = gridCell(s.map.scale, 80 * ui);
    paintGrid(s, cell);
    if (floor_) paintTable(s);
    // Blocks first, ribbons over their faces, hinges and words on top.
    if (s.thread)
        paintThread(s);
    else
        paintBlockFaces(s);
    paintSprings(s);
    paintParticles(s);
    if (options_.ribbons && !s.thread) paintRibbons(s);
    // Labels only where a block is big enough on screen to carry them.
    if (options_.orientation && s.blockPixels > 24) paintOrientation(s);
    if (options_.cornerNumbers && s.cornerFont >= 7) paintCornerNumbers(s);
    if (options_.blockNumbers && s.blockPixels > 16) paintBlockNumbers(s);
    paintHinges(s);
    paintContacts(s);
    // Blocks too thin on screen for a number at each corner (a whole ladder
    // in a small view): each hinge says at which corner k its blocks meet.
    if (options_.cornerNumbers && s.cornerFont < 7 && s.blockPixels > 14) paintHingeCorners(s);
    if (frame_->dragging) paintDrag(s);
    p.setFont(s.font);
    if (options_.clock) paintClock(s);
    paintScaleAndLegend(p, target, cell * s.map.scale, cell, ui);
    p.restore();
}

void SideView::paintGrid(const Sheet& s, double cell) const {
    QPainter& p = s.p;
    const QRectF& target = s.target;
    p.setPen(QPen(kGrid, 1));
    for (double x = std::floor((framing_.left() - 1) / cell) * cell; x <= framing_.right() + 1; x += cell) {
        const double px = s.map(jl::Vec2(x, 0)).x();
        if (px >= target.left() && px <= target.right())
            p.drawLine(QPointF(px, target.top()), QPointF(px, target.bottom()));
    }
    for (double y = std::floor((framing_.top() - 1) / cell) * cell; y <= framing_.bottom() + 1; y += cell) {
        const double py = s.map(jl::Vec2(0, y)).y();
        if (py >= target.top() && py <= target.bottom())
            p.drawLine(QPointF(target.left(), py), QPointF(target.right(), py));
    }
}

// The table top: its edge a line across the view, shaded under it.
void SideView::paintTable(const Sheet& s) const {
    const QRectF& target = s.target;
    const double py = s.map(jl::Vec2(0, *floor_)).y();
    if (py > target.bottom()) return;
    const double top = std::max(py, target.top());
    s.p.fillRect(QRectF(target.left(), top, target.width(), target.bottom() - top), kTable);
    s.p.setPen(QPen(kSideInk, 1.5 * s.ui));
    if (py >= target.top()) s.p.drawLine(QPointF(target.left(), py), QPointF(target.right(), py));
}

// The ladder as a thread. A point goes in once the thread has moved half a
// pixel: at 100,000 blocks a block is a few thousandths of a pixel, and a
// line that short is not drawn at all (the ladder vanished from the view).
void SideView::paintThread(const Sheet& s) const {
    QPolygonF line;
    const auto add = [&line](const QPointF& at, bool always) {
        if (line.isEmpty() || always || QLineF(line.back(), at).length() >= 0.5) line.append(at);
    };
    const int blocks = std::min(s.n, firstParticle_);
    for (int i = 0; i < blocks; ++i) {
        const auto c = corners(i);
        const bool last = i + 1 >= blocks || shapes_[size_t(i + 1)].color != shapes_[size_t(i)].color;
        add(s.map((c[0] + c[2]) / 2), false);
        add(s.map((c[1] + c[3]) / 2), last);
        if (!last) continue;
        s.p.setPen(QPen(shapes_[size_t(i)].color.darker(120), std::max(1.2, s.thicknessPixels), Qt::SolidLine,
                        Qt::SquareCap, Qt::BevelJoin));
        s.p.drawPolyline(line);
        line.clear();
    }
}

// Each block in its wood, outlined darker, or in ink while the hand holds it.
void SideView::paintBlockFaces(const Sheet& s) const {
    for (int i = 0; i < std::min(s.n, firstParticle_); ++i) {
        const auto c = corners(i);
        // Corners 0,1 share a side and 2,3 the other: walk 0-1-3-2 round the block.
        const QPolygonF poly({s.map(c[0]), s.map(c[1]), s.map(c[3]), s.map(c[2])});
        const QColor wood = shapes_[size_t(i)].color;
        const bool held = i < int(frame_->held.size()) && frame_->held[size_t(i)];
        s.p.setPen(QPen(held ? kSideInk : wood.darker(170), (held ? 2.2 : 1.1) * s.ui, Qt::SolidLine, Qt::SquareCap,
                        Qt::MiterJoin));
        s.p.setBrush(wood);
        s.p.drawPolygon(poly);
    }
}

// A general scene's springs, zigzags as in the 3-D view (spring_coil.h).
void SideView::paintSprings(const Sheet& s) const {
    s.p.setPen(QPen(kSideInk, 1.2 * s.ui, Qt::SolidLine, Qt::RoundCap, Qt::RoundJoin));
    s.p.setBrush(Qt::NoBrush);
    for (const auto& [a, b] : frame_->springs) {
        QPolygonF line;
        for (const jl::Vec2& point : springCoil(a, b)) line << s.map(point);
        s.p.drawPolyline(line);
    }
}

void SideView::paintParticles(const Sheet& s) const {
    for (int i = firstParticle_; i < s.n; ++i) {
        s.p.setPen(QPen(kSideInk, 1 * s.ui));
        s.p.setBrush(shapes_[size_t(i)].color);
        s.p.drawEllipse(s.map(frame_->poses[size_t(i)].position), 4.5 * s.ui, 4.5 * s.ui);
    }
}

// Which face carries which ribbons: the outer pair as a solid line, the
// middle ribbon dashed, each in its colour. The simulation's frames leave
// the ribbons to the views that draw them.
void SideView::paintRibbons(const Sheet& s) const {
    const std::vector<jl::RibbonFrame> ribbons =
        !frame_->ribbons.empty() || !ladder_ ? frame_->ribbons
                                             : jl::ladderRibbons(*ladder_, blockSpecs_, frame_->poses, frame_->hinges);
    const double w = std::max(1.6 * s.ui, ribbonThickness_ * s.map.scale);
    s.p.setBrush(Qt::NoBrush);
    for (const bool central : {false, true}) {
        QPen pen(central ? centralRibbonColor_ : ribbonColor_, w, central ? Qt::DashLine : Qt::SolidLine, Qt::FlatCap,
                 Qt::RoundJoin);
        s.p.setPen(pen);
        for (const jl::RibbonFrame& r : ribbons) {
            if (!r.visible || r.central != central) continue;
            QPolygonF path;
            for (const jl::Vec2& q : r.points) path << s.map(q);
            s.p.drawPolyline(path);
        }
    }
}

// An arrow along each ladder block from corner 0 towards corner 1: the
// lengthwise orientation.
void SideView::paintOrientation(const Sheet& s) const {
    s.p.setPen(QPen(kSideInk, 1.4 * s.ui));
    s.p.setBrush(kSideInk);
    for (int i = 0; i < std::min(s.n, int(cornerLocal_.size())); ++i) {
        const auto c = corners(i);
        const jl::Vec2 centre = frame_->poses[size_t(i)].position;
        const jl::Vec2 along = (c[1] - c[0]) * 0.3;
        arrow(s.p, s.map(centre - along), s.map(centre + along), 7 * s.ui);
    }
}

// The engine's corner numbers 0..3 inside each ladder block.
void SideView::paintCornerNumbers(const Sheet& s) const {
    QFont small = s.font;
    small.setPixelSize(int(std::lround(s.cornerFont)));
    s.p.setFont(small);
    for (int i = 0; i < std::min(s.n, int(cornerLocal_.size())); ++i) {
        const auto c = corners(i);
        const jl::Vec2 centre = frame_->poses[size_t(i)].position;
        // Inside the block near each corner: a little in from the end, a
        // quarter of the thickness in from the side, so the numbers of two
        // blocks meeting at a hinge do not overlap.
        const jl::Vec2 along = (c[1] - c[0]).normalized(), across = (c[2] - c[0]).normalized();
        const double inset = s.cornerFont * 1.05 / s.map.scale;
        for (int k = 0; k < 4; ++k) {
            const jl::Vec2 r = c[size_t(k)] - centre;
            const double a = r.dot(along), b = r.dot(across);
            const jl::Vec2 spot =
                centre + along * (a - std::copysign(std::min(inset, std::abs(a)), a)) + across * (b * 0.5);
            const QPointF at = s.map(spot);
            haloText(s.p, at, QString::number(k), kCornerInk);
        }
    }
}

// Each block's number at its centre; every few blocks where they crowd.
void SideView::paintBlockNumbers(const Sheet& s) const {
    QFont bold = s.font;
    bold.setBold(true);
    s.p.setFont(bold);
    const int every = std::max(1, int(std::ceil(bold.pixelSize() * 1.6 / std::max(1.0, s.blockPixels))));
    for (int i = 0; i < std::min(s.n, firstParticle_); i += every) {
        const QPointF at = s.map(frame_->poses[size_t(i)].position);
        // Beside the arrow when both are asked for.
        const QPointF shift = options_.orientation ? QPointF(0, -bold.pixelSize() * 0.9) : QPointF();
        haloText(s.p, at + shift, QString::number(i), kSideInk);
    }
}

// A dot per hinge in its mode's colour, and at an event's instant a ring
// round its hinge: the eye finds it at once.
void SideView::paintHinges(const Sheet& s) const {
    const double r = s.hingeRadius;
    for (const jl::HingeFrame& h : frame_->hinges) {
        // In a thread, only the hinges that hold (locked or folded) are worth a dot.
        if (s.thread && h.mode == jl::HingeMode::Free) continue;
        s.p.setPen(QPen(Qt::white, 1.2 * s.ui));
        s.p.setBrush(hingeColor(h.mode));
        s.p.drawEllipse(s.map(h.position), r, r);
    }
    for (const int j : hingesAtInstant(*frame_)) {
        s.p.setPen(QPen(kEventRing, 2.5 * s.ui));
        s.p.setBrush(Qt::NoBrush);
        s.p.drawEllipse(s.map(frame_->hinges[size_t(j - 1)].position), r + 5 * s.ui, r + 5 * s.ui);
    }
}

// A corner resting on another block's face: a wedge on the face, pointing
// the way the face pushes, so that a class sees what holds a block up where
// no hinge does.
void SideView::paintContacts(const Sheet& s) const {
    for (const jl::BlockContactFrame& c : frame_->blockContacts) {
        const QPointF at = s.map(c.point);
        const QPointF n(c.normal.x(), -c.normal.y()), t(-n.y(), n.x());
        const double size = std::max(7.0 * s.ui, s.hingeRadius * 2.0);  // larger than a hinge dot: seen beside one
        s.p.setPen(QPen(Qt::white, 1.2 * s.ui));
        s.p.setBrush(kContactMark);
        s.p.drawPolygon(QPolygonF({at, at - n * size + t * size * 0.6, at - n * size - t * size * 0.6}));
    }
}

void SideView::paintHingeCorners(const Sheet& s) const {
    QFont small = s.font;
    small.setPixelSize(int(std::lround(9.5 * s.ui)));
    s.p.setFont(small);
    for (const jl::HingeFrame& h : frame_->hinges)
        haloText(s.p, s.map(h.position) + QPointF(s.hingeRadius + 6 * s.ui, 0), QString::number(h.corner), kCornerInk);
}

// The mouse spring: a dashed line from the block to the pointer.
void SideView::paintDrag(const Sheet& s) const {
    s.p.setPen(QPen(QColor(200, 30, 30), 2 * s.ui, Qt::DashLine, Qt::RoundCap));
    s.p.drawLine(s.map(frame_->dragFrom), s.map(frame_->dragTo));
    s.p.setBrush(QColor(200, 30, 30));
    s.p.setPen(Qt::NoPen);
    s.p.drawEllipse(s.map(frame_->dragTo), 4 * s.ui, 4 * s.ui);
}

// "t = 0.700 s" at the top left and, at an event's instant (N, or a click
// on it), what happened there: in presentation mode the class sees no
// status bar.
void SideView::paintClock(const Sheet& s) const {
    QPainter& p = s.p;
    const QFontMetricsF m(s.font);
    const double pad = 8 * s.ui;
    p.setPen(kSideInk);
    p.drawText(QPointF(s.target.left() + pad, s.target.top() + pad + m.ascent()),
               tr("t = %1 s").arg(frame_->time, 0, 'f', 3));
    QStringList happened;
    for (const jl::Event& e : frame_->events)
        if (e.time == frame_->time) happened << whatHappened(e);
    if (happened.isEmpty()) return;
    QFont small = s.font;
    small.setPixelSize(std::max(6, int(std::lround(s.font.pixelSize() * 0.85))));
    p.setFont(small);
    const QRectF room(s.target.left() + pad, s.target.top() + pad + m.height() * 1.15, s.target.width() - 2 * pad,
                      s.target.height() / 3);
    const QRectF used = p.boundingRect(room, Qt::TextWordWrap, happened.join('\n'));
    p.fillRect(used.adjusted(-3 * s.ui, -2 * s.ui, 3 * s.ui, 2 * s.ui), QColor(255, 255, 255, 140));
    p.setPen(kSideInk);
    p.drawText(room, Qt::TextWordWrap, happened.join('\n'));
    p.setFont(s.font);
}

}  // namespace jl::ui
