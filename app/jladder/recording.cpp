#include "app/jladder/recording.h"

#include "app/jladder/options.h"
#include "core/frame_csv.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <sstream>

namespace jl::cli {

namespace {

void keep(Recording& r, Frame f, bool store) {
    for (Event& e : f.events) r.events.push_back(std::move(e));
    f.events.clear();
    r.worstBalance = std::max(r.worstBalance, std::abs(f.energy.balance()));
    r.energyEnd = f.energy.total();
    if (store) r.frames.push_back(std::move(f));
}

std::string number(double x) {
    std::ostringstream s;
    s.precision(17);
    s << x;
    return s.str();
}

}  // namespace

Recording record(Simulation& sim, double until, double every, bool keepFrames) {
    Recording r;
    Frame first = sim.frame();
    r.energyStart = first.energy.total();
    keep(r, std::move(first), keepFrames);
    double nextFrame = every;
    const auto start = std::chrono::steady_clock::now();
    while (sim.time() < until && sim.failure().empty()) {
        if (!sim.stepOnce()) break;
        for (Event& e : sim.takeEvents()) r.events.push_back(std::move(e));
        r.worstResidual = std::max(r.worstResidual, sim.lastResidual());
        const bool due = every > 0 && sim.time() >= nextFrame - 1e-12;
        if (due || sim.time() >= until) keep(r, sim.frame(), keepFrames && due);
        while (every > 0 && nextFrame <= sim.time() + 1e-12) nextFrame += every;
    }
    const Frame last = sim.frame();
    r.failure = last.failure;
    r.time = sim.time();
    r.steps = last.solver.steps;
    r.evaluations = last.solver.evaluations;
    r.solver = last.solver;
    r.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

// The tables themselves are core's (core/frame_csv.h): the desktop program writes the same.
bool writePosesCsv(const Recording& r, const std::string& path, std::string& error) {
    std::ofstream out(path);
    if (out) jl::writePosesCsv(out, r.frames);
    if (!out) error = path + ": cannot write";
    return bool(out);
}

bool writeEnergyCsv(const Recording& r, const std::string& path, std::string& error) {
    std::ofstream out(path);
    if (out) jl::writeEnergyCsv(out, r.frames);
    if (!out) error = path + ": cannot write";
    return bool(out);
}

bool writeEventsJson(const Recording& r, const std::string& path, std::string& error) {
    std::ofstream out(path);
    if (!out) {
        error = path + ": cannot write";
        return false;
    }
    out << "[";
    for (size_t i = 0; i < r.events.size(); ++i) {
        const Event& e = r.events[i];
        out << (i ? ",\n " : "\n ") << "{\"t\":" << number(e.time) << ",\"hinge\":" << e.hinge << ",\"event\":\""
            << toString(e.kind) << "\",\"corner\":" << e.corner << ",\"text\":" << jsonString(e.text) << "}";
    }
    out << "\n]\n";
    return bool(out);
}

// What step the run took: the scene's, or the engine's choice (its range,
// and how often a step that blew up made it halve the rest).
std::string stepJson(const SolverFrame& f) {
    std::ostringstream s;
    if (!f.automaticStep) {
        s << "{\"chosen_by\":\"scene\"}";
        return s.str();
    }
    s << "{\"chosen_by\":\"engine\",\"smallest\":" << number(f.smallestStep) << ",\"largest\":" << number(f.largestStep)
      << ",\"halvings\":" << f.stepHalvings << "}";
    return s.str();
}

std::string summaryJson(const Recording& r, const std::string& scenePath) {
    std::ostringstream s;
    s << "{\"scene\":" << jsonString(scenePath) << ",\"time\":" << number(r.time) << ",\"steps\":" << r.steps
      << ",\"evaluations\":" << r.evaluations << ",\"step\":" << stepJson(r.solver) << ",\"events\":" << r.events.size()
      << ",\"energy_start\":" << number(r.energyStart) << ",\"energy_end\":" << number(r.energyEnd)
      << ",\"worst_energy_balance\":" << number(r.worstBalance) << ",\"max_residual\":" << number(r.worstResidual)
      << ",\"wall_seconds\":" << number(r.wallSeconds)
      << ",\"failure\":" << (r.failure.empty() ? std::string("null") : jsonString(r.failure)) << "}";
    return s.str();
}

}  // namespace jl::cli
