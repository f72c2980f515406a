// How often the window takes a new status (and so draws a frame) while a
// run plays. Drawing a frame costs the processor as much as the engine
// does on a long ladder: on two cores with software OpenGL about 13 ms of
// CPU a frame (the renderer's threads 8.5 ms, the window's 5 ms), 0.8 of a
// core at 60 frames a second, beside a simulation thread that needs a whole
// core for a 1,000-block ladder at real time. While the run trails the
// clock, the window draws every other display interval, and the time the
// frames left out would have taken goes to catching up; once the run is on
// time again, it draws every interval.
#pragma once

namespace jl::ui {

// `behind`: s of simulated time the run trails the clock (SimStatus::behind);
// `interval`: s between the run's frames; `sinceDrawn` and `display`: s since
// the window last took a status, and between two of its looks.
constexpr bool drawNow(bool playing, double behind, double interval, double sinceDrawn, double display) {
    const bool trailing = playing && behind >= interval;
    return !trailing || sinceDrawn >= 1.5 * display;
}

}  // namespace jl::ui
