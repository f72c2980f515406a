#include "ui/play/kept_runs.h"

#include <algorithm>

namespace jl::ui {

namespace {
bool ranWith(const KeptRun& r, const std::vector<jl::DragRecord>& drags) {
    return r.recorded && r.recorded->drags == drags;
}
}  // namespace

void KeptRuns::keep(KeptRun run, std::size_t budget) {
    if (!run.sim || !run.recorded) return;
    std::erase_if(runs_, [&](const KeptRun& r) { return ranWith(r, run.recorded->drags); });
    runs_.push_back(std::move(run));
    trim(budget);
}

std::optional<KeptRun> KeptRuns::take(const std::vector<jl::DragRecord>& drags) {
    const auto it = std::find_if(runs_.begin(), runs_.end(), [&](const KeptRun& r) { return ranWith(r, drags); });
    if (it == runs_.end()) return std::nullopt;
    KeptRun found = std::move(*it);
    runs_.erase(it);
    return found;
}

void KeptRuns::trim(std::size_t budget) {
    while (runs_.size() > 1 && bytes() > budget) runs_.erase(runs_.begin());
}

std::size_t KeptRuns::bytes() const {
    std::size_t n = 0;
    for (const KeptRun& r : runs_) n += r.history.bytes();
    return n;
}

}  // namespace jl::ui
