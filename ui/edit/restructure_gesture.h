// Restructuring by hand, in the 3-D view and the side view alike: a click
// by a hinge selects it (Delete or its menu cuts it), a free corner dragged
// onto another block's free corner joins them (it snaps when near), and a
// block's menu holds or releases it. Each gives a script row at the instant
// shown, so a replay and a saved file do the same (docs/model.md 11.4).
// The views own one each and ask it what a press, a drag and a menu mean;
// both the views and the gesture work in the ladder's plane (m).
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame.h"

#include <QString>

#include <algorithm>
#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QMenu;
class QPainter;
class QPoint;
class QPointF;
class QWidget;

namespace jl::ui {

// Corner `corner` (0..3, the engine's numbering) of ladder block `block`.
struct BlockCorner {
    int block = -1;
    int corner = 0;
    bool operator==(const BlockCorner&) const = default;
};

// A script row and the words of its undo step.
struct GivenAction {
    jl::ScriptAction action;
    QString text;
};

class RestructureGesture {
public:
    // On screen: how near a press picks a hinge or a corner, and how near a dragged corner snaps.
    static constexpr double kReachPixels = 8, kSnapPixels = 18;

    void setScene(const jl::Scene& scene);
    // The instant shown (shared, not copied, 60 times a second): what a
    // press picks, and the time of the rows given.
    void showFrame(std::shared_ptr<const jl::Frame> frame);
    const jl::Frame& shown() const { return *shown_; }

    // A left press at `point` within `reach` (m, a few pixels) of an uncut
    // hinge selects it; of a free corner of a block at least half `reach` thick,
    // starts a join drag. False: the press is not the gesture's (the view
    // pushes, pans or orbits).
    bool press(const jl::Vec2& point, double reach);
    // During a join drag: the pointer, and how near (m) a corner snaps.
    void dragTo(const jl::Vec2& point, double snap);
    // The end of a join drag, at `point`: the join row when it snapped.
    std::optional<GivenAction> release(const jl::Vec2& point, double snap);
    bool joining() const { return joinFrom_.has_value(); }

    int selectedHinge() const { return selected_; }  // 1..N-1; 0: none
    // The cut of the selected hinge (Delete), at the instant shown.
    std::optional<GivenAction> cutSelected();
    // The blocks drawn highlighted for the selection.
    std::vector<int> selectedBlocks() const;

    // The context menu at `point`: "Cut hinge N" by a hinge, "Join hinge N
    // again" by a cut one, "Hold block N here" or "Release block N" on a
    // block, shown at `screen` (none when nothing is there); it deletes itself once closed.
    void popMenu(QWidget* parent, const jl::Vec2& point, double reach, const QPoint& screen,
                 const std::function<void(GivenAction)>& give);

    // The selection and the join drag, drawn over the side view's picture.
    void paint(QPainter& p, const std::function<QPointF(const jl::Vec2&)>& pixel, double ui) const;
    // The join drag's line, for the 3-D view: from the corner to the pointer or the snapped corner.
    std::optional<std::pair<jl::Vec2, jl::Vec2>> joinLine() const;
    bool snapped() const { return snappedTo_.has_value(); }

    // Corners no hinge holds: not the pin of an uncut hinge, nor the second
    // point of a locked or folded one.
    bool isFree(const BlockCorner& c) const;
    jl::Vec2 position(const BlockCorner& c) const;

private:
    int blocks() const { return int(std::min(shown_->poses.size(), cornerLocal_.size())); }  // of the ladder, shown
    void fillMenu(QMenu& menu, const jl::Vec2& point, double reach, const std::function<void(GivenAction)>& give);
    int hingeNear(const jl::Vec2& point, double reach) const;
    std::optional<BlockCorner> freeCornerNear(const jl::Vec2& point, double reach,
                                              const std::function<bool(const BlockCorner&)>& accept) const;
    bool joinable(int a, int b) const;
    int blockAt(const jl::Vec2& point) const;
    jl::ScriptAction row(jl::ScriptAction::Kind kind) const;

    std::vector<std::array<jl::Vec2, 4>> cornerLocal_;  // ladder blocks, from jl::blockCorners
    std::vector<jl::Vec2> halfSize_;                    // across, along: for a press on a block
    std::shared_ptr<const jl::Frame> shown_ = std::make_shared<const jl::Frame>();
    int selected_ = 0;
    std::optional<BlockCorner> joinFrom_, snappedTo_;
    jl::Vec2 pointer_ = jl::Vec2::Zero();
};

}  // namespace jl::ui
