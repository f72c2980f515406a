// How far the first ripple travels (docs/model.md section 15): the top block
// is turned over and the flips run down the ladder; the ripple has reached
// hinge k when hinges 1..k have each flipped, each after the one above it.
// A simulation of one design, on the calling thread, that stops as soon as
// that count is settled (jl/design/reach_settled.h) unless asked to run whole.
#pragma once

#include "jl/design/reach_settled.h"
#include "jl/ladder/hinge_event.h"
#include "jl/scene/scene.h"

#include <atomic>
#include <limits>
#include <string>
#include <vector>

namespace jl {

struct RippleReach {
    int hinges = 0;                   // N - 1
    int reached = 0;                  // hinges 1..reached flipped in order
    std::vector<double> flipTimes;    // s, first flip of hinges 1..reached
    double meanTimeBetweenFlips = 0;  // s; 0 with fewer than two flips
    // The next three count up to the instant the run stopped (`until`):
    int flipsElsewhere = 0;             // hinges below the ripple that flipped meanwhile
    int events = 0;                     // hinge events
    int quickRow = 0;                   // chatter: the most quick cycles of one hinge in a row
    double until = 0;                   // s, when the run stopped
    RippleEnd end = RippleEnd::RunEnd;  // why it stopped then
    bool whole = true;                  // false: cut at `longest`, the reach not settled (a first look)
    std::string failure;                // the engine's, if the run stopped
    bool cancelled = false;
};

// The classic question's design: n blocks 60 mm x `thickness` x 45 mm of
// density 600, block 0 held in the hanging equilibrium and turned half a
// turn counter-clockwise from t = 0.2 s over 0.3 s.
Scene turnedLadder(int blocks, double thickness);

// How long a run must last to see the first ripple: until the script has
// ended, then 0.5 s, then 0.2 s per block (a ripple takes about 0.13 s per hinge).
double rippleRunTime(const Scene& scene);

// Whether a run stops once the reach is settled, or runs its whole time
// (every column then counts the whole run).
enum class RippleStop { WhenSettled, WholeRun };

// Runs `scene` (a ladder with its script) for rippleRunTime, or `longest`
// seconds if that is shorter, or (WhenSettled) until the reach is settled,
// and measures the first ripple; `cancel` (may be null) is polled between steps.
RippleReach firstRippleReach(const Scene& scene, const std::atomic<bool>* cancel = nullptr,
                             double longest = std::numeric_limits<double>::infinity(),
                             RippleStop stop = RippleStop::WhenSettled);

// The chatter measure of docs/model.md section 8.6: a release of a hinge
// (unlock, flip, unfold, bounce) followed by a close of the same hinge (lock,
// fold) within 1 ms is a quick cycle; a slower close ends that hinge's row.
// The most quick cycles of one hinge in a row.
int longestQuickRow(const std::vector<Event>& events);

}  // namespace jl
