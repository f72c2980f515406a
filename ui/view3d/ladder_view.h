// The 3-D view: the ladder (instanced blocks, ribbons, the mouse spring) in a
// room; orbit and walk camera; a press on a block starts a drag.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame.h"
#include "ui/edit/restructure_gesture.h"
#include "ui/edit/turn_gesture.h"
#include "ui/view3d/block_shapes.h"
#include "ui/view3d/ribbon_instances.h"
#include "ui/view3d/view_camera.h"

#include <QElapsedTimer>
#include <QKeySequence>
#include <QSet>
#include <QTimer>
#include <Qt3DExtras/Qt3DWindow>

#include <memory>
#include <optional>
#include <vector>

namespace Qt3DRender {
class QRenderCapture;
}

namespace jl::ui {

class BlockInstances;
class StripEntity;
class Room;
class ScaleMark;

class LadderView : public Qt3DExtras::Qt3DWindow {
    Q_OBJECT
public:
    LadderView();

    // A new or edited scene: shapes, colours and the room; the camera too when asked.
    void setScene(const jl::Scene& scene, bool resetCamera);
    void showFrame(const jl::Frame& frame);
    // The simulation's published frame, shared rather than copied.
    void showFrame(std::shared_ptr<const jl::Frame> frame);
    // The blocks drawn highlighted because an event's hinge joins them.
    const std::vector<int>& pointedAt() const { return pointedAt_; }
    void resetView();
    // Keeps the direction of view and fits the whole ladder, as last shown, in the view.
    void frameLadder();
    // The same for the stretch of blocks around the one that moved most
    // between the last two frames shown (while playing, however far apart
    // the window could draw them), and their neighbours: on a long ladder,
    // where the action is. False
    // (the whole ladder framed) when there are no two such frames or
    // nothing moved.
    bool frameMotion();
    const ViewCamera& viewCamera() const { return camera_; }
    // Turns the viewer about the target, as a drag off the blocks (left or
    // right button) does.
    void orbit(float yawDegrees, float pitchDegrees);
    void setWalkMode(bool on);
    bool walkMode() const { return walk_; }
    // Follow the ladder: the camera moves with the blocks' centre, frame by
    // frame, keeping its direction and distance (a ladder that swings away
    // stays in view).
    void setFollow(bool on);
    bool follow() const { return follow_; }

    Qt3DRender::QRenderCapture* capture() const { return capture_; }
    // The point of the ladder's plane (z = 0) under a window pixel.
    std::optional<jl::Vec2> planePoint(const QPointF& pixel) const;
    // Where a point of the ladder's plane appears in the window (for tests and hints).
    // The scale bar beside the point looked at (its round length, m).
    const ScaleMark* scaleMark() const { return scale_; }
    // Blocks in the instance buffer (those a pixel from the last are left out).
    int blocksDrawn() const;
    QPointF pixelOf(const jl::Vec2& point) const;
    // Whether a block as last shown covers this point of the plane (within
    // 2 mm, so thin blocks stay easy to grab): a left drag there pushes the
    // block, anywhere else it orbits the camera.
    bool blockAt(const jl::Vec2& point) const { return grabAt(point).has_value(); }
    // The block there, as last shown, and the point in its own frame: the
    // last block that covers it, as the engine's pick takes it.
    struct Grab {
        int block = -1;
        jl::Vec2 local = jl::Vec2::Zero();
    };
    std::optional<Grab> grabAt(const jl::Vec2& point) const;
    double shownTime() const { return shownTime_; }  // s, of the frame drawn

signals:
    // A push begun on `block` at `local` (its own frame) in the frame of
    // time `shownTime` that the view showed at the press.
    void dragBegun(const jl::Vec2& point, int block, const jl::Vec2& local, double shownTime);
    void dragMoved(const jl::Vec2& target);
    void dragEnded();
    // Shift and a drag on a block: the hand turns it (turn_gesture.h), from
    // the time `shownTime` the view showed at the press.
    void turnGiven(int block, double angle, double duration, double shownTime);
    // A cut, join, hold or release by hand (restructure_gesture.h), at the instant shown.
    void actionGiven(const jl::ScriptAction& action, const QString& text);
    // Keys the view does not use, for the main window's shortcuts (this
    // window, embedded, has the keyboard focus when the ladder is clicked).
    void unhandledKey(const QKeySequence& key);
    void walkModeChanged(bool on);

protected:
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    void keyReleaseEvent(QKeyEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;

private:
    void updateCamera();
    void showRibbons();  // those near the view, of the frame shown
    void walkTick();
    // The corners of every block as last shown, and of the ladder as built
    // (for before the first frame): what framing must keep in view.
    std::vector<QVector3D> ladderCorners() const;
    // Whether every corner of the ladder, as last shown, is in view (or nearly).
    bool showsWholeLadder() const;
    // Whether any of it is: its outline on screen meets the view.
    bool showsSomeOfLadder() const;

    // The restructuring by hand: the selected hinge's blocks highlighted,
    // the join drag's line drawn (red, green once it snaps).
    double metresOf(double pixels, const QPointF& at) const;
    void showRestructure();
    std::vector<int> highlighted() const;  // the event's blocks and the selected hinge's
    void give(std::optional<GivenAction> given);
    RestructureGesture restructure_;
    QPointF rightPressAt_;  // a right press and release in one place is a click: the menu

    std::optional<TurnGesture> turning_;
    double turnShownTime_ = 0;  // s, the frame shown at the turn's press
    QElapsedTimer turnClock_;   // how long the hand has swept

    Qt3DCore::QEntity* root_;
    BlockInstances* blocks_;
    RibbonInstances* ribbons_;         // the outer pairs
    RibbonInstances* centralRibbons_;  // the middle ribbons (a colour of their own)
    StripEntity* dragLine_;
    StripEntity* springs_;  // a general scene's springs
    Room* room_;
    ScaleMark* scale_;  // how long a length on screen is
    Qt3DRender::QRenderCapture* capture_;
    ViewCamera camera_;
    jl::ViewSpec view_;
    std::vector<BlockShape> shapes_;
    std::vector<jl::Pose> shownPoses_;
    double shownTime_ = 0;                // s, the frame drawn
    std::vector<jl::Pose> earlierPoses_;  // of the frame drawn before it (frameMotion)
    jl::Vec2 hand_ = jl::Vec2::Zero();    // the first held block's centre in the frame shown (m)
    double earlierTime_ = 0;
    // The ladder is framed again on the first frame after a load or a change
    // of size: only a frame says where the blocks are.
    bool frameOnNextFrame_ = false;
    double extent_ = 0.36;
    double blockWidth_ = 0.045;
    jl::RibbonSpec ribbonSpec_;
    std::optional<jl::LadderSpec> ladder_;   // whose ribbons to draw
    std::vector<jl::BlockSpec> blockSpecs_;  // its blocks, as built
    double blockLength_ = 0.06;
    std::shared_ptr<const jl::Frame> shownFrame_;  // whose ribbons are drawn
    BlockSpan ribbonsNear_;                        // the blocks whose ribbons are drawn
    bool ribbonsStale_ = false;                    // a new frame, or ribbons of another kind
    bool walk_ = false;
    bool follow_ = false;
    std::optional<jl::Vec2> followedCentre_;  // the blocks' centre at the last frame followed
    bool dragging_ = false;
    bool orbiting_ = false;  // a left drag that began off every block
    int grabbed_ = -1;
    std::vector<int> pointedAt_;  // blocks joined by the hinge of an event at the instant on screen
    QPointF lastMouse_;
    QSet<int> keysDown_;
    QTimer walkTimer_;
    QElapsedTimer walkClock_;
};

}  // namespace jl::ui
