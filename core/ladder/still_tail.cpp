// The still tail of a long ladder (docs/model.md section 3.7): the blocks
// that the motion has not reached hang still, joined by the paper's combine
// into a few rigid segments, and are separated again, a few dozen at a
// time, just before the motion reaches them.
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <cmath>

namespace jl {

// Segments of kWakeBlocks, kWakeBlocks, 2 kWakeBlocks, 4 kWakeBlocks, ...
// blocks from the top of the tail down, hinged to each other: a wake
// parts only the segment on top (halving it until what is left on top is
// short), so it costs what that segment holds, not the whole tail, and the
// tail is a handful of bodies however long the ladder.
bool Ladder::hangStill(World& w, int first) {
    const int n = blockCount();
    if (stillFrom_ < n || w.weldsRigidPairs() || first < 1 || n - first < kLeastStillTail) return false;
    // A second shared point per hinge, at the lower block's centre, where
    // both blocks are now: with the hinge's own, two points make the pair one
    // rigid body at its current pose (the paper's "a hinge plus a further
    // combine"). Particles are never deleted: made once, parted once.
    std::vector<std::pair<ParticleId, ParticleId>> pairs;
    // The size doubles from the third segment on: 16, 16, 32, 64, ...
    for (int start = first, segment = 0, size = kWakeBlocks; start < n; size *= (++segment >= 2 ? 2 : 1)) {
        const int end = n - (start + size) < kWakeBlocks ? n : start + size;  // no remnant shorter than a wake
        for (int j = start + 1; j < end; ++j) {
            std::array<ParticleId, 2>& p = stillPoints_[size_t(j - 1)];
            const Vec2 centre = w.partPose(block(j)).position;
            p[0] = w.addParticle(block(j - 1), w.partPose(block(j - 1)).inverse().apply(centre));
            p[1] = w.addParticle(block(j), Vec2::Zero());
            pairs.push_back({p[0], p[1]});
        }
        start = end;
    }
    if (auto e = w.combine(pairs)) {
        error_ = "the still tail could not be joined: " + e->message;
        return false;
    }
    w.compactBodies();
    stillFrom_ = first;
    stillRest_ = hinge(first).foldAngle;
    return true;
}

// The cut hinge joins the last moving block to the tail: while the blocks
// above it hang still, it neither turns nor is turned. How far it has
// turned from where it rested, and how fast it turns (over the ladder's
// time scale), in metres at the block's length, is what the rigid tail
// could be getting wrong.
double Ladder::stillTailStrain(const World& w) const {
    if (stillFrom_ >= blockCount()) return 0;
    const double g = w.gravity.norm();
    const double timeScale = std::sqrt(length_ / (g > 0 ? g : 1.0));
    return length_ * (std::abs(foldAngle(w, stillFrom_) - stillRest_) + timeScale * std::abs(foldRate(w, stillFrom_)));
}

bool Ladder::tailReached(const World& w) const {
    return stillFrom_ < blockCount() && stillTailStrain(w) > kStillTolerance * length_;
}

int Ladder::wakeIfReached(World& w) { return tailReached(w) ? wakeThrough(w, stillFrom_) : 0; }

// Separates the still points of hinges first .. last (a batch: one regroup).
// The world's separate is all or nothing, and the points are forgotten only
// once it succeeded: a wake that fails leaves the world and the tail as they
// were (the run then stops at the step's end, Simulation::stopAt).
void Ladder::partStill(World& w, int first, int last) {
    std::vector<ParticleId> parting;
    for (int j = first; j <= last; ++j)
        if (stillPoints_[size_t(j - 1)][0] >= 0) parting.push_back(stillPoints_[size_t(j - 1)][0]);
    if (auto e = w.separate(parting)) {
        error_ = "the still tail could not be parted: " + e->message;
        return;
    }
    for (int j = first; j <= last; ++j) stillPoints_[size_t(j - 1)] = {-1, -1};
}

int Ladder::wakeThrough(World& w, int block) {
    const int n = blockCount();
    if (stillFrom_ >= n) return 0;
    const int before = stillFrom_;
    // Whatever touches block `block` reaches a few dozen blocks further at
    // once (a push, a grab): those move too, even when the block itself
    // already moves a few places above the tail. A tail too short to pay
    // for itself goes whole.
    int target = std::min(n, block + kWakeBlocks);
    if (n - target < kLeastStillTail) target = n;
    while (stillFrom_ < target && error_.empty()) {
        // The segment on top: blocks stillFrom_ .. end - 1.
        int end = stillFrom_ + 1;
        while (end < n && stillPoints_[size_t(end - 1)][0] >= 0) ++end;
        const int size = end - stillFrom_;
        if (size > 2 * kWakeBlocks) {
            partStill(w, stillFrom_ + size / 2, stillFrom_ + size / 2);  // two halves: the top one is parted next
            continue;
        }
        partStill(w, stillFrom_ + 1, end - 1);
        stillFrom_ = end;
    }
    // The bodies a wake made were appended: the state vectors' spare room
    // would be walked by every integrator's vector updates.
    w.shrinkToFit();
    if (stillFrom_ < n) stillRest_ = hinge(stillFrom_).foldAngle;
    return stillFrom_ - before;
}

}  // namespace jl
