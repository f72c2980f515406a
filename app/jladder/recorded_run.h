// The headless run that `jladder run` and `jladder export` share: the scene
// built, its run recorded (jl/sim/recording.h) into the outputs as it goes,
// a progress line on a terminal, Ctrl-C caught between two steps.
#pragma once

#include "app/jladder/run_outputs.h"
#include "jl/scene/scene.h"

#include <optional>
#include <string>

namespace jl::cli {

struct RecordedRun {
    Recording recording;
    bool written = false;  // every output in place (RunOutputs::finish)
};

// Records `scene` (read from `path`) to `until` with frames every `every`
// into `outputs`, a progress line unless `quiet`; says on stderr, after
// `command`, what went wrong. Nothing when the scene does not build or an
// output cannot be opened.
std::optional<RecordedRun> recordRun(const Scene& scene, const std::string& path, double until, double every,
                                     RunOutputs& outputs, bool quiet, const char* command);

}  // namespace jl::cli
