// Where the viewer stands: an orbit about a target (yaw, pitch, distance)
// that also walks (the target and the eye move together) and looks around
// from the eye.
#pragma once

#include "jl/scene/scene.h"

#include <QVector3D>

#include <span>

namespace Qt3DRender {
class QCamera;
}

namespace jl::ui {

class ViewCamera {
public:
    // The yaw is the scene's: three-quarters unless the file says otherwise
    // (jl::ViewSpec), since edge-on (yaw 0) the blocks are a zig-zag of
    // sticks without the faces and ribbons that show each flip.
    static constexpr float kFieldOfView = 40.0f;  // degrees, vertical

    // From the scene's view; the default one widened to show a ladder reaching `extent` below the hand.
    void reset(const jl::ViewSpec& view, double extent);
    // Keeps the direction of view and moves the target and the distance so
    // every point is in a view of width/height `aspect`, with a margin.
    void frame(std::span<const QVector3D> points, float aspect);
    void orbit(float dyawDeg, float dpitchDeg);
    void lookAround(float dyawDeg, float dpitchDeg);  // turns about the eye (walk mode)
    void zoom(float steps);                           // wheel notches; > 0 closer
    // The same, toward (or away from) `point`, which stays where it is on
    // the screen: the whole view scales about it (the wheel under the
    // pointer, to look at the top of a long ladder without losing it).
    void zoomAbout(float steps, const QVector3D& point);
    void pan(float dx, float dy);                     // in fractions of the view's height
    void walk(float forward, float right, float up);  // m
    // Moves target and eye together by `d` (m): following the ladder.
    void shift(const QVector3D& d) { target_ += d; }
    void apply(Qt3DRender::QCamera* camera) const;
    QVector3D eye() const;
    QVector3D target() const { return target_; }
    float distance() const { return distance_; }
    float yaw() const { return yaw_; }

private:
    QVector3D direction() const;  // from the target toward the eye
    QVector3D target_{0, -0.15f, 0};
    float distance_ = 0.8f, yaw_ = 0, pitch_ = 10;
};

}  // namespace jl::ui
