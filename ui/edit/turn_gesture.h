// The hand's turn, given with the mouse: Shift and a drag on a block sweeps
// an angle about the block's centre (the point a scripted turn turns it
// about). On release the angle snaps to a quarter turn and the turn takes
// as long as the hand took to sweep that much: a script row, replayed as
// any other.
#pragma once

#include "jl/base/geometry.h"

#include <optional>

namespace jl::ui {

struct Turn {
    int block = 0;
    double angle = 0;     // rad, counter-clockwise, a whole number of quarter turns
    double duration = 0;  // s
};

class TurnGesture {
public:
    TurnGesture(int block, const Vec2& centre, const Vec2& point);
    // The pointer at `seconds` after the press.
    void moveTo(const Vec2& point, double seconds);
    int block() const { return block_; }
    double swept() const { return swept_; }  // rad, so far
    // The turn the gesture gives: none under half a quarter turn. Its time
    // is the hand's from the last still moment before it swept to the last
    // move that swept: a wait before the sweep or before the release is
    // not part of the turn.
    std::optional<Turn> turn() const;
    static double snapped(double angle);  // to the nearest quarter turn

    // The shortest and longest turn a gesture gives (s): a flick is not an
    // impact, and a hand left on the mouse is not a turn of minutes.
    static constexpr double kShortest = 0.05, kLongest = 10.0;

private:
    int block_;
    Vec2 centre_;
    double last_;                          // rad, the pointer's bearing from the centre
    double swept_ = 0;                     // rad
    double lastAt_ = 0;                    // s, the last move
    double sweepFrom_ = -1, sweepTo_ = 0;  // s, the moves that swept
};

}  // namespace jl::ui
