// The one description of each plain value of a scene file: its key, unit,
// allowed range and meaning, where it lives in the scene, and for a choice
// its words. The reader, the writer, the desktop program's forms, the
// command line and the tables of docs/scene-format.md all take them from
// here, so a range or a word is changed in one place.
#pragma once

#include "jl/scene/bound.h"
#include "jl/scene/scene.h"
#include "jl/scene/scene_ranges.h"

#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>

namespace jl {

// A number of one section of the scene (SolverSpec, BlockSpec, ...): a
// plain number, one that may be left out, or a point [x, y].
enum FieldFlag : unsigned {
    kAngle = 1,     // radians, or a number with `deg` or `rad`
    kRequired = 2,  // the section must give it; always written
};
template <class Section>
struct NumberField {
    using Member = std::variant<double Section::*, std::optional<double> Section::*, Point2 Section::*>;
    std::string_view key;  // as in the file
    Member member;
    std::string_view unit;     // SI, as written in the file; empty: a pure number
    Bound range;               // of a point: of each coordinate
    std::string_view meaning;  // one line, for the docs and the forms' tips
    unsigned flags = 0;        // FieldFlag
    bool is(FieldFlag f) const { return (flags & f) != 0; }
};

// The value a field names in a section, as what it is (double,
// std::optional<double> or Point2), handed to `visit`.
template <class Section, class S, class Visit>
decltype(auto) visitValue(const NumberField<Section>& n, S& section, Visit&& visit) {
    return std::visit([&](auto member) -> decltype(auto) { return visit(section.*member); }, n.member);
}

// The row of `key` in a section's table; a key that is not there is a
// mistake of the program's own.
template <class Section, std::size_t N>
const NumberField<Section>& rowOf(const NumberField<Section> (&numbers)[N], std::string_view key) {
    for (const NumberField<Section>& n : numbers)
        if (n.key == key) return n;
    std::abort();
}

// A word of a choice, with the enum value it stands for and a label for menus.
template <class E>
struct Word {
    std::string_view word;  // as in the file and on the command line
    E value;
    std::string_view label;
};

// ---- numbers, section by section, in the order the writer writes them ----
// Whole numbers (a ladder's block count, a block or hinge index, a corner)
// are not here: their range is the ladder's own size, known only as the
// file is read, and each is read where that is known.

// The top level's numbers; `damping` (a section, below) is written between them.
inline constexpr NumberField<Scene> kGravityField = {"gravity", &Scene::gravity, "m/s²", range::gravity,
                                                     "the same on everything"};
inline constexpr NumberField<Scene> kDurationField = {
    "duration", &Scene::duration, "s", range::duration,
    "how long the scene plays before it pauses; the timeline spans it, and it is `jladder export`'s default end"};
inline constexpr NumberField<Scene> kSceneNumbers[] = {kGravityField, kDurationField};

inline constexpr NumberField<BlockSpec> kBlockNumbers[] = {
    {"length", &BlockSpec::length, "m", range::size,
     "along the ladder; every block shares it, so the far corners meet when folded"},
    {"thickness", &BlockSpec::thickness, "m", range::size,
     "in the plane, across the ladder; thin blocks carry the ripple further"},
    {"width", &BlockSpec::width, "m", range::size, "out of the plane; changes only the mass and the drawing"},
    {"density", &BlockSpec::density, "kg/m³", range::density, "of the wood; gives the mass unless `mass` is given"},
    {"mass", &BlockSpec::mass, "kg", range::mass, "of every block; left out, it follows from the density"},
};

// An override's `index` is a whole number (above); its `length` may only
// repeat the ladder's, so it is read and checked on its own.
inline constexpr NumberField<BlockOverride> kOverrideNumbers[] = {
    {"thickness", &BlockOverride::thickness, "m", range::size,
     "this block's, across the ladder; left out: the ladder's"},
    {"width", &BlockOverride::width, "m", range::size, "this block's, out of the plane; left out: the ladder's"},
    {"density", &BlockOverride::density, "kg/m³", range::density, "this block's; left out: the ladder's"},
    {"mass", &BlockOverride::mass, "kg", range::mass,
     "this block's, over its density; left out, it follows from the density"},
};

inline constexpr NumberField<RibbonSpec> kRibbonNumbers[] = {
    {"width", &RibbonSpec::width, "m", range::ribbonSize,
     "each of the two outer ribbons across the block faces (ribbons are drawn only)"},
    {"central_width", &RibbonSpec::centralWidth, "m", range::ribbonSize,
     "the middle ribbon, on the faces that do not carry the outer pair"},
    {"thickness", &RibbonSpec::thickness, "m", range::ribbonSize, "how far the ribbons stand off the faces"},
    {"inset", &RibbonSpec::inset, "m", range::inset, "from the block's side edge to an outer ribbon"},
};

inline constexpr NumberField<HingeOptions> kHingeNumbers[] = {
    {"damping", &HingeOptions::damping, "N m s", range::angularDamping,
     "viscous torque in a FREE hinge; above about 1e-5 it stops long ripples"},
    {"restitution", &HingeOptions::restitution, "", range::restitution,
     "bounce at LOCK/FOLD, from 0 (plastic) to just under 1"},
    {"min_rebound_speed", &HingeOptions::minReboundSpeed, "rad/s", range::reboundSpeed, "below it an impact locks"},
};

// Where a ladder block (a pose, after its `block`) or a body is, and how it
// moves: the same four numbers.
template <class Section>
inline constexpr NumberField<Section> kMotionNumbers[] = {
    {"position", &Section::position, "m", range::coordinate, "the centre"},
    {"angle", &Section::angle, "rad", range::angle, "counter-clockwise", kAngle},
    {"velocity", &Section::velocity, "m/s", range::velocity, "of the centre"},
    {"angular_velocity", &Section::angularVelocity, "rad/s", range::angularVelocity, "counter-clockwise"},
};

// A body's size and mass, before its motion (kMotionNumbers<BodySpec>).
inline constexpr NumberField<BodySpec> kBodyNumbers[] = {
    {"length", &BodySpec::length, "m", range::size, "along the body's local y axis"},
    {"thickness", &BodySpec::thickness, "m", range::size, "along its local x axis"},
    {"width", &BodySpec::width, "m", range::size, "out of the plane"},
    {"density", &BodySpec::density, "kg/m³", range::density, "used when `mass` is not given"},
    {"mass", &BodySpec::mass, "kg", range::mass, "left out: from the density"},
    {"inertia", &BodySpec::inertia, "kg m²", range::inertia, "about the centre; left out: from the box"},
};

inline constexpr NumberField<ParticleSpec> kParticleNumbers[] = {
    {"mass", &ParticleSpec::mass, "kg", range::mass, ""},
    {"position", &ParticleSpec::position, "m", range::coordinate, ""},
    {"velocity", &ParticleSpec::velocity, "m/s", range::velocity, ""},
};

// A point on something (after its `body`, a name).
inline constexpr NumberField<PointRef> kPointRefNumbers[] = {
    {"local", &PointRef::local, "m", range::coordinate, "in that thing's frame"},
};

// A pin's stops: the angle of b's frame to a's is held between them.
inline constexpr NumberField<PinSpec> kPinNumbers[] = {
    {"min_angle", &PinSpec::minAngle, "rad", range::stopAngle,
     "stop: the least angle of b's frame to a's (counter-clockwise); left out: none", kAngle},
    {"max_angle", &PinSpec::maxAngle, "rad", range::stopAngle,
     "stop: the greatest angle of b's frame to a's; left out: none", kAngle},
    {"restitution", &PinSpec::restitution, "", range::restitution,
     "stop: bounce at a strike, from 0 (plastic) to just under 1; needs a stop"},
};

inline constexpr NumberField<SpringSpec> kSpringNumbers[] = {
    {"stiffness", &SpringSpec::stiffness, "N/m", range::stiffness, ""},
    {"rest_length", &SpringSpec::restLength, "m", range::restLength, "left out: the initial distance"},
    {"damping", &SpringSpec::damping, "N s/m", range::springDamping, "along the spring"},
};

// A script entry's time, and the numbers of its actions (a turn's `by` is
// an angle, a move's a point: one key, two fields).
inline constexpr NumberField<ScriptAction> kActionAt = {"at",           &ScriptAction::at,        "s",
                                                        range::instant, "when the action starts", kRequired};
inline constexpr NumberField<ScriptAction> kTurnBy = {
    "by", &ScriptAction::angle, "rad", range::angle, "`turn`: the angle, counter-clockwise", kAngle | kRequired};
inline constexpr NumberField<ScriptAction> kMoveBy = {
    "by", &ScriptAction::offset, "m", range::coordinate, "`move`: how far the centre goes", kRequired};
inline constexpr NumberField<ScriptAction> kActionDuration = {
    "duration", &ScriptAction::duration, "s", range::actionDuration,
    "`turn`, `move`: how long it takes, with a smooth profile"};
inline constexpr NumberField<ScriptAction> kPushImpulse = {"impulse",      &ScriptAction::impulse, "N s",
                                                           range::impulse, "`push`: the impulse",  kRequired};
inline constexpr NumberField<ScriptAction> kPushPoint = {"point", &ScriptAction::point, "m", range::coordinate,
                                                         "`push`: where, in the block's frame"};
inline constexpr NumberField<ScriptAction> kActionNumbers[] = {kActionAt,       kTurnBy,      kMoveBy,
                                                               kActionDuration, kPushImpulse, kPushPoint};

// A recorded drag's numbers; its samples, [t, x, y] lists, are read on their own.
inline constexpr NumberField<DragRecord> kDragPoint = {"point", &DragRecord::point, "m", range::coordinate,
                                                       "the grabbed point, in the block's frame"};
inline constexpr NumberField<DragRecord> kDragEnd = {
    "end", &DragRecord::end, "s", range::instant, "the release, not before the last sample", kRequired};
inline constexpr NumberField<DragRecord> kDragNumbers[] = {kDragPoint, kDragEnd};

inline constexpr NumberField<Scene> kDampingNumbers[] = {
    {"linear", &Scene::linearDamping, "N s/m", range::linearDamping, "air drag on every block and body"},
    {"angular", &Scene::angularDamping, "N m s", range::angularDamping, "air drag on their turning"},
};

// The solver's numbers; `integrator`, `events`, `rigid_pairs`, `still_tail` and `block_contact` are choices
// (below). The writer puts the choices first, then these.
inline constexpr NumberField<SolverSpec> kSolverNumbers[] = {
    {"step", &SolverSpec::step, "s", range::step,
     "fixed step; the first try of the adaptive one. Left out, the engine chooses it: at most 1 ms, and short "
     "enough to stay stable on long ladders (docs/model.md section 6.3)"},
    {"tolerance", &SolverSpec::tolerance, "", range::tolerance,
     "local error tolerance of the adaptive `dormand_prince45`, `verner65` and `rosenbrock_w` (below 1e-14 the "
     "rounding of the state alone exceeds it)"},
    {"projection_tolerance", &SolverSpec::projectionTolerance, "m", range::projectionTolerance,
     "largest gap left in a pin after the constraint projection"},
    {"event_tolerance", &SolverSpec::eventTolerance, "s", range::eventTolerance,
     "how precisely the time of a lock, fold or flip is located"},
    {"frame_interval", &SolverSpec::frameInterval, "s", range::frameInterval,
     "simulated time between recorded frames (the timeline's resolution; 1/60 s)"},
};

inline constexpr NumberField<FloorSpec> kFloorNumbers[] = {
    {"height", &FloorSpec::height, "m", range::coordinate,
     "the table top's height; every block corner starts on or above it", kRequired},
};

inline constexpr NumberField<ViewSpec> kViewNumbers[] = {
    {"target", &ViewSpec::target, "m", range::coordinate, "where the camera looks, in the ladder plane"},
    {"distance", &ViewSpec::distance, "m", range::viewDistance, "from the camera to its target"},
    {"yaw", &ViewSpec::yaw, "°", range::yaw, "turn about the vertical; 0 looks at the ladder edge-on"},
    {"pitch", &ViewSpec::pitch, "°", range::pitch, "look down (+) or up (-)"},
};

// ---- choices ----

inline constexpr Word<Integrator> kIntegrators[] = {
    {"explicit_euler", Integrator::ExplicitEuler, "Explicit Euler (the paper's)"},
    {"symplectic_euler", Integrator::SymplecticEuler, "Symplectic Euler"},
    {"rk4", Integrator::RK4, "Runge-Kutta 4"},
    {"dormand_prince45", Integrator::DormandPrince45, "Dormand-Prince 5(4), adaptive"},
    {"verner65", Integrator::Verner65, "Verner 6(5), adaptive"},
    {"rosenbrock_w", Integrator::RosenbrockW, "Rosenbrock-W 3(2), linearly implicit, adaptive"},
};
inline constexpr Word<EventPolicy> kEventPolicies[] = {
    {"located", EventPolicy::Located, "Located inside the step"},
    {"end_of_step", EventPolicy::EndOfStep, "At the end of the step (the paper's)"},
};
inline constexpr Word<RigidPairs> kRigidPairs[] = {
    {"merge", RigidPairs::Merge, "One body (merged)"},
    {"weld", RigidPairs::Weld, "Two bodies and a weld"},
};
inline constexpr Word<StillTail> kStillTails[] = {
    {"joined", StillTail::Joined, "Still blocks joined until the motion nears them"},
    {"separate", StillTail::Separate, "Every block its own body from the start"},
};
inline constexpr Word<BlockContact> kBlockContacts[] = {
    {"on", BlockContact::On, "Blocks that are not neighbours push each other apart"},
    {"off", BlockContact::Off, "Blocks pass through one another (the paper's)"},
};
inline constexpr Word<InitialState::Kind> kInitialKinds[] = {
    {"equilibrium", InitialState::Kind::Equilibrium, "Hanging at rest"},
    {"poses", InitialState::Kind::Poses, "Given poses"},
    {"fold_angles", InitialState::Kind::FoldAngles, "Given fold angles"},
};

// The word of a value, and the value of a word (nullopt: not one of them).
template <class E>
std::string_view wordOf(std::span<const Word<E>> words, E value) {
    for (const Word<E>& w : words)
        if (w.value == value) return w.word;
    return "?";
}
template <class E>
std::optional<E> valueOf(std::span<const Word<E>> words, std::string_view word) {
    for (const Word<E>& w : words)
        if (w.word == word) return w.value;
    return std::nullopt;
}
// "explicit_euler, symplectic_euler, rk4, dormand_prince45"
template <class E>
std::string wordList(std::span<const Word<E>> words, std::string_view separator = ", ") {
    std::string out;
    for (const Word<E>& w : words) {
        if (!out.empty()) out += separator;
        out += w.word;
    }
    return out;
}

inline std::string_view integratorWord(Integrator i) { return wordOf<Integrator>(kIntegrators, i); }

// The sections whose tables docs/scene-format.md takes from here, and the
// Markdown table of one (key, type, unit, default, allowed, meaning). The
// page holds each between `<!-- fields: SECTION -->` and
// `<!-- end fields -->`; a test checks that it is current.
inline constexpr std::string_view kDocumentedSections[] = {
    "top",    "ladder.block", "ladder.overrides", "ladder.ribbons", "ladder.hinges", "pose",   "bodies", "particles",
    "points", "pins",         "springs",          "damping",        "solver",        "script", "drags",  "floor",
    "view"};
std::string fieldTable(std::string_view section);
// `page` with every generated table replaced by the current one.
std::string withCurrentFieldTables(const std::string& page);

}  // namespace jl
