#include "ui/edit/restructure_gesture.h"

#include "jl/ladder/block_corners.h"
#include "jl/ladder/ladder.h"
#include "ui/view3d/block_shapes.h"

#include <QMenu>
#include <QObject>
#include <QPainter>

#include <algorithm>
#include <cmath>
#include <utility>

namespace jl::ui {

namespace {
using Kind = jl::ScriptAction::Kind;
const QColor kSelection(20, 90, 200);  // apart from the event ring's red
const QColor kJoin(200, 30, 30), kSnapped(30, 150, 60);
constexpr int kMostCornersDrawn = 400;  // a long ladder's corners would be a smear, not a hint
}  // namespace

void RestructureGesture::setScene(const jl::Scene& scene) {
    cornerLocal_.clear();
    halfSize_.clear();
    if (scene.ladder && !jl::Ladder::validate(*scene.ladder)) {
        cornerLocal_ = jl::blockCorners(*scene.ladder);
        for (const BlockShape& s : blockShapes(scene)) halfSize_.emplace_back(s.across / 2, s.along / 2);
        halfSize_.resize(cornerLocal_.size());
    }
    shown_ = std::make_shared<const jl::Frame>();
    selected_ = 0;
    joinFrom_.reset();
    snappedTo_.reset();
}

void RestructureGesture::showFrame(std::shared_ptr<const jl::Frame> frame) {
    if (!frame) return;
    shown_ = std::move(frame);
    // A hinge cut since (or gone with an edit) is no longer a selection.
    if (selected_ > int(shown_->hinges.size()) ||
        (selected_ > 0 && shown_->hinges[size_t(selected_ - 1)].mode == jl::HingeMode::Cut))
        selected_ = 0;
}

jl::Vec2 RestructureGesture::position(const BlockCorner& c) const {
    return shown_->poses[size_t(c.block)].apply(cornerLocal_[size_t(c.block)][size_t(c.corner)]);
}

// Hinge j pins corner k of blocks j-1 and j; locked it holds k ^ 2 too,
// folded k ^ 1 (docs/model.md 3.6).
bool RestructureGesture::isFree(const BlockCorner& c) const {
    const auto holds = [&](int j) {
        if (j < 1 || j > int(shown_->hinges.size())) return false;
        const jl::HingeFrame& h = shown_->hinges[size_t(j - 1)];
        switch (h.mode) {
            case jl::HingeMode::Free:
                return c.corner == h.corner;
            case jl::HingeMode::OpenLocked:
                return c.corner == h.corner || c.corner == (h.corner ^ 2);
            case jl::HingeMode::Folded:
                return c.corner == h.corner || c.corner == (h.corner ^ 1);
            case jl::HingeMode::Cut:
                return false;
        }
        return false;
    };
    return !holds(c.block) && !holds(c.block + 1);
}

// What the engine refuses, as far as a frame shows it: the same block, two
// held blocks, neighbours that share a hinge, blocks locked or folded into
// one body. (A pin an earlier join made is not in the frame: the engine
// refuses that join and says so in the event log.)
bool RestructureGesture::joinable(int a, int b) const {
    if (a == b) return false;
    const auto held = [&](int i) { return i < int(shown_->held.size()) && shown_->held[size_t(i)]; };
    if (held(a) && held(b)) return false;
    const int lo = std::min(a, b), hi = std::max(a, b);
    if (hi > int(shown_->hinges.size())) return false;
    if (hi - lo == 1 && shown_->hinges[size_t(hi - 1)].mode != jl::HingeMode::Cut) return false;
    for (int j = lo + 1; j <= hi; ++j) {
        const jl::HingeMode m = shown_->hinges[size_t(j - 1)].mode;
        if (m != jl::HingeMode::OpenLocked && m != jl::HingeMode::Folded) return true;
    }
    return false;
}

int RestructureGesture::hingeNear(const jl::Vec2& point, double reach) const {
    int best = 0;
    double nearest = reach;
    for (size_t j = 0; j < shown_->hinges.size(); ++j) {
        if (shown_->hinges[j].mode == jl::HingeMode::Cut) continue;
        const double d = (shown_->hinges[j].position - point).norm();
        if (d <= nearest) nearest = d, best = int(j + 1);
    }
    return best;
}

std::optional<BlockCorner> RestructureGesture::freeCornerNear(
    const jl::Vec2& point, double reach, const std::function<bool(const BlockCorner&)>& accept) const {
    std::optional<BlockCorner> best;
    double nearest = reach;
    for (int b = 0; b < blocks(); ++b)
        for (int k = 0; k < 4; ++k) {
            const BlockCorner c{b, k};
            const double d = (position(c) - point).norm();
            if (d <= nearest && isFree(c) && accept(c)) nearest = d, best = c;
        }
    return best;
}

int RestructureGesture::blockAt(const jl::Vec2& point) const {
    constexpr double margin = 0.002;  // m, as the views' own picks
    for (size_t i = size_t(blocks()); i-- > 0;) {
        const jl::Vec2 local = jl::rotate(-shown_->poses[i].angle, point - shown_->poses[i].position);
        if (std::abs(local.x()) <= halfSize_[i].x() + margin && std::abs(local.y()) <= halfSize_[i].y() + margin)
            return int(i);
    }
    return -1;
}

// A hinge before a corner: the hinge's dot is drawn over the corners it pins.
bool RestructureGesture::press(const jl::Vec2& point, double reach) {
    if (blocks() == 0) return false;
    selected_ = hingeNear(point, reach);
    if (selected_ > 0) return true;
    // Only on blocks thick enough on screen to tell their corners apart: on a
    // ladder seen whole, a press pushes or pans as before.
    joinFrom_ =
        freeCornerNear(point, reach, [&](const BlockCorner& c) { return 4 * halfSize_[size_t(c.block)].x() >= reach; });
    snappedTo_.reset();
    pointer_ = point;
    return joinFrom_.has_value();
}

void RestructureGesture::dragTo(const jl::Vec2& point, double snap) {
    if (!joinFrom_) return;
    pointer_ = point;
    const int from = joinFrom_->block;
    snappedTo_ = freeCornerNear(point, snap, [&](const BlockCorner& c) { return joinable(from, c.block); });
}

std::optional<GivenAction> RestructureGesture::release(const jl::Vec2& point, double snap) {
    dragTo(point, snap);
    const auto from = joinFrom_, to = snappedTo_;
    joinFrom_.reset();
    snappedTo_.reset();
    if (!from || !to) return std::nullopt;
    jl::ScriptAction a = row(Kind::Join);
    a.block = from->block;
    a.corner = from->corner;
    a.otherBlock = to->block;
    a.otherCorner = to->corner;
    return GivenAction{a, QObject::tr("Join block %1 to block %2").arg(a.block).arg(a.otherBlock)};
}

std::optional<std::pair<jl::Vec2, jl::Vec2>> RestructureGesture::joinLine() const {
    if (!joinFrom_) return std::nullopt;
    return std::pair{position(*joinFrom_), snappedTo_ ? position(*snappedTo_) : pointer_};
}

jl::ScriptAction RestructureGesture::row(Kind kind) const {
    jl::ScriptAction a;
    a.kind = kind;
    a.at = shown_->time;
    return a;
}

std::optional<GivenAction> RestructureGesture::cutSelected() {
    if (selected_ <= 0) return std::nullopt;
    jl::ScriptAction a = row(Kind::Cut);
    a.hinge = std::exchange(selected_, 0);
    return GivenAction{a, QObject::tr("Cut hinge %1").arg(a.hinge)};
}

std::vector<int> RestructureGesture::selectedBlocks() const {
    if (selected_ <= 0) return {};
    return {selected_ - 1, selected_};
}

void RestructureGesture::fillMenu(QMenu& menu, const jl::Vec2& point, double reach,
                                  const std::function<void(GivenAction)>& give) {
    if (blocks() == 0) return;
    if (const int j = hingeNear(point, reach)) {
        selected_ = j;
        menu.addAction(QObject::tr("Cut hinge %1").arg(j), [this, give] {
            if (auto cut = cutSelected()) give(*cut);
        });
    }
    // The corners of a cut hinge, as the scene's join row takes them: the hinge again.
    for (size_t j = 0; j + 1 < size_t(blocks()) && j < shown_->hinges.size(); ++j) {
        const jl::HingeFrame& h = shown_->hinges[j];
        const BlockCorner upper{int(j), h.corner}, lower{int(j + 1), h.corner};
        if (h.mode != jl::HingeMode::Cut ||
            std::min((position(upper) - point).norm(), (position(lower) - point).norm()) > reach)
            continue;
        jl::ScriptAction a = row(Kind::Join);
        a.block = upper.block, a.otherBlock = lower.block, a.corner = a.otherCorner = h.corner;
        menu.addAction(QObject::tr("Join hinge %1 again").arg(j + 1), [give, a, j] {
            give({a, QObject::tr("Join hinge %1 again").arg(j + 1)});
        });
    }
    if (const int b = blockAt(point); b >= 0) {
        const bool held = b < int(shown_->held.size()) && shown_->held[size_t(b)];
        jl::ScriptAction a = row(held ? Kind::Release : Kind::Hold);
        a.block = b;
        const QString text = held ? QObject::tr("Release block %1").arg(b) : QObject::tr("Hold block %1 here").arg(b);
        menu.addAction(text, [give, a, text] { give({a, text}); });
    }
}

void RestructureGesture::popMenu(QWidget* parent, const jl::Vec2& point, double reach, const QPoint& screen,
                                 const std::function<void(GivenAction)>& give) {
    auto* m = new QMenu(parent);
    m->setObjectName("restructureMenu");
    m->setAttribute(Qt::WA_DeleteOnClose);
    fillMenu(*m, point, reach, give);
    if (m->isEmpty())
        delete m;
    else
        m->popup(screen);
}

void RestructureGesture::paint(QPainter& p, const std::function<QPointF(const jl::Vec2&)>& pixel, double ui) const {
    p.save();
    p.setBrush(Qt::NoBrush);
    if (selected_ > 0) {
        p.setPen(QPen(kSelection, 3 * ui));
        p.drawEllipse(pixel(shown_->hinges[size_t(selected_ - 1)].position), 11 * ui, 11 * ui);
    }
    if (joinFrom_) {
        // Where the corner may go: every free corner of a block it may join.
        if (blocks() * 4 <= kMostCornersDrawn) {
            p.setPen(QPen(kSnapped, 1.5 * ui));
            for (int b = 0; b < blocks(); ++b)
                for (int k = 0; k < 4; ++k)
                    if (isFree({b, k}) && joinable(joinFrom_->block, b))
                        p.drawEllipse(pixel(position({b, k})), 4 * ui, 4 * ui);
        }
        const auto [from, to] = *joinLine();
        p.setPen(QPen(snappedTo_ ? kSnapped : kJoin, 2 * ui, Qt::DashLine, Qt::RoundCap));
        p.drawLine(pixel(from), pixel(to));
        p.setPen(QPen(snappedTo_ ? kSnapped : kJoin, 3 * ui));
        p.drawEllipse(pixel(from), 5 * ui, 5 * ui);
        if (snappedTo_) p.drawEllipse(pixel(to), 8 * ui, 8 * ui);
    }
    p.restore();
}

}  // namespace jl::ui
