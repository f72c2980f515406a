// The section readers behind readScene, one per part of a scene file (internal to core).
#pragma once

#include "jl/scene/load_limits.h"
#include "jl/scene/scene.h"
#include "jl/scene/scene_fields.h"
#include "problems.h"
#include "yaml_fields.h"

#include <yaml-cpp/yaml.h>

#include <string>
#include <unordered_set>
#include <vector>

namespace jl {

// Names of bodies and particles, which pins and springs refer to.
using Names = std::unordered_set<std::string>;

// `blocks` is the ladder's block count, 0 when the scene has no ladder.
void readLadder(const Located& at, const LoadLimits& limits, Problems& problems, LadderSpec& ladder);
void readInitial(const Located& at, Problems& problems, LadderSpec& ladder);
void readBodies(const Located& at, Problems& problems, std::vector<BodySpec>& bodies, Names& names);
void readParticles(const Located& at, Problems& problems, std::vector<ParticleSpec>& particles, Names& names);
void readPins(const Located& at, Problems& problems, int blocks, const Names& names,
              const std::vector<BodySpec>& bodies, std::vector<PinSpec>& pins);
void readSprings(const Located& at, Problems& problems, int blocks, const Names& names,
                 std::vector<SpringSpec>& springs);
void readScript(const Located& at, Problems& problems, int blocks, std::vector<ScriptAction>& script);
void readDrags(const Located& at, Problems& problems, int blocks, std::vector<DragRecord>& drags);

// Each item of a list, located as "path[i]".
template <class Visit>
void forEachItem(Problems& problems, const Located& list, Visit visit) {
    if (!expectList(problems, list)) return;
    std::size_t i = 0;
    for (const YAML::Node& item : list.node) visit(locate(item, list.path + "[" + std::to_string(i++) + "]"));
}

// The keys of a section: the others it starts with, its numbers from the
// table, then the others after them (the order did-you-mean goes by).
template <class Section, std::size_t N>
std::vector<std::string_view> keysOf(std::vector<std::string_view> before, const NumberField<Section> (&numbers)[N],
                                     std::vector<std::string_view> after = {}) {
    for (const NumberField<Section>& n : numbers) before.push_back(n.key);
    before.insert(before.end(), after.begin(), after.end());
    return before;
}

// A ladder block index (0..blocks-1) under `key`; says so when there is no ladder.
void readBlockIndex(Fields& f, std::string_view key, int& out, int blocks);

}  // namespace jl
