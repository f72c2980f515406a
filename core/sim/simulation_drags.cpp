// The user's drags: the mouse spring on a free block, or the hand of a
// held block following the mouse; recorded into the scene so that a replay
// reproduces them.
#include "jl/sim/simulation.h"

#include <algorithm>

namespace jl {

namespace {

constexpr double kDragTimeConstant = 0.05;   // s, the mouse spring's response
constexpr double kDragMaxAcceleration = 20;  // in g: the spring's force cap per kg

Vec2 vec(const Point2& p) { return {p[0], p[1]}; }

}  // namespace

// The user's drag: the mouse spring on a free block; a held block's hand
// follows the mouse instead (docs/model.md sections 10 and 11.3).
void Simulation::applyDragSample(const DragRecord& d, const DragRecord::Sample& s) {
    if (d.block < 0 || d.block >= blockCount()) return;
    wakeThrough(d.block);
    const PartId part = blockPart(d.block);
    if (Drive* drive = world_.editDrive(part)) {
        const Pose final = drive->at(kOpenEnd).pose;
        drive->add({t_, 4 * kDragTimeConstant, vec(s.target) - final.apply(vec(d.point)), 0.0});
        return;
    }
    const double m = world_.part(part).mass;
    const double omega = 1.0 / kDragTimeConstant;
    UserDrag g{part,          vec(d.point),
               vec(s.target), m * omega * omega,
               2 * m * omega, kDragMaxAcceleration * m * std::max(world_.gravity.norm(), 9.81)};
    for (UserDrag& live : world_.editDrags())
        if (live.part == part && live.local == g.local) {
            live = g;
            return;
        }
    world_.editDrags().push_back(g);
}

void Simulation::beginDrag(int block, const Vec2& local, const Vec2& target) {
    if (block < 0 || block >= blockCount()) return;
    endDrag();
    DragRecord d;
    d.block = block;
    d.point = {local.x(), local.y()};
    d.samples.push_back({t_, {target.x(), target.y()}});
    d.end = kOpenEnd;
    scene_.drags.push_back(d);
    nextDragSample_.push_back(1);
    liveDrag_ = int(scene_.drags.size()) - 1;
    applyDragSample(d, d.samples.back());
}

void Simulation::moveDrag(const Vec2& target) {
    if (liveDrag_ < 0) return;
    DragRecord& d = scene_.drags[size_t(liveDrag_)];
    // Several moves between two steps: the last one wins, as in a replay.
    if (d.samples.back().t == t_)
        d.samples.back().target = {target.x(), target.y()};
    else
        d.samples.push_back({t_, {target.x(), target.y()}});
    nextDragSample_[size_t(liveDrag_)] = d.samples.size();
    applyDragSample(d, d.samples.back());
}

// The world's spring of a recorded drag, gone once the drag has ended.
void Simulation::removeMouseSpring(const DragRecord& d) {
    if (d.block < 0 || d.block >= blockCount()) return;
    const PartId part = blockPart(d.block);
    auto& drags = world_.editDrags();
    drags.erase(std::remove_if(drags.begin(), drags.end(),
                               [&](const UserDrag& g) { return g.part == part && g.local == vec(d.point); }),
                drags.end());
}

void Simulation::endDrag() {
    if (liveDrag_ < 0) return;
    DragRecord& d = scene_.drags[size_t(liveDrag_)];
    d.end = t_;
    // A drag of a free block while no time passed (the run was paused) did
    // nothing: it is not kept, so it is neither replayed nor saved. (A drag
    // of a held block moves the hand over the next 0.2 s: that one stays.)
    if (d.end <= d.samples.front().t && !world_.isHeld(blockPart(d.block))) {
        removeMouseSpring(d);
        scene_.drags.erase(scene_.drags.begin() + liveDrag_);
        nextDragSample_.erase(nextDragSample_.begin() + liveDrag_);
        liveDrag_ = -1;
        return;
    }
    liveDrag_ = -1;
    applyDueInputs();
}

}  // namespace jl
