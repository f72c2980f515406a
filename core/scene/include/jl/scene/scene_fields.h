// The one description of each plain value of a scene file: its key, unit,
// allowed range and meaning, where it lives in the scene, and for a choice
// its words. The reader, the writer, the desktop program's forms, the
// command line and the tables of docs/scene-format.md all take them from
// here, so a range or a word is changed in one place.
#pragma once

#include "jl/scene/bound.h"
#include "jl/scene/scene.h"
#include "jl/scene/scene_ranges.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace jl {

// A number of one section of the scene (SolverSpec, BlockSpec, ...).
template <class Section>
struct NumberField {
    std::string_view key;  // as in the file
    double Section::*member;
    std::string_view unit;  // SI, as written in the file; empty: a pure number
    Bound range;
    std::string_view meaning;  // one line, for the docs and the forms' tips
};

// A word of a choice, with the enum value it stands for and a label for menus.
template <class E>
struct Word {
    std::string_view word;  // as in the file and on the command line
    E value;
    std::string_view label;
};

// ---- numbers, section by section, in the order the writer writes them ----

inline constexpr NumberField<BlockSpec> kBlockNumbers[] = {
    {"length", &BlockSpec::length, "m", range::size, "along the ladder; shared by all blocks"},
    {"thickness", &BlockSpec::thickness, "m", range::size, "in the plane, across the ladder"},
    {"width", &BlockSpec::width, "m", range::size, "out of the plane (mass, drawing)"},
    {"density", &BlockSpec::density, "kg/m³", range::density, "used when `mass` is not given"},
};
// block.mass is optional (left out, it follows from the density).
inline constexpr std::string_view kBlockMassUnit = "kg";

inline constexpr NumberField<RibbonSpec> kRibbonNumbers[] = {
    {"width", &RibbonSpec::width, "m", range::ribbonSize, "each of the outer pair (ribbons are drawn only)"},
    {"central_width", &RibbonSpec::centralWidth, "m", range::ribbonSize, "the middle ribbon"},
    {"thickness", &RibbonSpec::thickness, "m", range::ribbonSize, ""},
    {"inset", &RibbonSpec::inset, "m", range::inset, "from the block's side edge to an outer ribbon"},
};

inline constexpr NumberField<HingeOptions> kHingeNumbers[] = {
    {"damping", &HingeOptions::damping, "N m s", range::angularDamping, "viscous torque while FREE"},
    {"restitution", &HingeOptions::restitution, "", range::restitution, "bounce at LOCK/FOLD"},
    {"min_rebound_speed", &HingeOptions::minReboundSpeed, "rad/s", range::reboundSpeed, "below it an impact locks"},
};

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
     "constraint residual after projection"},
    {"event_tolerance", &SolverSpec::eventTolerance, "s", range::eventTolerance, "time accuracy of located events"},
    {"frame_interval", &SolverSpec::frameInterval, "s", range::frameInterval, "output frames (1/60 s)"},
};

inline constexpr NumberField<FloorSpec> kFloorNumbers[] = {
    {"height", &FloorSpec::height, "m", range::coordinate,
     "the table top's height; every block corner starts on or above it"},
};

inline constexpr NumberField<ViewSpec> kViewNumbers[] = {
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
inline constexpr std::string_view kDocumentedSections[] = {"ladder.block", "ladder.ribbons", "ladder.hinges", "damping",
                                                           "solver",       "floor",          "view"};
std::string fieldTable(std::string_view section);
// `page` with every generated table replaced by the current one.
std::string withCurrentFieldTables(const std::string& page);

}  // namespace jl
