// The folding chain: the falling chain of docs/model.md section 16.1 with
// stops on its hinges, the hybrid problem on which this engine and its peers
// are compared (impacts at joint limits, not a smooth motion).
//
// N boxes 60 x 12 x 45 mm of density 600 kg/m^3, pinned end to end at the
// middles of their ends, lying straight along +x at rest; the free end of
// block 0 pinned to the world at the origin (that pin has no stop). Gravity
// 9.81 m/s^2 along -y. Hinge i (i = 1 .. N-1) joins block i-1 and block i;
// its relative angle phi_i = theta_i - theta_{i-1} (counter-clockwise, x
// right, y up) is held in [-stopAngle(N), +stopAngle(N)] by stops. Impacts
// at the stops are plastic, nothing has friction. Run to 1 s.
//
// The range: at +-60 deg ten blocks first strike at 0.316 s and then not
// until 0.937 s, and a hundred strike nothing within 1 s (their largest
// bend by then is 14 deg). At +-20 deg ten blocks strike from 0.189 s on,
// about 150 times in the second; a hundred blocks bend less, and +-10 deg
// is the widest range they reach within 1 s (from 0.95 s on): below it
// their stops close thousands of times a second (+-5 deg: 6,274 events in
// this engine), a storm no reference could follow.
#pragma once

#include "jl/base/geometry.h"

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace jl::bench {

namespace folding {
constexpr double kLength = 0.06, kThickness = 0.012, kWidth = 0.045, kDensity = 600, kGravity = 9.81;
constexpr double kMass = kDensity * kLength * kThickness * kWidth;  // kg
// Moment of inertia about the centre, about the axis normal to the plane.
constexpr double kInertia = kMass * (kLength * kLength + kThickness * kThickness) / 12;              // kg m^2
inline double stopAngle(int n) { return (n <= 10 ? 20.0 : 10.0) * 3.14159265358979323846 / 180.0; }  // rad
constexpr double kDuration = 1.0;                                                                    // s
constexpr std::array<double, 3> kSampleTimes{0.25, 0.5, 1.0};                                        // s
}  // namespace folding

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// One run of the folding chain in one engine at one setting.
struct FoldingRun {
    std::string engine;     // "mujoco 2.2.2", "siconos 4.4", "jladder", ...
    std::string method;     // "rk4", "moreau-jean theta=0.5", "event-driven lsodar", ...
    std::string stopModel;  // how this run models a stop, in words: "soft constraint", "impulse", ...
    std::string setting;    // "dt = 1e-4 s", "tolerance 1e-8", ...
    int blocks = 0;
    double cpuSeconds = 0;  // CPU s of one thread for the whole run to kDuration
    // This engine's runs: the parts of cpuSeconds spent on events and, of
    // that, locating them (Simulation::eventSeconds, locatingSeconds); the
    // steps taken and the events recorded.
    double eventSeconds = 0, locatingSeconds = 0;
    long long steps = 0, events = 0;
    bool finished = true;  // false: it blew up, produced NaN or failed; `why` says what
    std::string why;
    // At each of folding::kSampleTimes: every block's centre (x right, y up, m)
    // and the energy dissipated so far (J): the kinetic plus gravitational
    // energy at the start minus that at the sample (energy stored in a soft
    // stop's spring counts as dissipated: the run does not hold it as motion).
    std::array<std::vector<Vec2>, folding::kSampleTimes.size()> centres;
    std::array<double, folding::kSampleTimes.size()> dissipated{kNaN, kNaN, kNaN};  // NaN: not reached
    // For each hinge i = 1 .. N-1 (index i-1): the first time |phi_i| reaches
    // stopAngle(N) (located events: the event time; a stepping method: linear
    // interpolation between the two steps that straddle it); NaN if never.
    std::vector<double> firstClosing;
};

constexpr double kNever = kNaN;

// This engine's runs (bench/folding_ours.cpp): RK4 and symplectic Euler at
// several steps, with located and end-of-step events, and the adaptive
// methods at several tolerances; and its reference, Dormand-Prince at
// `tolerance` with located events.
std::vector<FoldingRun> runFoldingOurs(int n, double minSeconds);
FoldingRun runFoldingReference(int n, double tolerance);
// One fixed-step run: `integrator` "rk4" or "symplectic_euler".
FoldingRun runFoldingSetting(int n, const std::string& integrator, bool located, double step);

}  // namespace jl::bench
