// What the simulation thread publishes for the UI: an immutable snapshot of
// the run, swapped whole, so the UI reads it without ever waiting on a step.
#pragma once

#include "jl/scene/scene.h"
#include "jl/sim/frame.h"

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace jl::ui {

struct SimStatus {
    std::shared_ptr<const jl::Frame> frame;                // on screen (the cursor's frame)
    std::shared_ptr<const std::vector<jl::Event>> events;  // every event up to the head, in time order
    std::shared_ptr<const jl::Scene> recorded;             // the running scene with the drags recorded so far
    int frameIndex = 0;                                    // the cursor
    int frameCount = 0;                                    // recorded frames; the head is frameCount - 1
    double interval = 1.0 / 60.0;                          // s between frames
    double headTime = 0;                                   // s, simulated so far
    bool playing = false;
    // A seek (or an edit run again up to the moment on screen) still on its
    // way: the time it is simulating to, s; negative when none is.
    double seekingTo = -1;
    double seekProgress = 0;  // how far along the way there, 0 .. 1
    bool dragging = false;
    double speed = 1.0;
    // Simulated seconds, and solver steps, per wall second over the last
    // rateSpan s of playing (RateWindow); negative: none yet.
    double realTimeFactor = -1;
    double stepsPerSecond = -1;
    double rateSpan = 0;
    // While playing, s of simulated time the frame on screen trails the
    // clock by (up to kCatchUp, which the run makes good); 0 on time.
    double behind = 0;
    std::uint64_t headHash = 0;  // Simulation::stateHash() at the head
    std::string failure;         // non-empty: the run stopped and says why
    // Every frame the run made that the window has not taken yet, in time
    // order, the first numbered firstNewFrame in a count that never restarts
    // (SimController takes them with SimWorker::taken): the plots sample
    // every frame of the run, not only those on screen when the window looked.
    std::shared_ptr<const std::vector<std::shared_ptr<const jl::Frame>>> newFrames;
    std::uint64_t firstNewFrame = 0;
    std::uint64_t serial = 0;      // grows with every publication
    std::uint64_t loadSerial = 0;  // grows with every scene load
};

}  // namespace jl::ui
