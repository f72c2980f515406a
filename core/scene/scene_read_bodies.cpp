// Reading the parts of a scene that are bodies and the links between them:
// the ladder's initial state, free bodies, particles, pins and springs.
#include "jl/scene/scene_ranges.h"
#include "scene_read_parts.h"
#include "shown_text.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <charconv>
#include <numbers>

namespace jl {

namespace {

BlockState readPose(const Located& item, Problems& problems, int blocks) {
    Fields f(problems, item, keysOf({"block"}, kMotionNumbers<BlockState>));
    BlockState pose;
    pose.block = -1;
    if (f.require("block")) readBlockIndex(f, "block", pose.block, blocks);
    f.readAll(kMotionNumbers<BlockState>, pose);
    return pose;
}

// Poses: one per block, each block once.
void checkPoses(const Fields& f, const std::vector<Located>& items, const LadderSpec& ladder) {
    std::vector<bool> seen(static_cast<std::size_t>(ladder.blocks), false);
    const auto& poses = ladder.initial.poses;
    for (std::size_t i = 0; i < poses.size(); ++i) {
        const int b = poses[i].block;
        if (b < 0) continue;
        if (seen[static_cast<std::size_t>(b)])
            report(f.problems(), items[i].mark, items[i].path + ": block " + std::to_string(b) + " has a pose already");
        seen[static_cast<std::size_t>(b)] = true;
    }
    if (poses.size() != static_cast<std::size_t>(ladder.blocks))
        f.errorAt("poses", "gives " + std::to_string(poses.size()) + " poses; the ladder has " +
                               std::to_string(ladder.blocks) + " blocks, give one per block");
}

void checkFoldAngles(const Fields& f, const LadderSpec& ladder) {
    const auto& initial = ladder.initial;
    const std::size_t given = f.value("fold_angles").node.size();
    if (given + 1 != static_cast<std::size_t>(ladder.blocks))
        f.errorAt("fold_angles", "gives " + std::to_string(given) + " angles; a ladder of " +
                                     std::to_string(ladder.blocks) + " blocks has " +
                                     std::to_string(ladder.blocks - 1) + " hinges, give one per hinge");
    if (initial.poses.size() > 1 || (initial.poses.size() == 1 && initial.poses[0].block != 0))
        f.errorAt("poses", "with fold angles, only block 0's pose may be given (it places the ladder)");
}

}  // namespace

void readInitial(const Located& at, Problems& problems, LadderSpec& ladder) {
    using Kind = InitialState::Kind;
    Fields f(problems, at, {"kind", "poses", "fold_angles"});
    if (!f.isMap()) return;
    InitialState& initial = ladder.initial;
    // The kind may be left out when the lists say it.
    initial.kind = f.has("fold_angles") ? Kind::FoldAngles : f.has("poses") ? Kind::Poses : Kind::Equilibrium;
    f.choice<Kind>("kind", initial.kind, kInitialKinds);
    std::vector<Located> poseItems;
    if (f.has("poses"))
        forEachItem(problems, f.value("poses"), [&](const Located& item) {
            poseItems.push_back(item);
            initial.poses.push_back(readPose(item, problems, ladder.blocks));
        });
    if (f.has("fold_angles"))
        forEachItem(problems, f.value("fold_angles"), [&](const Located& item) {
            if (const auto phi = readAngle(problems, item, range::foldAngle)) initial.foldAngles.push_back(*phi);
        });
    if (initial.kind == Kind::Poses) checkPoses(f, poseItems, ladder);
    if (initial.kind == Kind::FoldAngles) checkFoldAngles(f, ladder);
    if (initial.kind == Kind::Equilibrium && f.has("poses"))
        f.errorAt("poses", "is not used when kind is equilibrium; remove it or set kind: poses");
    if (initial.kind != Kind::FoldAngles && f.has("fold_angles"))
        f.errorAt("fold_angles", "is not used unless kind is fold_angles");
}

namespace {

// Names are how pins and springs find things, so they must be unique and
// must not look like the built-in references.
void readName(Fields& f, std::string& name, Names& names) {
    f.text("name", name, kMostNameCharacters);
    if (name.empty()) return;
    if (name == "world" || name.starts_with("block:"))
        f.errorAt("name", "'" + name + "' is reserved ('world' and 'block:N' are built-in references)");
    else if (!names.insert(name).second)
        f.errorAt("name", "'" + name + "' is already the name of another body or particle");
}

}  // namespace

void readBodies(const Located& at, Problems& problems, std::vector<BodySpec>& bodies, Names& names) {
    forEachItem(problems, at, [&](const Located& item) {
        Fields f(problems, item,
                 keysOf({"name"}, kBodyNumbers, keysOf({}, kMotionNumbers<BodySpec>, {"held", "color"})));
        if (!f.isMap()) return;
        BodySpec body;
        readName(f, body.name, names);
        f.readAll(kBodyNumbers, body);
        f.readAll(kMotionNumbers<BodySpec>, body);
        f.flag("held", body.held);
        f.color("color", body.color);
        bodies.push_back(body);
    });
}

void readParticles(const Located& at, Problems& problems, std::vector<ParticleSpec>& particles, Names& names) {
    forEachItem(problems, at, [&](const Located& item) {
        Fields f(problems, item, keysOf({"name"}, kParticleNumbers));
        if (!f.isMap()) return;
        ParticleSpec particle;
        readName(f, particle.name, names);
        f.readAll(kParticleNumbers, particle);
        particles.push_back(particle);
    });
}

namespace {

void checkReference(Fields& f, const std::string& body, int blocks, const Names& names) {
    if (body == "world") return;
    if (body.starts_with("block:")) {
        const std::string_view digits = std::string_view(body).substr(6);
        int index = -1;
        const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
        if (blocks == 0)
            f.errorAt("body", "'" + body + "' refers to a ladder block but the scene has no ladder");
        else if (error != std::errc{} || end != digits.data() + digits.size() || index < 0 || index >= blocks)
            f.errorAt("body", "'" + body + "' is not a block of the ladder (block:0 to block:" +
                                  std::to_string(blocks - 1) + ")");
        return;
    }
    if (names.count(body)) return;
    std::vector<std::string_view> known(names.begin(), names.end());
    known.push_back("world");
    std::string message = "no body or particle is named '" + shownText(body) + "'";
    if (const auto guess = closestWord(body, known)) message += "; did you mean '" + std::string(*guess) + "'?";
    f.errorAt("body", message);
}

PointRef readPointRef(Fields& parent, std::string_view key, int blocks, const Names& names) {
    PointRef ref;
    if (!parent.require(key)) return ref;
    Fields f(parent.problems(), parent.value(key), keysOf({"body"}, kPointRefNumbers));
    if (f.require("body")) {
        f.text("body", ref.on, kMostNameCharacters);
        checkReference(f, ref.on, blocks, names);
    }
    f.readAll(kPointRefNumbers, ref);
    return ref;
}

}  // namespace

namespace {

// Stops hold one body's angle to another's: a point has no angle, the
// world's stops would be a hand, and a ladder's hinges have their own limits.
// They need the pins' weld form of a locked pair (docs/model.md section
// 18), which a ladder in the same world would take too: not with a ladder.
void checkStops(Fields& f, const PinSpec& pin, int blocks, const std::vector<BodySpec>& bodies) {
    if (!pin.minAngle && !pin.maxAngle) {
        if (pin.restitution != 0) f.errorAt("restitution", "a bounce needs a stop: give min_angle or max_angle");
        return;
    }
    const std::string_view key = pin.minAngle ? "min_angle" : "max_angle";
    if (blocks > 0) {
        f.errorAt(key, "stops on pins are not available in a scene with a ladder");
        return;
    }
    const auto isBody = [&](const std::string& name) {
        return std::any_of(bodies.begin(), bodies.end(), [&](const BodySpec& b) { return b.name == name; });
    };
    for (const PointRef* r : {&pin.a, &pin.b})
        if (!r->on.empty() && !isBody(r->on)) {
            f.errorAt(key, "stops hold the angle between two bodies; '" + shownText(r->on) +
                               "' is not a body of `bodies` (the world, a particle or a ladder block)");
            return;
        }
    if (pin.minAngle && pin.maxAngle && !(*pin.minAngle < *pin.maxAngle))
        f.errorAt("max_angle", "must be greater than min_angle");
}

}  // namespace

void readPins(const Located& at, Problems& problems, int blocks, const Names& names,
              const std::vector<BodySpec>& bodies, std::vector<PinSpec>& pins) {
    forEachItem(problems, at, [&](const Located& item) {
        Fields f(problems, item, keysOf({"a", "b"}, kPinNumbers));
        if (!f.isMap()) return;
        PinSpec pin;
        pin.a = readPointRef(f, "a", blocks, names);
        pin.b = readPointRef(f, "b", blocks, names);
        if (!pin.a.on.empty() && pin.a.on == pin.b.on)
            report(problems, item.mark, item.path + ": pins '" + pin.a.on + "' to itself");
        f.readAll(kPinNumbers, pin);
        checkStops(f, pin, blocks, bodies);
        pins.push_back(pin);
    });
}

void readSprings(const Located& at, Problems& problems, int blocks, const Names& names,
                 std::vector<SpringSpec>& springs) {
    forEachItem(problems, at, [&](const Located& item) {
        Fields f(problems, item, keysOf({"a", "b"}, kSpringNumbers));
        if (!f.isMap()) return;
        SpringSpec spring;
        spring.a = readPointRef(f, "a", blocks, names);
        spring.b = readPointRef(f, "b", blocks, names);
        f.readAll(kSpringNumbers, spring);
        springs.push_back(spring);
    });
}

}  // namespace jl
