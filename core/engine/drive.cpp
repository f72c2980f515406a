#include "jl/engine/drive.h"

#include <numbers>

namespace jl {

namespace {

// The smooth profile and its first two derivatives with respect to time.
struct Profile {
    double value, rate, accel;
};

Profile smooth(const DriveMove& m, double t) {
    if (t <= m.t0) return {0, 0, 0};
    if (m.duration <= 0 || t >= m.t0 + m.duration) return {1, 0, 0};
    const double pi = std::numbers::pi;
    const double s = (t - m.t0) / m.duration;
    const double w = pi / m.duration;
    return {(1 - std::cos(pi * s)) / 2, w * std::sin(pi * s) / 2, w * w * std::cos(pi * s) / 2};
}

}  // namespace

DriveSample Drive::at(double t) const {
    DriveSample d{base_, {}, {}};
    for (const DriveMove& m : moves_) {
        const Profile p = smooth(m, t);
        d.pose.position += p.value * m.offset;
        d.pose.angle += p.value * m.turn;
        d.velocity.linear += p.rate * m.offset;
        d.velocity.angular += p.rate * m.turn;
        d.acceleration.linear += p.accel * m.offset;
        d.acceleration.angular += p.accel * m.turn;
    }
    return d;
}

}  // namespace jl
