// A frame: everything the views, plots and recordings need at one instant.
#pragma once

#include "jl/base/geometry.h"
#include "jl/ladder/hinge_event.h"

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace jl {

struct EnergyFrame {
    double kinetic = 0, potential = 0;       // J
    double heldWork = 0, userWork = 0;       // J, done on the ladder since t = 0
    double impactLoss = 0, dampingLoss = 0;  // J, dissipated since t = 0 (>= 0)
    double total() const { return kinetic + potential; }
    // E(0) + W_held + W_user - D_impacts - D_damping: equals total() when the books balance.
    double initial = 0;
    double balance() const { return total() - (initial + heldWork + userWork - impactLoss - dampingLoss); }
};

struct SolverFrame {
    long long steps = 0, evaluations = 0, rejected = 0;
    long long spuriousEvents = 0;  // located crossings that resolved to nothing
    double lastStep = 0;           // s
    // The fixed-step integrators' step: the scene's, or chosen by the engine
    // from the fastest vibration (smallest and largest so far), halved for
    // the rest of the run after each step that blew up. The adaptive ones'
    // steps are their error control's: smallest and largest so far of those
    // it chose (not those cut short to land on a scripted instant or an event).
    bool automaticStep = false;
    bool adaptiveStep = false;
    double smallestStep = 0, largestStep = 0;  // s
    int stepHalvings = 0;
    double residual = 0;       // m, largest pin gap after the last step
    int bodies = 0, pins = 0;  // unknowns in use (locked pairs are one body)
    int stillFrom = -1;        // the first block of the still tail (docs/model.md section 3.7); -1: none
    double wallSeconds = 0;    // spent simulating so far
};

// Evenly spaced instants: origin + k every for every whole k (s).
struct FrameGrid {
    double origin = 0, every = 0;  // every = 0: no instants
    double at(double k) const { return origin + k * every; }
    // The nearest instant's k, and whether t is that instant to within rounding.
    double nearest(double t) const { return std::round((t - origin) / every); }
    bool on(double t) const { return every > 0 && std::abs(t - at(nearest(t))) <= 1e-9 * every; }
};

struct Frame {
    double time = 0;          // s
    std::vector<Pose> poses;  // every block (ladder), then every box and particle (general scene), in scene order
    std::vector<bool> held;   // per block
    std::vector<HingeFrame> hinges;  // ladder: hinges[j-1] is hinge j
    std::vector<RibbonFrame> ribbons;
    std::vector<BlockContactFrame> blockContacts;  // ladder: corners resting on faces of other blocks
    std::vector<std::pair<Vec2, Vec2>> springs;    // general scene: each spring's two ends (m), in scene order
    EnergyFrame energy;
    SolverFrame solver;
    std::vector<Event> events;  // since the previous frame
    bool dragging = false;      // the mouse spring, for drawing
    Vec2 dragFrom = Vec2::Zero(), dragTo = Vec2::Zero();
    std::string failure;  // non-empty: the run stopped; this is the last good state
};

}  // namespace jl
