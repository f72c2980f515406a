#include "ui/teaching/side_view.h"

#include "jl/ladder/block_corners.h"
#include "jl/ladder/ladder.h"
#include "jl/scene/ladder_blocks.h"
#include "ui/teaching/side_view_sheet.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jl::ui {

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
    // A spring's fixed end is in the picture too (where the chain hangs from).
    for (const auto& [a, b] : f.springs)
        for (const jl::Vec2& e : {a, b}) {
            x0 = std::min(x0, e.x()), x1 = std::max(x1, e.x());
            y0 = std::min(y0, e.y()), y1 = std::max(y1, e.y());
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

}  // namespace jl::ui
