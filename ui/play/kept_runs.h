// The runs a push in the past replaced, kept whole: Undo brings one back as
// it was (every frame, every event, the simulation at its head) instead of
// computing it again, and Redo the pushed run the same way.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame_history.h"
#include "jl/sim/simulation.h"

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace jl::ui {

// A run on record, as the simulation thread holds it.
struct KeptRun {
    std::unique_ptr<jl::Simulation> sim;  // at the head (or some steps past it: midFrame)
    bool midFrame = false;
    jl::FrameHistory history;
    std::shared_ptr<std::vector<jl::Event>> events;
    std::vector<jl::Event> carried;  // events after the head's frame, for the next one
    std::uint64_t headHash = 0;
    std::shared_ptr<const jl::Scene> recorded;  // its scene with its drags
    std::string failure;
};

// Runs of one scene that differ only in their drags (an edit of anything
// else runs the scene again: the keeper is cleared then), found by them.
class KeptRuns {
public:
    // Keeps `run` in place of one with the same drags. The oldest go while
    // the runs kept hold more than `budget` bytes of history (the newest
    // always stays: a run alone stays within the budget of its history).
    void keep(KeptRun run, std::size_t budget);
    // The run whose drags are `drags`, taken out; none: no run of them is kept.
    std::optional<KeptRun> take(const std::vector<jl::DragRecord>& drags);
    void trim(std::size_t budget);
    void clear() { runs_.clear(); }
    int count() const { return int(runs_.size()); }
    std::size_t bytes() const;

private:
    std::vector<KeptRun> runs_;  // the oldest first
};

}  // namespace jl::ui
