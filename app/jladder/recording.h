// Runs a scene headless and records what the command-line tool writes:
// block poses (CSV), energies (CSV), events (JSON) and a JSON summary.
#pragma once

#include "core/frame.h"
#include "core/simulation.h"

#include <string>
#include <vector>

namespace jl::cli {

struct Recording {
    std::vector<Frame> frames;     // at the requested interval (first step at or after each multiple)
    std::vector<Event> events;     // every event of the run
    double energyStart = 0, energyEnd = 0, worstBalance = 0, worstResidual = 0, wallSeconds = 0;
    double time = 0;
    long long steps = 0, evaluations = 0;
    SolverFrame solver;            // the last frame's statistics (the step the engine chose among them)
    std::string failure;
};

// Runs `sim` to `until`, collecting every event and the largest pin gap
// after every step, and a frame (energy books checked) every `every`
// seconds; the frames are kept if `keepFrames`.
Recording record(Simulation& sim, double until, double every, bool keepFrames);

bool writePosesCsv(const Recording& r, const std::string& path, std::string& error);
bool writeEnergyCsv(const Recording& r, const std::string& path, std::string& error);
bool writeEventsJson(const Recording& r, const std::string& path, std::string& error);
std::string summaryJson(const Recording& r, const std::string& scenePath);

}  // namespace jl::cli
