// Planar geometry: vectors, rotations and the 2-D cross product used everywhere.
#pragma once

#include <Eigen/Core>

#include <cmath>

namespace jl {

using Vec2 = Eigen::Vector2d;

inline Vec2 rotate(double angle, const Vec2& r) {
    const double c = std::cos(angle), s = std::sin(angle);
    return {c * r.x() - s * r.y(), s * r.x() + c * r.y()};
}

// perp(r) = z x r: the velocity of point r on a body turning at unit rate.
inline Vec2 perp(const Vec2& r) { return {-r.y(), r.x()}; }

// The z component of a x b.
inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// A planar pose: position of a frame's origin and its angle.
struct Pose {
    Vec2 position = Vec2::Zero();
    double angle = 0;

    Vec2 apply(const Vec2& local) const { return position + rotate(angle, local); }
    Pose compose(const Pose& local) const { return {apply(local.position), angle + local.angle}; }
    Pose inverse() const { return {-rotate(-angle, position), -angle}; }
};

// A planar twist (velocity) or its time derivative, of a frame's origin.
struct Twist {
    Vec2 linear = Vec2::Zero();
    double angular = 0;
};

}  // namespace jl
