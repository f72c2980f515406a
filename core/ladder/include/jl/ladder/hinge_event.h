// What the ladder reports: each hinge's mode and state, the events that
// change them, and the ribbons to draw. The ladder's own vocabulary; a
// frame (jl/sim/frame.h) carries it to the views and recordings.
#pragma once

#include "jl/base/geometry.h"

#include <array>
#include <string>
#include <vector>

namespace jl {

enum class HingeMode { Free, OpenLocked, Folded, Cut };
// Touch and Part: a corner of a block meets, or leaves, a face of a block
// that is not its neighbour (docs/model.md section 17); hinge -1.
enum class EventKind { Lock, Unlock, Fold, Unfold, FlipFlop, Bounce, Cut, Join, Script, Touch, Part };

const char* toString(HingeMode m);
const char* toString(EventKind k);  // "lock", "unlock", "fold", "unfold", "flip", ...

// Something that happened, at its located time.
struct Event {
    double time = 0;  // s
    EventKind kind = EventKind::Lock;
    int hinge = -1;    // ladder hinge j (between blocks j-1 and j), or -1
    int corner = -1;   // the hinge corner after the event
    std::string text;  // in words, for the event log
};

struct HingeFrame {
    HingeMode mode = HingeMode::Free;
    int corner = 0;                // k, the same number on both blocks
    double foldAngle = 0;          // rad, phi of docs/model.md section 7
    Vec2 position = Vec2::Zero();  // m, the hinge point in the plane
};

// A corner of one block resting on a face of another that is not its
// neighbour (docs/model.md section 17), for the views: where, which way the
// face pushes the corner, and how hard.
struct BlockContactFrame {
    int block = 0, corner = 0, other = 0;  // corner `corner` of `block` on a face of `other`
    Vec2 point = Vec2::Zero();             // m, the corner
    Vec2 normal = Vec2::Zero();            // the face's outward normal: the push on the corner's block
    double push = 0;                       // N
};

// A ribbon drawn over the block faces: a polyline in the ladder's plane,
// drawn across the width at the outer pair's two places or at the middle.
struct RibbonFrame {
    // Round the upper block's end to the hinge and on down the lower block:
    // always five points, kept in place (a long ladder's frame has two
    // ribbons per hinge, and a list of its own for each cost more than the
    // rest of the frame).
    std::array<Vec2, 5> points;
    bool central = false;  // the middle ribbon; else the outer pair
    bool visible = true;
};

}  // namespace jl
