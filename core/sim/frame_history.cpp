#include "jl/sim/frame_history.h"

#include <algorithm>
#include <cmath>

namespace jl {

void FrameHistory::reset(double interval, std::size_t budgetBytes) {
    interval_ = interval > 0 ? interval : 1.0 / 60.0;
    keyEvery_ = std::max(1, int(std::lround(0.5 / interval_)));
    budget_ = budgetBytes;
    bytes_ = 0;
    oldestKept_ = 0;
    frames_.clear();
    keys_.clear();
    keyBytes_.clear();
}

void FrameHistory::setBudget(std::size_t bytes) {
    budget_ = bytes;
    evict(head());
}

std::size_t FrameHistory::frameBytes(const Frame& f) {
    std::size_t n = sizeof(Frame) + f.poses.size() * sizeof(Pose) + f.held.size() / 8 +
                    f.hinges.size() * sizeof(HingeFrame) + f.events.size() * sizeof(Event);
    n += f.ribbons.size() * sizeof(RibbonFrame);
    return n;
}

void FrameHistory::append(FramePtr frame, SnapshotPtr key, int protectIndex) {
    const int index = count();
    const std::size_t fb = frameBytes(*frame);
    bytes_ += fb;
    frames_.push_back(std::move(frame));
    if (isKeyframeIndex(index)) {
        const std::size_t kb = key ? snapshotBytes(*key) : 0;
        bytes_ += kb;
        keys_.push_back(std::move(key));
        keyBytes_.push_back(kb);
    }
    evict(protectIndex);
}

void FrameHistory::restoreFrame(int index, FramePtr frame, int protectIndex) {
    if (index < 0 || index >= count() || frames_[size_t(index)]) return;
    bytes_ += frameBytes(*frame);
    frames_[size_t(index)] = std::move(frame);
    oldestKept_ = std::min(oldestKept_, index);
    evict(protectIndex);
}

void FrameHistory::truncateAfter(int index) {
    for (int i = count() - 1; i > index; --i) {
        if (frames_[size_t(i)]) bytes_ -= frameBytes(*frames_[size_t(i)]);
        frames_.pop_back();
    }
    const size_t keep = size_t(index / keyEvery_ + 1);
    while (keys_.size() > keep) {
        bytes_ -= keyBytes_.back();
        keys_.pop_back();
        keyBytes_.pop_back();
    }
    oldestKept_ = std::min(oldestKept_, count());
}

// Oldest first, never the frame on screen, never a keyframe's own frame 0
// (the scene as built is what a restart shows at once).
void FrameHistory::evict(int protectIndex) {
    while (bytes_ > budget_ && oldestKept_ < head()) {
        const int i = oldestKept_++;
        if (i == 0 || i == protectIndex || !frames_[size_t(i)]) continue;
        bytes_ -= frameBytes(*frames_[size_t(i)]);
        frames_[size_t(i)].reset();
    }
    while (bytes_ > budget_ && thinKeyframes()) {
    }
}

// Drops the keyframe whose neighbours lie closest together, so that the
// longest stretch a seek re-simulates grows as little as it can; never the
// first (the scene as built) nor the newest. False when none can go.
bool FrameHistory::thinKeyframes() {
    std::vector<int> kept;
    for (int k = 0; k < int(keys_.size()); ++k)
        if (keys_[size_t(k)]) kept.push_back(k);
    if (kept.size() < 3) return false;
    size_t drop = 1;
    for (size_t i = 2; i + 1 < kept.size(); ++i)
        if (kept[i + 1] - kept[i - 1] < kept[drop + 1] - kept[drop - 1]) drop = i;
    const size_t k = size_t(kept[drop]);
    bytes_ -= keyBytes_[k];
    keyBytes_[k] = 0;
    keys_[k].reset();
    return true;
}

FrameHistory::FramePtr FrameHistory::frame(int index) const {
    if (index < 0 || index >= count()) return nullptr;
    return frames_[size_t(index)];
}

std::pair<int, FrameHistory::SnapshotPtr> FrameHistory::keyframeAtOrBefore(int index) const {
    int k = std::min(index / keyEvery_, int(keys_.size()) - 1);
    while (k >= 0 && !keys_[size_t(k)]) --k;
    if (k < 0) return {-1, nullptr};
    return {k * keyEvery_, keys_[size_t(k)]};
}

int FrameHistory::indexAt(double t) const {
    if (count() == 0) return -1;
    const int i = int(std::floor(t / interval_ + 1e-6));
    return std::clamp(i, 0, head());
}

}  // namespace jl
