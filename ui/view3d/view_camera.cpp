#include "ui/view3d/view_camera.h"

#include <Qt3DRender/QCamera>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace jl::ui {

namespace {
constexpr float kFieldOfView = ViewCamera::kFieldOfView;
// The framed points fill this fraction of the view, each way: a margin
// around the ladder, and room for the blocks to swing out a little.
constexpr float kFramedFill = 0.85f;
float radians(float deg) { return deg * std::numbers::pi_v<float> / 180.0f; }
}  // namespace

void ViewCamera::reset(const jl::ViewSpec& view, double extent) {
    target_ = QVector3D(float(view.target[0]), float(view.target[1]), 0);
    distance_ = float(view.distance);
    yaw_ = float(view.yaw);  // the file's, or the three-quarter default of jl::ViewSpec
    pitch_ = float(view.pitch);
    // A default view on a ladder longer than it shows: frame the whole
    // ladder. A scene that says where to look is looked at there (a long
    // ladder's lesson may be at its top, where the blocks show).
    const jl::ViewSpec unsaid;
    const bool said = view.target != unsaid.target || view.distance != unsaid.distance;
    const float visible = 2 * distance_ * std::tan(radians(kFieldOfView / 2));
    if (!said && extent > visible * 0.9) {
        distance_ = float(extent) * 1.15f / (2 * std::tan(radians(kFieldOfView / 2)));
        target_.setY(-float(extent) / 2);
    }
}

void ViewCamera::frame(std::span<const QVector3D> points, float aspect) {
    if (points.empty()) return;
    QVector3D lo = points.front(), hi = points.front();
    for (const QVector3D& p : points) {
        lo = QVector3D(std::min(lo.x(), p.x()), std::min(lo.y(), p.y()), std::min(lo.z(), p.z()));
        hi = QVector3D(std::max(hi.x(), p.x()), std::max(hi.y(), p.y()), std::max(hi.z(), p.z()));
    }
    target_ = (lo + hi) / 2;
    // In the camera's axes a point at `side` right, `rise` up and `depth`
    // toward the viewer from the target is in view when its offset over its
    // distance from the eye is within the half-angle's tangent: the nearest
    // eye distance that holds for every point.
    const QVector3D back = direction();
    const QVector3D right = QVector3D::crossProduct(-back, {0, 1, 0}).normalized();
    const QVector3D up = QVector3D::crossProduct(right, -back).normalized();
    const float tanUp = std::tan(radians(kFieldOfView / 2)) * kFramedFill;
    const float tanSide = tanUp * std::max(aspect, 0.1f);
    float needed = 0.02f;
    for (const QVector3D& p : points) {
        const QVector3D d = p - target_;
        const float depth = QVector3D::dotProduct(d, back);
        needed = std::max(needed, depth + std::abs(QVector3D::dotProduct(d, right)) / tanSide);
        needed = std::max(needed, depth + std::abs(QVector3D::dotProduct(d, up)) / tanUp);
    }
    distance_ = std::min(needed, 5000.0f);
}

QVector3D ViewCamera::direction() const {
    const float y = radians(yaw_), p = radians(pitch_);
    return {std::sin(y) * std::cos(p), std::sin(p), std::cos(y) * std::cos(p)};
}

QVector3D ViewCamera::eye() const { return target_ + direction() * distance_; }

void ViewCamera::orbit(float dyawDeg, float dpitchDeg) {
    yaw_ += dyawDeg;
    pitch_ = std::clamp(pitch_ + dpitchDeg, -85.0f, 85.0f);
}

void ViewCamera::lookAround(float dyawDeg, float dpitchDeg) {
    const QVector3D e = eye();
    orbit(dyawDeg, dpitchDeg);
    target_ = e - direction() * distance_;
}

void ViewCamera::zoom(float steps) { distance_ = std::clamp(distance_ * std::pow(0.88f, steps), 0.02f, 5000.0f); }

void ViewCamera::zoomAbout(float steps, const QVector3D& point) {
    const float before = distance_;
    zoom(steps);
    // Eye and target scaled about the point by the same factor: the line
    // from the eye to the point keeps its direction, so its pixel stays.
    target_ = point + (target_ - point) * (distance_ / before);
}

void ViewCamera::pan(float dx, float dy) {
    const QVector3D forward = -direction();
    const QVector3D right = QVector3D::crossProduct(forward, {0, 1, 0}).normalized();
    const QVector3D up = QVector3D::crossProduct(right, forward).normalized();
    const float h = 2 * distance_ * std::tan(radians(kFieldOfView / 2));
    target_ += (-dx * right + dy * up) * h;
}

void ViewCamera::walk(float forward, float right, float up) {
    QVector3D f = -direction();
    f.setY(0);  // walking stays level, like a person in the room
    if (f.lengthSquared() > 0) f.normalize();
    const QVector3D r = QVector3D::crossProduct(f, {0, 1, 0}).normalized();
    target_ += f * forward + r * right + QVector3D(0, up, 0);
}

void ViewCamera::apply(Qt3DRender::QCamera* camera) const {
    camera->setFieldOfView(kFieldOfView);
    // Near and far follow the distance so depth precision stays where we look.
    camera->setNearPlane(std::max(0.002f, distance_ * 0.02f));
    camera->setFarPlane(std::max(60.0f, distance_ * 60.0f));
    camera->setUpVector({0, 1, 0});
    camera->setPosition(eye());
    camera->setViewCenter(target_);
}

}  // namespace jl::ui
