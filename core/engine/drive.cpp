#include "jl/engine/drive.h"

#include <numbers>

namespace jl {

namespace {

// The smooth profile and its first two derivatives with respect to time.
struct Profile {
    double value, rate, accel;
};

// 0 before the move, 1 while it lasts, 2 after it.
int piece(const DriveMove& m, double t) {
    if (t < m.t0) return 0;
    return m.duration <= 0 || t >= m.t0 + m.duration ? 2 : 1;
}

// The piece is chosen by `within` and evaluated at t: on a piece's own
// ends the formula is the one-sided limit.
Profile smooth(const DriveMove& m, double t, double within) {
    const int at = piece(m, within);
    if (at == 0) return {0, 0, 0};
    if (at == 2) return {1, 0, 0};
    const double pi = std::numbers::pi;
    const double s = (t - m.t0) / m.duration;
    const double w = pi / m.duration;
    return {(1 - std::cos(pi * s)) / 2, w * std::sin(pi * s) / 2, w * w * std::cos(pi * s) / 2};
}

}  // namespace

DriveSample Drive::at(double t, double within) const {
    DriveSample d{base_, {}, {}};
    for (const DriveMove& m : moves_) {
        const Profile p = smooth(m, t, within);
        d.pose.position += p.value * m.offset;
        d.pose.angle += p.value * m.turn;
        d.velocity.linear += p.rate * m.offset;
        d.velocity.angular += p.rate * m.turn;
        d.acceleration.linear += p.accel * m.offset;
        d.acceleration.angular += p.accel * m.turn;
    }
    return d;
}

bool Drive::samePiece(double a, double b) const {
    for (const DriveMove& m : moves_)
        if (piece(m, a) != piece(m, b)) return false;
    return true;
}

}  // namespace jl
