// The scene: plain data, exactly what a scene file holds (see docs/scene-format.md).
#pragma once

#include "jl/base/integrator.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace jl {

// The version this program reads and writes, the value of the `format` key.
inline constexpr std::string_view kSceneFormat = "jacobs-ladder/1";

// Colours are kept as the user wrote them would be lossy; store the value.
struct Color {
    std::uint8_t r = 200, g = 162, b = 107;  // light wood, "#c8a26b"
    bool operator==(const Color&) const = default;
};

using Point2 = std::array<double, 2>;

enum class EventPolicy { Located, EndOfStep };
// How a locked or folded pair is modelled: one body (the paper's combine,
// fewer unknowns) or two bodies held by a pin and a weld (World::Weld).
enum class RigidPairs { Merge, Weld };
// The blocks of a ladder at rest that the motion has not reached yet
// (docs/model.md section 3.7): joined into a few still bodies until it nears
// them, or each its own body from the start (the full model, to compare).
enum class StillTail { Joined, Separate };
enum class BlockContact { On, Off };

// Size and material of a block; every block of a ladder shares `length`.
struct BlockSpec {
    double length = 0.06;        // m, along the ladder
    double thickness = 0.012;    // m, in the plane, across the ladder
    double width = 0.045;        // m, out of the plane (mass and drawing only)
    double density = 600.0;      // kg/m^3, used when mass is not given
    std::optional<double> mass;  // kg, overrides density
    Color color{};
    bool operator==(const BlockSpec&) const = default;
};

// Per-block changes by index; unset fields keep the ladder's value.
struct BlockOverride {
    int index = 0;
    std::optional<double> thickness, width, density, mass;
    std::optional<Color> color;
    bool operator==(const BlockOverride&) const = default;
};

// Ribbons are drawn, never simulated.
struct RibbonSpec {
    double width = 0.008;         // m, each of the outer pair
    double centralWidth = 0.012;  // m, the middle ribbon
    double thickness = 0.0005;    // m
    double inset = 0.006;         // m, from the block's side edge to an outer ribbon
    Color color{40, 60, 140};     // the outer pair
    Color centralColor{160, 40, 60};
    bool visible = true;
    bool operator==(const RibbonSpec&) const = default;
};

struct HingeOptions {
    double damping = 0.0;           // N m s, viscous torque while FREE
    double restitution = 0.0;       // [0, 1)
    double minReboundSpeed = 1e-4;  // rad/s, below it an impact locks (v_min)
    bool operator==(const HingeOptions&) const = default;
};

// Pose and velocity of one block (centre, angle counter-clockwise).
struct BlockState {
    int block = 0;
    Point2 position{0, 0};       // m
    double angle = 0;            // rad
    Point2 velocity{0, 0};       // m/s
    double angularVelocity = 0;  // rad/s
    bool operator==(const BlockState&) const = default;
};

// How the ladder starts: the engine's hanging equilibrium (default), explicit
// block states, or one fold angle per hinge (hinge 1..N-1) with block 0 placed.
struct InitialState {
    enum class Kind { Equilibrium, Poses, FoldAngles };
    Kind kind = Kind::Equilibrium;
    std::vector<BlockState> poses;   // Kind::Poses: one per block
    std::vector<double> foldAngles;  // Kind::FoldAngles: N-1 values, rad
    bool operator==(const InitialState&) const = default;
};

struct LadderSpec {
    int blocks = 6;
    BlockSpec block{};
    std::vector<BlockOverride> overrides;
    RibbonSpec ribbons{};
    HingeOptions hinges{};
    std::vector<int> held{0};  // blocks that follow the hand
    InitialState initial{};
    bool operator==(const LadderSpec&) const = default;
};

// General scenes: rigid boxes, free particles, pins and springs.
struct BodySpec {
    std::string name;
    double length = 0.06, thickness = 0.012, width = 0.045;  // m, a box
    double density = 600.0;
    std::optional<double> mass;     // kg
    std::optional<double> inertia;  // kg m^2 about the centre, else from the box
    Point2 position{0, 0};
    double angle = 0;
    Point2 velocity{0, 0};
    double angularVelocity = 0;
    bool held = false;
    Color color{};
    bool operator==(const BodySpec&) const = default;
};

struct ParticleSpec {
    std::string name;
    double mass = 0.01;  // kg
    Point2 position{0, 0};
    Point2 velocity{0, 0};
    bool operator==(const ParticleSpec&) const = default;
};

// A point on something: a body or particle by name, "world" for the ground,
// or a ladder block as "block:3". `local` is in that thing's frame (m).
struct PointRef {
    std::string on;
    Point2 local{0, 0};
    bool operator==(const PointRef&) const = default;
};

struct PinSpec {
    PointRef a, b;
    // Stops (docs/model.md section 18): the least and greatest angle of b's
    // frame to a's, rad, counter-clockwise. Only between two bodies.
    std::optional<double> minAngle, maxAngle;
    double restitution = 0.0;  // [0, 1): a stop's bounce, as a hinge's
    bool operator==(const PinSpec&) const = default;
};

struct SpringSpec {
    PointRef a, b;
    double stiffness = 100.0;          // N/m
    std::optional<double> restLength;  // m, else the initial distance
    double damping = 0.0;              // N s/m
    bool operator==(const SpringSpec&) const = default;
};

// A timed action of the script.
struct ScriptAction {
    enum class Kind { Turn, Move, Hold, Release, Push, Cut, Join };
    Kind kind = Kind::Turn;
    double at = 0;          // s
    int block = 0;          // Turn, Move, Hold, Release, Push; Join: first block
    double angle = 0;       // Turn: rad, counter-clockwise
    Point2 offset{0, 0};    // Move: m
    double duration = 0.3;  // Turn, Move: s
    Point2 impulse{0, 0};   // Push: N s
    Point2 point{0, 0};     // Push: where, in the block's frame (m)
    int hinge = 1;          // Cut: hinge index 1..N-1
    int otherBlock = 1;     // Join: second block
    int corner = 0;         // Join: corner 0..3 on the first block
    int otherCorner = 0;    // Join: corner 0..3 on the second block
    bool operator==(const ScriptAction&) const = default;
};

// A recorded mouse drag, replayed exactly: the target is piecewise constant,
// each sample taking effect at its time (a time the simulation stepped to).
struct DragRecord {
    int block = 0;
    Point2 point{0, 0};  // grabbed point in the block's frame (m)
    struct Sample {
        double t = 0;
        Point2 target{0, 0};
        bool operator==(const Sample&) const = default;
    };
    std::vector<Sample> samples;
    double end = 0;  // s, the release
    bool operator==(const DragRecord&) const = default;
};

struct SolverSpec {
    Integrator integrator = Integrator::RK4;
    // s, fixed-step integrators' step and the adaptive one's first try; 0:
    // chosen by the engine (at most 1 ms, within the stability limit).
    double step = 0;
    double tolerance = 1e-8;             // adaptive integrator's local error tolerance
    double projectionTolerance = 1e-10;  // m, constraint residual after projection
    EventPolicy events = EventPolicy::Located;
    double eventTolerance = 1e-9;       // s, located events
    double frameInterval = 1.0 / 60.0;  // s, output frames
    RigidPairs rigidPairs = RigidPairs::Merge;
    StillTail stillTail = StillTail::Joined;
    BlockContact blockContact = BlockContact::On;  // docs/model.md section 17
    bool operator==(const SolverSpec&) const = default;
};

// A table top under the ladder (docs/model.md section 17.8): block
// corners rest on it, frictionless, and strike it as they strike a block.
struct FloorSpec {
    double height = 0;  // m, the table top's height in the ladder's plane
    bool operator==(const FloorSpec&) const = default;
};

struct ViewSpec {
    Point2 target{0, -0.15};  // m, where the camera looks (in the ladder plane)
    double distance = 0.8;    // m
    // degrees. Three-quarter by default, so the faces, the ribbons and the
    // zig-zag all show; yaw 0 looks at the ladder edge-on.
    double yaw = 35, pitch = 10;
    bool operator==(const ViewSpec&) const = default;
};

struct Scene {
    std::string title;
    std::string description;
    std::optional<LadderSpec> ladder;
    std::vector<BodySpec> bodies;
    std::vector<ParticleSpec> particles;
    std::vector<PinSpec> pins;
    std::vector<SpringSpec> springs;
    Point2 gravity{0, -9.81};     // m/s^2
    double linearDamping = 0.0;   // N s/m per block
    double angularDamping = 0.0;  // N m s per block
    double duration = 5.0;        // s, suggested run length (the timeline)
    SolverSpec solver{};
    std::vector<ScriptAction> script;
    std::vector<DragRecord> drags;
    std::optional<FloorSpec> floor;
    ViewSpec view{};
    bool operator==(const Scene&) const = default;
};

}  // namespace jl
