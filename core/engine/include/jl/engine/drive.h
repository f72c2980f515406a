// The prescribed path of a held block: a base pose plus smooth timed moves.
#pragma once

#include "jl/base/geometry.h"

#include <vector>

namespace jl {

// A move of the held block's centre by `offset` and a turn about its centre by
// `turn`, from t0 over `duration`, along the smooth profile (1 - cos(pi s))/2
// of docs/model.md section 10: velocity is continuous, acceleration jumps only at
// the ends (where the force tests run).
struct DriveMove {
    double t0 = 0;
    double duration = 0;
    Vec2 offset = Vec2::Zero();
    double turn = 0;
};

struct DriveSample {
    Pose pose;
    Twist velocity;
    Twist acceleration;
};

class Drive {
public:
    Drive() = default;
    explicit Drive(const Pose& base) : base_(base) {}

    void add(const DriveMove& m) { moves_.push_back(m); }
    // The path at time t. Its acceleration jumps where a move starts and
    // where it stops; an instant there belongs to the piece that starts
    // there (right-continuous), which is what the step that starts there and
    // the force tests there must see.
    DriveSample at(double t) const { return at(t, t); }
    // The path at time t along the piece that holds the instant `within`:
    // a step from t0 to t1, which never straddles an end of a move, takes
    // all its stages, those at its ends included, from the piece of its
    // midpoint. The step that ends where a move starts sees no turn at its
    // end, the one that ends where it stops sees the turn's deceleration.
    DriveSample at(double t, double within) const;
    // Whether the instants a and b lie on the same piece of every move.
    bool samePiece(double a, double b) const;
    const std::vector<DriveMove>& moves() const { return moves_; }
    const Pose& base() const { return base_; }

private:
    Pose base_;
    std::vector<DriveMove> moves_;
};

}  // namespace jl
