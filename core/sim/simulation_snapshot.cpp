// Simulation: the whole state of a run, copied out and put back (the
// timeline's keyframes), and a hash of it that determinism checks compare.
#include "snapshot.h"

#include <algorithm>

namespace jl {

Simulation::~Simulation() = default;

std::shared_ptr<const Snapshot> Simulation::snapshot() const {
    return std::make_shared<const Snapshot>(std::make_from_tuple<Snapshot>(stateOf(*this)));
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
    pending_.clear();
    gridDoneUpTo_ = std::min(gridDoneUpTo_, t_);  // grid instants after the restored time come again
    failure_.clear();
}

std::uint64_t Simulation::stateHash() const {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&](const void* data, size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (size_t i = 0; i < n; ++i) h = (h ^ p[i]) * 1099511628211ull;
    };
    mix(&t_, sizeof t_);
    for (PartId p : blocks_) {
        const Pose pose = world_.partPose(p);
        const Twist vel = world_.partVelocity(p);
        const double x[6] = {pose.position.x(), pose.position.y(), pose.angle,
                             vel.linear.x(),    vel.linear.y(),    vel.angular};
        mix(x, sizeof x);
    }
    if (ladder_)
        for (int j = 1; j < ladder_->blockCount(); ++j) {
            const int state[2] = {int(ladder_->hinge(j).mode), ladder_->hinge(j).corner};
            mix(state, sizeof state);
        }
    return h;
}

}  // namespace jl
