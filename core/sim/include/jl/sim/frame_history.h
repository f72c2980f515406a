// The recorded run: frames for scrubbing within a memory budget, plus
// keyframes (full simulation snapshots) from which evicted frames are re-simulated.
#pragma once

#include "jl/sim/frame.h"
#include "jl/sim/simulation.h"

#include <cstddef>
#include <memory>
#include <vector>

namespace jl {

// Frame i is the state at exactly time i * interval (frame 0 is the built
// scene). Frames are evicted to stay within the budget, oldest first, and
// any evicted frame can be re-simulated from a keyframe before it. The
// budget counts each keyframe at what its snapshot takes (snapshotBytes:
// 12 MB at 10,000 blocks); when the keyframes alone outgrow it, they are
// thinned evenly (the first and the newest stay), so that a seek re-simulates
// further but memory stays what the user set. A keyframe is the
// simulation's state at the end of the step that gave its frame, so it may
// lie a little after that frame's time.
class FrameHistory {
public:
    using FramePtr = std::shared_ptr<const Frame>;
    using SnapshotPtr = std::shared_ptr<const Snapshot>;

    void reset(double interval, std::size_t budgetBytes);
    void setBudget(std::size_t bytes);

    double interval() const { return interval_; }
    // Keyframes every ~0.5 s of simulated time: seeks re-simulate at most that much.
    int keyframeEvery() const { return keyEvery_; }
    int count() const { return int(frames_.size()); }  // recorded frames, head = count() - 1
    int head() const { return count() - 1; }

    // Appends the frame after the head; `key` is kept when the index is a keyframe index.
    void append(FramePtr frame, SnapshotPtr key, int protectIndex);
    // Puts a re-simulated frame back into an evicted slot.
    void restoreFrame(int index, FramePtr frame, int protectIndex);
    // Drops everything after `index` (the future is discarded by an edit in the past).
    void truncateAfter(int index);

    FramePtr frame(int index) const;  // null when evicted
    // The last keyframe at or before `index` and its index.
    std::pair<int, SnapshotPtr> keyframeAtOrBefore(int index) const;
    bool isKeyframeIndex(int index) const { return index % keyEvery_ == 0; }
    // The last frame whose time is <= t (by index, frames are evenly spaced).
    int indexAt(double t) const;
    std::size_t bytes() const { return bytes_; }

private:
    static std::size_t frameBytes(const Frame& f);
    void evict(int protectIndex);
    bool thinKeyframes();

    double interval_ = 1.0 / 60.0;
    int keyEvery_ = 30;
    std::size_t budget_ = 256u << 20;
    std::size_t bytes_ = 0;
    int oldestKept_ = 0;  // frames before it have been evicted (except restored ones)
    std::vector<FramePtr> frames_;
    std::vector<SnapshotPtr> keys_;      // keys_[i] belongs to frame i * keyEvery_; null once thinned
    std::vector<std::size_t> keyBytes_;  // what each of keys_ takes, 0 once thinned
};

}  // namespace jl
