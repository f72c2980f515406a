// How far each number of a scene file may go, and the command line's options
// that stand for the same numbers. Wide enough for any desk toy or lecture
// demonstration; narrow enough that the engine can honour every value: a
// step that moves time on, tolerances above the rounding of a double, sizes
// and masses whose products stay far from overflow and underflow, and a run
// short enough to end. docs/scene-format.md states every range.
#pragma once

#include "jl/scene/bound.h"

#include <numbers>

namespace jl::range {

// A ladder: at least two blocks (one hinge); at most what the loader
// accepts before it allocates anything per block.
inline constexpr int kFewestBlocks = 2;
inline constexpr int kMostBlocks = 100000;

// Times (s): a run's length, script times, recorded drags. 1e5 s is more
// than a day of simulated time.
inline constexpr double kLongestTime = 1e5;
inline constexpr Bound duration = Bound::leftOpen(0, kLongestTime);
inline constexpr Bound instant = Bound::closed(0, kLongestTime);
// A scripted turn or move: faster than a millisecond is a blow, not a hand.
inline constexpr Bound actionDuration = Bound::closed(1e-3, kLongestTime);

// The solver. Below 1 us a step moves time on too slowly to end a run; a
// tolerance below 1e-14 is under the rounding of the state, and the
// adaptive step would shrink forever to meet it; an event bracket cannot be
// narrowed below the rounding of the step.
inline constexpr Bound step = Bound::closed(1e-6, 0.1);
inline constexpr Bound tolerance = Bound::closed(1e-14, 0.1);
inline constexpr Bound projectionTolerance = Bound::closed(1e-15, 1e-3);
inline constexpr Bound eventTolerance = Bound::closed(1e-14, 0.1);
inline constexpr Bound frameInterval = Bound::closed(1e-6, kLongestTime);

// Sizes (m), masses (kg) and inertias (kg m^2) of blocks, bodies and particles.
inline constexpr Bound size = Bound::closed(1e-4, 100);
inline constexpr Bound ribbonSize = Bound::closed(1e-6, 1);
inline constexpr Bound inset = Bound::closed(0, 1);
inline constexpr Bound density = Bound::closed(1, 1e5);
inline constexpr Bound mass = Bound::closed(1e-6, 1e6);
inline constexpr Bound inertia = Bound::closed(1e-15, 1e9);

// Where things are and how they move: each coordinate of a point.
inline constexpr Bound coordinate = Bound::symmetric(1e4);               // m
inline constexpr Bound velocity = Bound::symmetric(1e4);                 // m/s
inline constexpr Bound angle = Bound::symmetric(1e4);                    // rad
inline constexpr Bound stopAngle = Bound::symmetric(3.141592653589793);  // rad, within half a turn either way
inline constexpr Bound foldAngle = Bound::closed(0, std::numbers::pi);   // rad, a hinge's fold
inline constexpr Bound angularVelocity = Bound::symmetric(1e4);          // rad/s
inline constexpr Bound gravity = Bound::symmetric(1e3);                  // m/s^2, about 100 g
inline constexpr Bound impulse = Bound::symmetric(1e4);                  // N s

// Springs, dampers and impacts.
inline constexpr Bound stiffness = Bound::closed(0, 1e7);       // N/m
inline constexpr Bound restLength = Bound::closed(0, 1e4);      // m
inline constexpr Bound springDamping = Bound::closed(0, 1e4);   // N s/m
inline constexpr Bound linearDamping = Bound::closed(0, 1e3);   // N s/m
inline constexpr Bound angularDamping = Bound::closed(0, 1e3);  // N m s, air and hinges
inline constexpr Bound restitution = Bound::halfOpen(0, 1);
inline constexpr Bound reboundSpeed = Bound::closed(0, 1e3);  // rad/s

// The camera.
inline constexpr Bound viewDistance = Bound::closed(1e-3, 1e4);  // m
inline constexpr Bound yaw = Bound::closed(-360, 360);           // degrees
inline constexpr Bound pitch = Bound::closed(-90, 90);           // degrees

}  // namespace jl::range
