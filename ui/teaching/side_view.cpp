#include "ui/teaching/side_view.h"

#include "jl/ladder/block_corners.h"
#include "jl/ladder/ladder.h"
#include "jl/scene/ladder_blocks.h"
#include "ui/teaching/events_panel.h"
#include "ui/teaching/side_view_ink.h"
#include "ui/view3d/round_length.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QPainterPath>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

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

// Plane (m, y up) to picture (pixels, y down): one scale for both axes, centred.
struct SideView::Mapping {
    double scale = 1;
    QPointF origin;  // pixel of the plane's point (0, 0)
    QPointF operator()(const jl::Vec2& v) const { return {origin.x() + scale * v.x(), origin.y() - scale * v.y()}; }
    Mapping(const QRectF& plane, const QRectF& target) {
        scale = std::min(target.width() / plane.width(), target.height() / plane.height());
        const QPointF c = target.center(), pc = plane.center();
        origin = {c.x() - scale * pc.x(), c.y() + scale * pc.y()};
    }
};

SideView::SideView(QWidget* parent) : QWidget(parent) {
    setObjectName("sideView");
    setMinimumSize(160, 160);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::ClickFocus);  // Delete cuts the selected hinge
    setToolTip(
        tr("The ladder seen from the side, as the paper draws it. Hinges: green free, blue locked open, "
           "orange folded. Wheel: zoom; drag: pan; double-click: follow the whole ladder again. Click by a hinge "
           "and Delete: cut it; drag a free corner onto another block's: join them; right-click: hold, release, cut."));
}

// Where the ladder is drawn: all of `target` but a band at the top (the
// clock) and one at the bottom (the legend, and the scale bar above it).
QRectF SideView::plotArea(const QRectF& target, double ui) const {
    const double line = (12 * ui) * 1.4, band = line + 12 * ui;
    if (target.height() < 6 * band) return target;
    const bool legend = options_.legend && !frame_->hinges.empty();
    return target.adjusted(0, options_.clock ? band : 0, 0, -(band + (legend ? line : 0)));
}

// Type and lines grow with the picture (and with the options' scale).
double SideView::uiScale(const QRectF& target) const {
    return options_.scale * std::max(1.0, std::min(target.width(), target.height()) / 700);
}

// The mouse: the wheel zooms about the pointer, a drag pans, a double click
// goes back to following the whole ladder. Zoomed or panned, the view stays
// where the user put it.
void SideView::wheelEvent(QWheelEvent* e) {
    if (framing_.isEmpty()) return;
    const Mapping map(framing_, plotArea(rect(), uiScale(rect())));
    const QPointF at = e->position();
    const jl::Vec2 fixed((at.x() - map.origin.x()) / map.scale, (map.origin.y() - at.y()) / map.scale);
    const double factor = std::pow(0.85, e->angleDelta().y() / 120.0);
    QRectF r = framing_;
    r = QRectF(fixed.x() - (fixed.x() - r.left()) * factor, fixed.y() - (fixed.y() - r.top()) * factor,
               r.width() * factor, r.height() * factor);
    if (r.width() < 1e-3 || r.width() > 1e3) return;
    framing_ = r;
    following_ = false;
    update();
    e->accept();
}

jl::Vec2 SideView::planePoint(const QPointF& pixel) const {
    if (framing_.isEmpty()) return jl::Vec2::Zero();
    const Mapping map(framing_, plotArea(rect(), uiScale(rect())));
    return {(pixel.x() - map.origin.x()) / map.scale, (map.origin.y() - pixel.y()) / map.scale};
}

int SideView::blockAt(const jl::Vec2& point) const {
    constexpr double margin = 0.002;  // m
    const size_t n = std::min({frame_->poses.size(), shapes_.size(), size_t(ladderBlocks_)});
    for (size_t i = n; i-- > 0;) {
        const jl::Vec2 local = jl::rotate(-frame_->poses[i].angle, point - frame_->poses[i].position);
        if (std::abs(local.x()) <= shapes_[i].across / 2 + margin &&
            std::abs(local.y()) <= shapes_[i].along / 2 + margin)
            return int(i);
    }
    return -1;
}

// Shift and a press on a block starts the hand's turn; a press by a hinge
// or a free corner is the restructuring's; any other press pans.
void SideView::mousePressEvent(QMouseEvent* e) {
    if (e->button() != Qt::LeftButton) return QWidget::mousePressEvent(e);
    const jl::Vec2 p = planePoint(e->position());
    const int block = framing_.isEmpty() ? -1 : blockAt(p);
    if ((e->modifiers() & Qt::ShiftModifier) && block >= 0) {
        turning_.emplace(block, frame_->poses[size_t(block)].position, p);
        turnShownTime_ = frame_->time;
        turnClock_.start();
        return;
    }
    // By a hinge: select it (a drag still pans); at a free corner: drag it to join (restructure_gesture.h).
    if (!framing_.isEmpty()) restructure_.press(p, metresOf(RestructureGesture::kReachPixels));
    update();
    if (restructure_.joining()) return;
    dragFrom_ = e->position();
    setCursor(Qt::ClosedHandCursor);
}

void SideView::mouseMoveEvent(QMouseEvent* e) {
    if (turning_) {
        turning_->moveTo(planePoint(e->position()), double(turnClock_.nsecsElapsed()) * 1e-9);
        const double degrees = TurnGesture::snapped(turning_->swept()) * 180 / std::numbers::pi;
        QToolTip::showText(e->globalPosition().toPoint(),
                           degrees == 0 ? tr("Turn: sweep at least 45 degrees")
                                        : tr("Turn block %1 by %2 degrees").arg(turning_->block()).arg(degrees));
        return;
    }
    if (restructure_.joining()) {
        restructure_.dragTo(planePoint(e->position()), metresOf(RestructureGesture::kSnapPixels));
        return update();
    }
    if (!(e->buttons() & Qt::LeftButton) || framing_.isEmpty()) return QWidget::mouseMoveEvent(e);
    const Mapping map(framing_, plotArea(rect(), uiScale(rect())));
    const QPointF d = e->position() - dragFrom_;
    dragFrom_ = e->position();
    framing_.translate(-d.x() / map.scale, d.y() / map.scale);
    following_ = false;
    update();
}

void SideView::mouseReleaseEvent(QMouseEvent* e) {
    if (e->button() == Qt::LeftButton && turning_) {
        turning_->moveTo(planePoint(e->position()), double(turnClock_.nsecsElapsed()) * 1e-9);
        const auto turn = turning_->turn();
        turning_.reset();
        QToolTip::hideText();
        if (turn) emit turnGiven(turn->block, turn->angle, turn->duration, turnShownTime_);
    }
    if (e->button() == Qt::LeftButton && restructure_.joining())
        give(restructure_.release(planePoint(e->position()), metresOf(RestructureGesture::kSnapPixels)));
    // The menu on the release, as the 3-D view's (where a right drag orbits).
    if (e->button() == Qt::RightButton && !framing_.isEmpty())
        restructure_.popMenu(this, planePoint(e->position()), metresOf(RestructureGesture::kReachPixels),
                             e->globalPosition().toPoint(), [this](GivenAction a) { give(a); });
    update();
    unsetCursor();
    QWidget::mouseReleaseEvent(e);
}

void SideView::contextMenuEvent(QContextMenuEvent* e) { e->accept(); }  // the release shows ours

void SideView::keyPressEvent(QKeyEvent* e) {
    if (e->key() == Qt::Key_Delete && restructure_.selectedHinge() > 0) return give(restructure_.cutSelected());
    QWidget::keyPressEvent(e);
}

void SideView::give(std::optional<GivenAction> given) {
    update();
    if (given) emit actionGiven(given->action, given->text);
}

double SideView::metresOf(double pixels) const {
    return (planePoint(QPointF(pixels, 0)) - planePoint(QPointF(0, 0))).norm();
}

void SideView::mouseDoubleClickEvent(QMouseEvent*) {
    following_ = true;
    resetFraming();
}

void SideView::setScene(const jl::Scene& scene) {
    shapes_ = blockShapes(scene);
    floor_ = scene.floor ? std::optional<double>(scene.floor->height) : std::nullopt;
    restructure_.setScene(scene);
    cornerLocal_.clear();
    ladder_.reset();
    blockSpecs_.clear();
    ladderBlocks_ = scene.ladder ? scene.ladder->blocks : 0;
    firstParticle_ = int(shapes_.size() - scene.particles.size());
    if (scene.ladder && !jl::Ladder::validate(*scene.ladder)) {
        // The engine's own numbering, not a copy of its rule.
        cornerLocal_ = jl::blockCorners(*scene.ladder);
        ladder_ = scene.ladder;
        blockSpecs_ = jl::ladderBlocks(*scene.ladder);
        ribbonColor_ =
            QColor(scene.ladder->ribbons.color.r, scene.ladder->ribbons.color.g, scene.ladder->ribbons.color.b);
        ribbonThickness_ = scene.ladder->ribbons.thickness;
        const jl::Color m = scene.ladder->ribbons.centralColor;
        centralRibbonColor_ = QColor(m.r, m.g, m.b);
    }
    frame_ = std::make_shared<const jl::Frame>();
    resetFraming();
}

void SideView::setOptions(const SideViewOptions& o) {
    options_ = o;
    update();
}

std::array<jl::Vec2, 4> SideView::corners(int block) const {
    const jl::Pose& pose = frame_->poses[size_t(block)];
    std::array<jl::Vec2, 4> out;
    if (block < int(cornerLocal_.size())) {
        for (int k = 0; k < 4; ++k) out[size_t(k)] = pose.apply(cornerLocal_[size_t(block)][size_t(k)]);
        return out;
    }
    // Bodies and particles: a box across local x, along local y, corners in drawing order.
    const BlockShape& s = shapes_[size_t(block)];
    const double a = s.across / 2, l = s.along / 2;
    const jl::Vec2 local[4] = {{-a, -l}, {-a, l}, {a, -l}, {a, l}};
    for (int k = 0; k < 4; ++k) out[size_t(k)] = pose.apply(local[k]);
    return out;
}

QRectF SideView::extentOf(const jl::Frame& f) const {
    double x0 = INFINITY, y0 = INFINITY, x1 = -INFINITY, y1 = -INFINITY;
    const size_t n = std::min(f.poses.size(), shapes_.size());
    for (size_t i = 0; i < n; ++i) {
        // The circumscribed circle: the extent does not depend on the angle.
        const double r = std::hypot(shapes_[i].across, shapes_[i].along) / 2;
        const jl::Vec2& c = f.poses[i].position;
        x0 = std::min(x0, c.x() - r), x1 = std::max(x1, c.x() + r);
        y0 = std::min(y0, c.y() - r), y1 = std::max(y1, c.y() + r);
    }
    if (!(x0 <= x1)) return {};
    return QRectF(QPointF(x0, y0), QPointF(x1, y1));
}

void SideView::resetFraming() {
    framing_ = {};
    following_ = true;
    if (!frame_->poses.empty()) growFraming(extentOf(*frame_));
    update();
}

void SideView::setFraming(const QRectF& plane) {
    framing_ = plane.normalized();
    update();
}

void SideView::growFraming(const QRectF& need) {
    if (!following_ && !framing_.isEmpty()) return;  // zoomed or panned by hand: stay there
    if (need.isEmpty() || framing_.contains(need)) return;
    QRectF r = framing_.isEmpty() ? need : framing_.united(need);
    // Grow with room to spare, so a swinging ladder changes scale seldom.
    const double pad = 0.12 * std::max(r.width(), r.height());
    r.adjust(-pad, -pad, pad, pad);
    // A hanging ladder is tall and thin; show its surroundings too.
    if (r.width() < 0.75 * r.height()) {
        const double grow = (0.75 * r.height() - r.width()) / 2;
        r.adjust(-grow, 0, grow, 0);
    }
    framing_ = r;
}

void SideView::showFrame(const jl::Frame& frame) { showFrame(std::make_shared<const jl::Frame>(frame)); }

void SideView::showFrame(std::shared_ptr<const jl::Frame> frame) {
    if (!frame) return;
    frame_ = std::move(frame);
    restructure_.showFrame(frame_);
    growFraming(extentOf(*frame_));
    update();
}

QPointF SideView::pixelOf(const jl::Vec2& point, const QRectF& target) const {
    if (framing_.isEmpty()) return target.center();
    const double ui = uiScale(target);
    return Mapping(framing_, plotArea(target, ui))(point);
}

QImage SideView::render(const QSize& size) const {
    QImage image(size, QImage::Format_ARGB32_Premultiplied);
    QPainter p(&image);
    paint(p, QRectF(QPointF(0, 0), QSizeF(size)));
    return image;
}

void SideView::paintEvent(QPaintEvent*) {
    QPainter p(this);
    paint(p, rect());
    restructure_.paint(  // not in paint(): an exported picture shows no selection
        p, [this](const jl::Vec2& v) { return pixelOf(v, rect()); }, uiScale(rect()));
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
    QFont font = p.font();
    font.setPixelSize(int(std::lround(12 * ui)));
    const Mapping map(framing_, plotArea(target, ui));

    // A grid of round lengths, at least ~80 px apart: the scale at a glance.
    const double cell = gridCell(map.scale, 80 * ui);
    p.setPen(QPen(kGrid, 1));
    for (double x = std::floor((framing_.left() - 1) / cell) * cell; x <= framing_.right() + 1; x += cell) {
        const double px = map(jl::Vec2(x, 0)).x();
        if (px >= target.left() && px <= target.right())
            p.drawLine(QPointF(px, target.top()), QPointF(px, target.bottom()));
    }
    for (double y = std::floor((framing_.top() - 1) / cell) * cell; y <= framing_.bottom() + 1; y += cell) {
        const double py = map(jl::Vec2(0, y)).y();
        if (py >= target.top() && py <= target.bottom())
            p.drawLine(QPointF(target.left(), py), QPointF(target.right(), py));
    }

    if (floor_) {
        // The table top: its edge a line across the view, shaded under it.
        const double py = map(jl::Vec2(0, *floor_)).y();
        if (py <= target.bottom()) {
            const double top = std::max(py, target.top());
            p.fillRect(QRectF(target.left(), top, target.width(), target.bottom() - top), kTable);
            p.setPen(QPen(kSideInk, 1.5 * ui));
            if (py >= target.top()) p.drawLine(QPointF(target.left(), py), QPointF(target.right(), py));
        }
    }

    const int n = int(std::min(frame_->poses.size(), shapes_.size()));
    const double blockPixels = shapes_.empty() ? 0 : shapes_.front().along * map.scale;
    const double thicknessPixels = shapes_.empty() ? 0 : shapes_.front().across * map.scale;
    // A long ladder seen whole is a thread: the blocks' centre lines, end to
    // end, one polyline per run of a colour; no ribbons (they would
    // coincide). A point goes in once the thread has moved half a pixel:
    // at 100,000 blocks a block is a few thousandths of a pixel, and a line
    // that short is not drawn at all (the ladder vanished from the view).
    const bool thread = thicknessPixels < 2.5;
    // Blocks first, ribbons over their faces, hinges and words on top.
    if (thread) {
        QPolygonF line;
        const auto add = [&line](const QPointF& at, bool always) {
            if (line.isEmpty() || always || QLineF(line.back(), at).length() >= 0.5) line.append(at);
        };
        for (int i = 0; i < std::min(n, firstParticle_); ++i) {
            const auto c = corners(i);
            const bool last =
                i + 1 >= std::min(n, firstParticle_) || shapes_[size_t(i + 1)].color != shapes_[size_t(i)].color;
            add(map((c[0] + c[2]) / 2), false);
            add(map((c[1] + c[3]) / 2), last);
            if (!last) continue;
            p.setPen(QPen(shapes_[size_t(i)].color.darker(120), std::max(1.2, thicknessPixels), Qt::SolidLine,
                          Qt::SquareCap, Qt::BevelJoin));
            p.drawPolyline(line);
            line.clear();
        }
    } else {
        for (int i = 0; i < std::min(n, firstParticle_); ++i) {
            const auto c = corners(i);
            // Corners 0,1 share a side and 2,3 the other: walk 0-1-3-2 round the block.
            const QPolygonF poly({map(c[0]), map(c[1]), map(c[3]), map(c[2])});
            const QColor wood = shapes_[size_t(i)].color;
            const bool held = i < int(frame_->held.size()) && frame_->held[size_t(i)];
            p.setPen(QPen(held ? kSideInk : wood.darker(170), (held ? 2.2 : 1.1) * ui, Qt::SolidLine, Qt::SquareCap,
                          Qt::MiterJoin));
            p.setBrush(wood);
            p.drawPolygon(poly);
        }
    }
    for (int i = firstParticle_; i < n; ++i) {
        p.setPen(QPen(kSideInk, 1 * ui));
        p.setBrush(shapes_[size_t(i)].color);
        p.drawEllipse(map(frame_->poses[size_t(i)].position), 4.5 * ui, 4.5 * ui);
    }
    if (options_.ribbons && !thread) {
        // Which face carries which ribbons: the outer pair as a solid line,
        // the middle ribbon dashed, each in its colour. The simulation's
        // frames leave the ribbons to the views that draw them.
        const std::vector<jl::RibbonFrame> ribbons =
            !frame_->ribbons.empty() || !ladder_
                ? frame_->ribbons
                : jl::ladderRibbons(*ladder_, blockSpecs_, frame_->poses, frame_->hinges);
        const double w = std::max(1.6 * ui, ribbonThickness_ * map.scale);
        p.setBrush(Qt::NoBrush);
        for (const bool central : {false, true}) {
            QPen pen(central ? centralRibbonColor_ : ribbonColor_, w, central ? Qt::DashLine : Qt::SolidLine,
                     Qt::FlatCap, Qt::RoundJoin);
            p.setPen(pen);
            for (const jl::RibbonFrame& r : ribbons) {
                if (!r.visible || r.central != central) continue;
                QPolygonF path;
                for (const jl::Vec2& q : r.points) path << map(q);
                p.drawPolyline(path);
            }
        }
    }

    // Labels only where a block is big enough on screen to carry them.
    // Two corner numbers sit side by side across a block: their size follows the thickness.
    const double cornerFont = std::min(9.5 * ui, thicknessPixels * 0.42);
    if (options_.orientation && blockPixels > 24) {
        p.setPen(QPen(kSideInk, 1.4 * ui));
        p.setBrush(kSideInk);
        for (int i = 0; i < std::min(n, int(cornerLocal_.size())); ++i) {
            const auto c = corners(i);
            const jl::Vec2 centre = frame_->poses[size_t(i)].position;
            const jl::Vec2 along = (c[1] - c[0]) * 0.3;  // corner 0 towards corner 1: the lengthwise orientation
            arrow(p, map(centre - along), map(centre + along), 7 * ui);
        }
    }
    if (options_.cornerNumbers && cornerFont >= 7) {
        QFont small = font;
        small.setPixelSize(int(std::lround(cornerFont)));
        p.setFont(small);
        for (int i = 0; i < std::min(n, int(cornerLocal_.size())); ++i) {
            const auto c = corners(i);
            const jl::Vec2 centre = frame_->poses[size_t(i)].position;
            // Inside the block near each corner: a little in from the end, a
            // quarter of the thickness in from the side, so the numbers of two
            // blocks meeting at a hinge do not overlap.
            const jl::Vec2 along = (c[1] - c[0]).normalized(), across = (c[2] - c[0]).normalized();
            const double inset = cornerFont * 1.05 / map.scale;
            for (int k = 0; k < 4; ++k) {
                const jl::Vec2 r = c[size_t(k)] - centre;
                const double a = r.dot(along), b = r.dot(across);
                const jl::Vec2 spot =
                    centre + along * (a - std::copysign(std::min(inset, std::abs(a)), a)) + across * (b * 0.5);
                const QPointF at = map(spot);
                haloText(p, at, QString::number(k), kCornerInk);
            }
        }
    }
    if (options_.blockNumbers && blockPixels > 16) {
        QFont bold = font;
        bold.setBold(true);
        p.setFont(bold);
        const int every = std::max(1, int(std::ceil(bold.pixelSize() * 1.6 / std::max(1.0, blockPixels))));
        for (int i = 0; i < std::min(n, firstParticle_); i += every) {
            const QPointF at = map(frame_->poses[size_t(i)].position);
            // Beside the arrow when both are asked for.
            const QPointF shift = options_.orientation ? QPointF(0, -bold.pixelSize() * 0.9) : QPointF();
            haloText(p, at + shift, QString::number(i), kSideInk);
        }
    }

    // A hinge dot never hides the blocks it joins.
    const double r = std::max(3.0, std::min(std::clamp(blockPixels * 0.06, 3.5, 8.0) * ui, thicknessPixels * 0.45));
    for (const jl::HingeFrame& h : frame_->hinges) {
        // In a thread, only the hinges that hold (locked or folded) are worth a dot.
        if (thread && h.mode == jl::HingeMode::Free) continue;
        p.setPen(QPen(Qt::white, 1.2 * ui));
        p.setBrush(hingeColor(h.mode));
        p.drawEllipse(map(h.position), r, r);
    }
    // At an event's instant, a ring round its hinge: the eye finds it at once.
    for (const int j : hingesAtInstant(*frame_)) {
        p.setPen(QPen(kEventRing, 2.5 * ui));
        p.setBrush(Qt::NoBrush);
        p.drawEllipse(map(frame_->hinges[size_t(j - 1)].position), r + 5 * ui, r + 5 * ui);
    }
    // A corner resting on another block's face: a wedge on the face,
    // pointing the way the face pushes, so that a class sees what holds a
    // block up where no hinge does.
    for (const jl::BlockContactFrame& c : frame_->blockContacts) {
        const QPointF at = map(c.point);
        const QPointF n(c.normal.x(), -c.normal.y()), t(-n.y(), n.x());
        const double size = std::max(7.0 * ui, r * 2.0);  // larger than a hinge dot: seen beside one
        p.setPen(QPen(Qt::white, 1.2 * ui));
        p.setBrush(kContactMark);
        p.drawPolygon(QPolygonF({at, at - n * size + t * size * 0.6, at - n * size - t * size * 0.6}));
    }
    // Blocks too thin on screen for a number at each corner (a whole ladder
    // in a small view): each hinge says at which corner k its blocks meet.
    if (options_.cornerNumbers && cornerFont < 7 && blockPixels > 14) {
        QFont small = font;
        small.setPixelSize(int(std::lround(9.5 * ui)));
        p.setFont(small);
        for (const jl::HingeFrame& h : frame_->hinges)
            haloText(p, map(h.position) + QPointF(r + 6 * ui, 0), QString::number(h.corner), kCornerInk);
    }
    if (frame_->dragging) {
        p.setPen(QPen(QColor(200, 30, 30), 2 * ui, Qt::DashLine, Qt::RoundCap));
        p.drawLine(map(frame_->dragFrom), map(frame_->dragTo));
        p.setBrush(QColor(200, 30, 30));
        p.setPen(Qt::NoPen);
        p.drawEllipse(map(frame_->dragTo), 4 * ui, 4 * ui);
    }

    p.setFont(font);
    const QFontMetricsF m(font);
    const double pad = 8 * ui;
    if (options_.clock) {
        p.setPen(kSideInk);
        p.drawText(QPointF(target.left() + pad, target.top() + pad + m.ascent()),
                   tr("t = %1 s").arg(frame_->time, 0, 'f', 3));
        // At an event's instant (N, or a click on it), what happened there:
        // in presentation mode the class sees no status bar.
        QStringList happened;
        for (const jl::Event& e : frame_->events)
            if (e.time == frame_->time) happened << whatHappened(e);
        if (!happened.isEmpty()) {
            QFont small = font;
            small.setPixelSize(std::max(6, int(std::lround(font.pixelSize() * 0.85))));
            p.setFont(small);
            const QRectF room(target.left() + pad, target.top() + pad + m.height() * 1.15, target.width() - 2 * pad,
                              target.height() / 3);
            const QRectF used = p.boundingRect(room, Qt::TextWordWrap, happened.join('\n'));
            p.fillRect(used.adjusted(-3 * ui, -2 * ui, 3 * ui, 2 * ui), QColor(255, 255, 255, 140));
            p.setPen(kSideInk);
            p.drawText(room, Qt::TextWordWrap, happened.join('\n'));
            p.setFont(font);
        }
    }
    paintScaleAndLegend(p, target, cell * map.scale, cell, ui);
    p.restore();
}

}  // namespace jl::ui
