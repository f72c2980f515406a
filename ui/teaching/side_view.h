// The 2-D side view: the ladder as the paper draws it (blocks, hinges
// coloured by mode, corner numbers, orientation arrows, ribbons, the drag
// line), painted with QPainter so it works without OpenGL and offscreen.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame.h"
#include "ui/edit/restructure_gesture.h"
#include "ui/edit/turn_gesture.h"
#include "ui/view3d/block_shapes.h"

#include <QElapsedTimer>
#include <QImage>
#include <QRectF>
#include <QWidget>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace jl::ui {

struct SideViewOptions {
    bool blockNumbers = true;
    bool cornerNumbers = false;  // the paper's 0..3 (k^1 along, k^2 across)
    bool orientation = false;    // lengthwise orientation: corner 0 towards corner 1
    bool ribbons = true;
    bool legend = true;
    bool clock = true;   // "t = 0.700 s" in a corner, and under it the events of that very instant
    double scale = 1.0;  // fonts and lines; 2 or more for a projector
};

class SideView : public QWidget {
    Q_OBJECT
public:
    explicit SideView(QWidget* parent = nullptr);

    // Sizes, colours and corner positions of the blocks come from the scene
    // (frames carry only poses); the framing starts afresh.
    void setScene(const jl::Scene& scene);
    void showFrame(const jl::Frame& frame);
    // The simulation's published frame, shared rather than copied (60 times a second).
    void showFrame(std::shared_ptr<const jl::Frame> frame);
    const jl::Frame& frame() const { return *frame_; }
    void setOptions(const SideViewOptions& o);
    const SideViewOptions& options() const { return options_; }

    // The part of the plane shown (m). It grows to keep every block in view
    // and never shrinks by itself, so the picture does not jump about; once
    // zoomed (wheel) or panned (drag) by hand it stays put until a double
    // click or resetFraming.
    QRectF framing() const { return framing_; }
    // Where the scale bar's length was last written (empty before a paint).
    QRectF scaleLabelRect() const { return scaleLabel_; }
    void setFraming(const QRectF& plane);
    void resetFraming();
    bool following() const { return following_; }
    // Everything frame `f` occupies in the plane (m).
    QRectF extentOf(const jl::Frame& f) const;

    // Draws the current frame into `target` (any paint device: the widget,
    // an image, an SVG file).
    void paint(QPainter& p, const QRectF& target) const;
    QImage render(const QSize& size) const;
    // Where a point of the plane lands in a picture of `target` (for tests and hints).
    QPointF pixelOf(const jl::Vec2& point, const QRectF& target) const;

    // The point of the plane under a pixel of the widget, and the ladder
    // block there as last shown (-1: none; within 2 mm, as in the 3-D view).
    jl::Vec2 planePoint(const QPointF& pixel) const;
    int blockAt(const jl::Vec2& point) const;

    QSize sizeHint() const override { return {420, 560}; }

signals:
    // Shift and a drag on a block: the hand turns it (turn_gesture.h), from
    // the time `shownTime` of the frame shown at the press.
    void turnGiven(int block, double angle, double duration, double shownTime);
    // A cut, join, hold or release by hand (restructure_gesture.h), at the instant shown.
    void actionGiven(const jl::ScriptAction& action, const QString& text);

protected:
    void paintEvent(QPaintEvent*) override;
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void contextMenuEvent(QContextMenuEvent* e) override;

private:
    struct Mapping;  // side_view_sheet.h
    struct Sheet;
    std::array<jl::Vec2, 4> corners(int block) const;  // in the plane, numbered as the engine numbers them
    void growFraming(const QRectF& need);
    QRectF plotArea(const QRectF& target, double ui) const;
    double uiScale(const QRectF& target) const;
    double metresOf(double pixels) const;  // on screen now
    // The layers of a picture, bottom to top (side_view_paint.cpp).
    void paintGrid(const Sheet& s, double cell) const;
    void paintTable(const Sheet& s) const;
    void paintThread(const Sheet& s) const;
    void paintBlockFaces(const Sheet& s) const;
    void paintSprings(const Sheet& s) const;
    void paintParticles(const Sheet& s) const;
    void paintRibbons(const Sheet& s) const;
    void paintOrientation(const Sheet& s) const;
    void paintCornerNumbers(const Sheet& s) const;
    void paintBlockNumbers(const Sheet& s) const;
    void paintHinges(const Sheet& s) const;
    void paintContacts(const Sheet& s) const;
    void paintHingeCorners(const Sheet& s) const;
    void paintDrag(const Sheet& s) const;
    void paintClock(const Sheet& s) const;
    // One grid cell as a bar at the bottom left (`cell` m, `cellPixels`
    // long), and the hinge modes' legend at the bottom right.
    void paintScaleAndLegend(QPainter& p, const QRectF& target, double cellPixels, double cell, double ui) const;
    void give(std::optional<GivenAction> given);

    std::vector<BlockShape> shapes_;
    std::vector<std::array<jl::Vec2, 4>> cornerLocal_;  // ladder blocks, from jl::blockCorners
    int ladderBlocks_ = 0, firstParticle_ = 0;
    QColor ribbonColor_{40, 60, 140};
    QColor centralRibbonColor_;
    double ribbonThickness_ = 0.0005;
    std::optional<jl::LadderSpec> ladder_;   // whose ribbons to draw
    std::optional<double> floor_;            // m, the table top's height
    std::vector<jl::BlockSpec> blockSpecs_;  // its blocks, as built
    std::shared_ptr<const jl::Frame> frame_ = std::make_shared<const jl::Frame>();
    QRectF framing_;
    mutable QRectF scaleLabel_;
    bool following_ = true;  // the framing grows with the ladder (until zoomed or panned by hand)
    QPointF dragFrom_;
    std::optional<TurnGesture> turning_;
    double turnShownTime_ = 0;  // s
    QElapsedTimer turnClock_;
    RestructureGesture restructure_;
    SideViewOptions options_;
};

// Hinge colours by mode, used by the side view and its legend.
QColor hingeColor(jl::HingeMode mode);

}  // namespace jl::ui
