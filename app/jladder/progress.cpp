#include "app/jladder/progress.h"

#include "app/jladder/interruption.h"
#include "jl/base/short_number.h"

#include <cmath>
#include <cstdio>
#include <limits>
#include <unistd.h>

namespace jl::cli {

ProgressLine::ProgressLine(bool wanted)
    : shown_(wanted && isatty(STDERR_FILENO) == 1), start_(std::chrono::steady_clock::now()), last_(start_) {}

ProgressLine::~ProgressLine() { clear(); }

std::string spokenDuration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0) return "?";
    if (seconds < 1) return "under a second";
    char text[64];
    const long long s = std::llround(seconds);
    if (s < 60)
        std::snprintf(text, sizeof text, "%lld s", s);
    else if (s < 3600)
        std::snprintf(text, sizeof text, "%lld min %02lld s", s / 60, s % 60);
    else if (s < 100 * 3600)
        std::snprintf(text, sizeof text, "%lld h %02lld min", s / 3600, s / 60 % 60);
    else
        std::snprintf(text, sizeof text, "%.0f days", seconds / 86400);
    return text;
}

bool ProgressLine::due() {
    const auto now = std::chrono::steady_clock::now();
    if (now - last_ < std::chrono::milliseconds(200)) return false;
    last_ = now;
    return true;
}

void ProgressLine::draw(const std::string& text) {
    const std::size_t blank = width_ > text.size() ? width_ - text.size() : 0;
    std::fprintf(stderr, "\r%s%*s", text.c_str(), int(blank), "");
    std::fflush(stderr);
    width_ = text.size();
}

void ProgressLine::simulated(double t, double until) {
    if (!shown_) return;
    const std::lock_guard lock(mutex_);
    if (!due()) return;
    const double wall = std::chrono::duration<double>(last_ - start_).count();
    const double rate = wall > 0 ? t / wall : 0;
    char text[160];
    std::snprintf(text, sizeof text, "t = %.4g of %.4g s simulated, %.3g s per s", t, until, rate);
    draw(text + (rate > 0 ? ", about " + spokenDuration((until - t) / rate) + " left" : std::string()));
}

void ProgressLine::cells(int done, int total) {
    if (!shown_) return;
    const std::lock_guard lock(mutex_);
    if (done < total && !due()) return;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const std::string left = done > 0 ? "about " + spokenDuration(wall / done * (total - done)) + " left" : "";
    draw(std::to_string(done) + " of " + std::to_string(total) + " cells done, " + spokenDuration(wall) + " so far" +
         (left.empty() ? "" : ", " + left));
}

void ProgressLine::stage(const std::string& what, int done, int total) {
    if (!shown_) return;
    const std::lock_guard lock(mutex_);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    // Appended piece by piece: GCC 12's -Wrestrict misreads "[" + std::string.
    std::string text(1, '[');
    text += std::to_string(done);
    text += " of ";
    text += std::to_string(total);
    text += " done, ";
    text += spokenDuration(wall);
    text += " so far] ";
    text += what;
    draw(text);
    std::fputc('\n', stderr);
    width_ = 0;
}

void ProgressLine::clear() {
    if (!shown_) return;
    const std::lock_guard lock(mutex_);
    if (width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", int(width_), "");
    std::fflush(stderr);
    width_ = 0;
}

std::string slowRunWarning(const Simulation& sim, double until, double wall) {
    const double t = sim.time();
    const double left = t > 0 ? (until - t) * wall / t : std::numeric_limits<double>::infinity();
    if (wall < 3 || !(left > 60) || !(left > 100 * (until - t))) return {};
    const StiffMode mode = sim.stiffestMode();
    std::string text = "slow: t = " + shortNumber(t) + " s after " + spokenDuration(wall) + ", so the " +
                       shortNumber(until) + " s asked for would take " +
                       (std::isfinite(left) ? "about " + spokenDuration(left) + " more" : "forever") +
                       ". The step is " + shortNumber(sim.lastStep()) + " s; the stiffest mode is " + describe(mode);
    if (sim.scene().solver.integrator != Integrator::RosenbrockW && mode.rate * sim.lastStep() > 1e-2 &&
        !mode.what.empty())
        text +=
            "; the linearly implicit rosenbrock_w (--integrator rosenbrock_w) is not held to a step under "
            "such a mode's time scale: try it";
    return text;
}

std::function<int()> watchedRun(ProgressLine& line, const Simulation& sim, double until, const char* command) {
    const auto start = std::chrono::steady_clock::now();
    return [&line, &sim, until, command, start, warned = false, calls = 0u]() mutable {
        line.simulated(sim.time(), until);
        // Asked between steps: the clock is read only every 1,000th time.
        if (!warned && ++calls % 1000 == 0) {
            const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            if (const std::string why = slowRunWarning(sim, until, wall); !why.empty()) {
                line.clear();
                std::fprintf(stderr, "%s: %s\n", command, why.c_str());
                warned = true;
            }
        }
        return interruption();
    };
}

}  // namespace jl::cli
