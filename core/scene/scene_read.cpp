// Reading a scene: each section of the file has one function here, and each
// checks its values and its references to other sections as it goes. The
// scene under construction is private until no problem has been found.
#include "scene_read.h"

#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_ranges.h"
#include "scene_read_parts.h"
#include "yaml_fields.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <climits>
#include <numbers>
#include <string>
#include <unordered_map>
#include <vector>

namespace jl {

namespace {

void readBlockSpec(const Fields& parent, BlockSpec& block) {
    Fields f(parent.problems(), parent.value("block"), keysOf({}, kBlockNumbers, {"color"}));
    f.readAll(kBlockNumbers, block);
    f.color("color", block.color);
}

// All blocks share the length (the flip-flop needs the far corners to
// meet), so an override may repeat the length but never change it.
void readOverrides(const Fields& parent, LadderSpec& ladder) {
    std::unordered_map<int, std::string> seen;  // index -> where
    forEachItem(parent.problems(), parent.value("overrides"), [&](const Located& item) {
        Fields f(parent.problems(), item, keysOf({"index", "length"}, kOverrideNumbers, {"color"}));
        if (!f.isMap()) return;
        BlockOverride o;
        o.index = -1;
        if (f.require("index")) f.integer("index", o.index, 0, ladder.blocks - 1);
        if (o.index >= 0 && !seen.emplace(o.index, item.path).second)
            f.errorAt("index", "block " + std::to_string(o.index) + " already has an override (" + seen[o.index] +
                                   "); merge them");
        std::optional<double> length;
        f.number("length", length, kBlockNumbers[0].range);  // the ladder's `length`
        if (length && *length != ladder.block.length)
            f.errorAt("length", formatNumber(*length) + " differs from the ladder's block length " +
                                    formatNumber(ladder.block.length) +
                                    "; all blocks of a ladder have the same length");
        f.readAll(kOverrideNumbers, o);
        f.color("color", o.color);
        ladder.overrides.push_back(o);
    });
}

void readRibbons(const Fields& parent, RibbonSpec& ribbons) {
    Fields f(parent.problems(), parent.value("ribbons"),
             keysOf({}, kRibbonNumbers, {"color", "central_color", "visible"}));
    f.readAll(kRibbonNumbers, ribbons);
    f.color("color", ribbons.color);
    f.color("central_color", ribbons.centralColor);
    f.flag("visible", ribbons.visible);
}

void readHinges(const Fields& parent, HingeOptions& hinges) {
    Fields f(parent.problems(), parent.value("hinges"), keysOf({}, kHingeNumbers));
    f.readAll(kHingeNumbers, hinges);
}

void readHeld(const Fields& parent, LadderSpec& ladder) {
    Problems& problems = parent.problems();
    ladder.held.clear();
    forEachItem(problems, parent.value("held"), [&](const Located& item) {
        const auto index = readInteger(problems, item, 0, ladder.blocks - 1);
        if (!index) return;
        if (std::find(ladder.held.begin(), ladder.held.end(), *index) != ladder.held.end())
            report(problems, item.mark, item.path + ": block " + std::to_string(*index) + " is listed twice");
        ladder.held.push_back(static_cast<int>(*index));
    });
}

}  // namespace

void readLadder(const Located& at, const LoadLimits& limits, Problems& problems, LadderSpec& ladder) {
    Fields f(problems, at, {"blocks", "block", "overrides", "ribbons", "hinges", "held", "initial"});
    if (!f.isMap()) return;
    // The count comes first and is checked against the limit before any
    // list of that length exists (the engine allocates per block). Without
    // a valid count, the parts that index blocks cannot be checked.
    bool countKnown = true;
    if (f.has("blocks")) {
        const auto n = readInteger(problems, f.value("blocks"), range::kFewestBlocks, LLONG_MAX);
        if (n && *n > limits.maxBlocks)
            f.errorAt("blocks",
                      std::to_string(*n) + " blocks is more than the limit of " + std::to_string(limits.maxBlocks));
        countKnown = n && *n <= limits.maxBlocks;
        if (countKnown) ladder.blocks = static_cast<int>(*n);
    }
    if (f.has("block")) readBlockSpec(f, ladder.block);
    if (f.has("ribbons")) readRibbons(f, ladder.ribbons);
    if (f.has("hinges")) readHinges(f, ladder.hinges);
    if (!countKnown) return;
    if (f.has("overrides")) readOverrides(f, ladder);
    if (f.has("held")) readHeld(f, ladder);
    if (f.has("initial")) readInitial(f.value("initial"), problems, ladder);
}

namespace {

// Appended piece by piece: GCC 12's -Wrestrict misreads "'" + std::string
// under the sanitizers' instrumentation (a known false positive).
std::string quoted(std::string_view s) {
    std::string q(1, '\'');
    q += s;
    q += '\'';
    return q;
}

void readFormat(Fields& f) {
    if (!f.require("format")) return;
    const Located at = f.value("format");
    const auto text = readText(f.problems(), at);
    if (!text || *text == kSceneFormat) return;
    if (text->starts_with("jacobs-ladder/"))
        f.errorAt("format", quoted(*text) + " is a version this program cannot read; it reads " + quoted(kSceneFormat));
    else
        fail(f.problems(), at, quoted(kSceneFormat));
}

void readDamping(const Fields& parent, Scene& scene) {
    Fields f(parent.problems(), parent.value("damping"), keysOf({}, kDampingNumbers));
    f.readAll(kDampingNumbers, scene);
}

void readSolver(const Fields& parent, SolverSpec& solver) {
    Fields f(parent.problems(), parent.value("solver"),
             keysOf({}, kSolverNumbers, {"integrator", "events", "rigid_pairs", "still_tail", "block_contact"}));
    f.choice<Integrator>("integrator", solver.integrator, kIntegrators);
    f.choice<EventPolicy>("events", solver.events, kEventPolicies);
    f.choice<RigidPairs>("rigid_pairs", solver.rigidPairs, kRigidPairs);
    f.choice<StillTail>("still_tail", solver.stillTail, kStillTails);
    f.choice<BlockContact>("block_contact", solver.blockContact, kBlockContacts);
    f.readAll(kSolverNumbers, solver);
}

void readView(const Fields& parent, ViewSpec& view) {
    Fields f(parent.problems(), parent.value("view"), keysOf({}, kViewNumbers));
    f.readAll(kViewNumbers, view);
}

void readFloor(const Fields& parent, FloorSpec& floor) {
    Fields f(parent.problems(), parent.value("floor"), keysOf({}, kFloorNumbers));
    if (!f.isMap()) return;
    f.readAll(kFloorNumbers, floor);
}

}  // namespace

std::optional<Scene> readScene(const YAML::Node& root, const LoadLimits& limits, Problems& problems) {
    const std::size_t before = problems.size();
    Fields f(problems, locate(root, ""),
             {"format", "title", "description", "ladder", "bodies", "particles", "pins", "springs", "gravity",
              "damping", "duration", "solver", "script", "drags", "floor", "view"});
    if (!f.isMap()) return std::nullopt;
    Scene scene;
    readFormat(f);
    f.text("title", scene.title, kMostTitleCharacters);
    f.text("description", scene.description, kMostDescriptionCharacters);
    if (f.has("ladder")) readLadder(f.value("ladder"), limits, problems, scene.ladder.emplace());
    const int blocks = scene.ladder ? scene.ladder->blocks : 0;
    Names names;
    if (f.has("bodies")) readBodies(f.value("bodies"), problems, scene.bodies, names);
    if (f.has("particles")) readParticles(f.value("particles"), problems, scene.particles, names);
    if (f.has("pins")) readPins(f.value("pins"), problems, blocks, names, scene.bodies, scene.pins);
    if (f.has("springs")) readSprings(f.value("springs"), problems, blocks, names, scene.springs);
    f.read(kGravityField, scene);
    if (f.has("damping")) readDamping(f, scene);
    f.read(kDurationField, scene);
    if (f.has("solver")) readSolver(f, scene.solver);
    if (f.has("script")) readScript(f.value("script"), problems, blocks, scene.script);
    if (f.has("drags")) readDrags(f.value("drags"), problems, blocks, scene.drags);
    if (f.has("floor")) readFloor(f, scene.floor.emplace());
    if (f.has("view")) readView(f, scene.view);
    if (!scene.ladder && scene.bodies.empty() && scene.particles.empty() && problems.size() == before)
        report(problems, f.mark(), "the scene has nothing to simulate: give 'ladder', 'bodies' or 'particles'");
    if (problems.size() != before) return std::nullopt;
    return scene;
}

}  // namespace jl
