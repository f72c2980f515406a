// Simulation: the whole state of a run, copied out and put back (the
// timeline's keyframes), and a hash of it that determinism checks compare.
#include "jl/base/heap_bytes.h"
#include "snapshot.h"

#include <algorithm>
#include <bit>
#include <cstdint>

namespace jl {

Simulation::~Simulation() = default;

std::shared_ptr<const Snapshot> Simulation::snapshot() const {
    return std::make_shared<const Snapshot>(std::make_from_tuple<Snapshot>(stateOf(*this)));
}

std::size_t snapshotBytes(const Snapshot& s) {
    return sizeof(Snapshot) + s.world.heapBytes() + (s.ladder ? s.ladder->heapBytes() : 0) +
           (s.stops ? s.stops->heapBytes() : 0) + s.stepper.heapBytes() + heapBytes(s.nextDragSample);
}

// The state before the step's first change of structure, copied into the
// storage the last step used.
void Simulation::keepBeforeChange() {
    if (changeKept_) return;
    if (beforeChange_)
        Snapshot::stateOf(*beforeChange_) = stateOf(*this);
    else
        beforeChange_ = std::make_shared<Snapshot>(std::make_from_tuple<Snapshot>(stateOf(*this)));
    changeKept_ = true;
}

// Restores the state; recorded drags stay, so carrying on replays them.
void Simulation::restore(const Snapshot& s) {
    stateOf(*this) = Snapshot::stateOf(s);
    nextDragSample_.resize(scene_.drags.size(), 0);
    dynamics_.forgetStructure();  // its caches belong to the structure it last saw
    dynamics_.evaluate(world_, t_);
    liveDrag_ = -1;
    stiffenedRate_ = 0;
    retakes_ = 0;
    pending_.clear();
    gridDoneUpTo_ = std::min(gridDoneUpTo_, t_);  // grid instants after the restored time come again
    failure_.clear();
}

// A word at a time: the window hashes the head after every frame it
// records, and byte by byte that was 5 % of its simulation thread's
// instructions on a 10,000-block ladder. Each word is folded in by FNV-1a's
// step, then its high half into its low (a product alone carries a change
// of a high bit no lower).
std::uint64_t Simulation::stateHash() const {
    std::uint64_t h = 1469598103934665603ull;
    const auto mix = [&](std::uint64_t w) {
        h = (h ^ w) * 1099511628211ull;
        h ^= h >> 32;
    };
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    mix(bits(t_));
    for (PartId p : blocks_) {
        const Pose pose = world_.partPose(p);
        const Twist vel = world_.partVelocity(p);
        for (const double x :
             {pose.position.x(), pose.position.y(), pose.angle, vel.linear.x(), vel.linear.y(), vel.angular})
            mix(bits(x));
    }
    if (ladder_)
        for (int j = 1; j < ladder_->blockCount(); ++j)
            mix(std::uint64_t(std::uint32_t(ladder_->hinge(j).mode)) << 32 | std::uint32_t(ladder_->hinge(j).corner));
    return h;
}

}  // namespace jl
