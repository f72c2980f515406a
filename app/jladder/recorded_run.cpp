#include "app/jladder/recorded_run.h"

#include "app/jladder/interruption.h"
#include "app/jladder/progress.h"

#include <cmath>
#include <cstdio>

namespace jl::cli {

std::optional<RecordedRun> recordRun(const Scene& scene, const std::string& path, double until, double every,
                                     RunOutputs& outputs, bool quiet, const char* command) {
    Simulation::Built built = Simulation::build(scene);
    for (const std::string& e : built.errors) std::fprintf(stderr, "%s: %s\n", path.c_str(), e.c_str());
    if (!built.simulation) return std::nullopt;
    if (!outputs.open()) {
        std::fprintf(stderr, "%s: %s\n", command, outputs.error().c_str());
        return std::nullopt;
    }
    catchInterruptions();
    if (outputs.wantsFrames()) outputs.expectFrames(std::floor(until / every) + 1, command);
    ProgressLine progress(!quiet);
    RecordedRun run;
    run.recording = record(*built.simulation, until, FrameGrid{0, every}, &outputs,
                           watchedRun(progress, *built.simulation, until, command));
    progress.clear();
    run.written = outputs.finish(run.recording.complete(), command);
    return run;
}

}  // namespace jl::cli
