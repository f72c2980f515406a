// Writing a scene: keys in one fixed order (the order of docs/scene-format.md)
// so files diff well, and only values that differ from the defaults, so a
// file says what is special about its scene.
#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_io.h"

#include <yaml-cpp/emitter.h>
#include <yaml-cpp/emittermanip.h>

#include <string>
#include <variant>

namespace jl {

namespace {

// Thin layer over the emitter that writes our value types in their text form.
class Writer {
public:
    explicit Writer(YAML::Emitter& out) : out_(out) {}

    void text(std::string_view key, const std::string& value) { keyed(key) << value; }
    void number(std::string_view key, double value) { keyed(key) << formatNumber(value); }
    void integer(std::string_view key, long long value) { keyed(key) << std::to_string(value); }
    void angle(std::string_view key, double value) { keyed(key) << formatAngle(value); }
    void color(std::string_view key, const Color& value) { keyed(key) << formatColor(value); }
    void flag(std::string_view key, bool value) { keyed(key) << (value ? "true" : "false"); }
    void point(std::string_view key, const Point2& p) {
        keyed(key);
        pointValue(p);
    }
    void pointValue(const Point2& p) {
        out_ << YAML::Flow << YAML::BeginSeq << formatNumber(p[0]) << formatNumber(p[1]) << YAML::EndSeq;
    }

    // The same, skipped when the value is the default or not given.
    void number(std::string_view key, const std::optional<double>& value) {
        if (value) number(key, *value);
    }
    void colorIf(std::string_view key, const Color& value, const Color& fallback) {
        if (value != fallback) color(key, value);
    }
    void textIf(std::string_view key, const std::string& value) {
        if (!value.empty()) text(key, value);
    }
    template <class E>
    void choiceIf(std::string_view key, E value, E fallback, std::span<const Word<E>> words) {
        if (value != fallback) text(key, std::string(wordOf(words, value)));
    }

    YAML::Emitter& keyed(std::string_view key) { return out_ << YAML::Key << std::string(key) << YAML::Value; }
    void beginMap(bool flow = false) {
        if (flow) out_ << YAML::Flow;
        out_ << YAML::BeginMap;
    }
    void endMap() { out_ << YAML::EndMap; }
    void beginList(bool flow = false) {
        if (flow) out_ << YAML::Flow;
        out_ << YAML::BeginSeq;
    }
    void endList() { out_ << YAML::EndSeq; }
    YAML::Emitter& raw() { return out_; }

private:
    YAML::Emitter& out_;
};

// A number of the table, only where it differs from the default of a fresh
// section (a required one always, an optional one when given).
void writeValue(Writer& w, std::string_view key, unsigned flags, double value, double fallback) {
    if (!(flags & kRequired) && value == fallback) return;
    if (flags & kAngle)
        w.angle(key, value);
    else
        w.number(key, value);
}
void writeValue(Writer& w, std::string_view key, unsigned flags, const std::optional<double>& value,
                const std::optional<double>&) {
    if (value && (flags & kAngle))
        w.angle(key, *value);
    else
        w.number(key, value);
}
void writeValue(Writer& w, std::string_view key, unsigned flags, const Point2& value, const Point2& fallback) {
    if ((flags & kRequired) || value != fallback) w.point(key, value);
}

template <class Section>
void writeNumber(Writer& w, const NumberField<Section>& n, const Section& section) {
    static const Section d{};
    std::visit([&](auto member) { writeValue(w, n.key, n.flags, section.*member, d.*member); }, n.member);
}

template <class Section, std::size_t N>
void writeNumbers(Writer& w, const NumberField<Section> (&numbers)[N], const Section& section) {
    for (const NumberField<Section>& n : numbers) writeNumber(w, n, section);
}

void writeBlockSpec(Writer& w, const BlockSpec& block) {
    const BlockSpec d;
    if (block == d) return;
    w.keyed("block");
    w.beginMap(true);
    writeNumbers(w, kBlockNumbers, block);
    w.colorIf("color", block.color, d.color);
    w.endMap();
}

void writeOverrides(Writer& w, const std::vector<BlockOverride>& overrides) {
    if (overrides.empty()) return;
    w.keyed("overrides");
    w.beginList();
    for (const BlockOverride& o : overrides) {
        w.beginMap(true);
        w.integer("index", o.index);
        writeNumbers(w, kOverrideNumbers, o);
        if (o.color) w.color("color", *o.color);
        w.endMap();
    }
    w.endList();
}

void writeRibbonsAndHinges(Writer& w, const RibbonSpec& ribbons, const HingeOptions& hinges) {
    const RibbonSpec r;
    if (ribbons != r) {
        w.keyed("ribbons");
        w.beginMap(true);
        writeNumbers(w, kRibbonNumbers, ribbons);
        w.colorIf("color", ribbons.color, r.color);
        w.colorIf("central_color", ribbons.centralColor, r.centralColor);
        if (ribbons.visible != r.visible) w.flag("visible", ribbons.visible);
        w.endMap();
    }
    const HingeOptions h;
    if (hinges != h) {
        w.keyed("hinges");
        w.beginMap(true);
        writeNumbers(w, kHingeNumbers, hinges);
        w.endMap();
    }
}

void writePose(Writer& w, const BlockState& pose) {
    w.beginMap(true);
    w.integer("block", pose.block);
    writeNumbers(w, kMotionNumbers<BlockState>, pose);
    w.endMap();
}

void writeInitial(Writer& w, const InitialState& initial) {
    using Kind = InitialState::Kind;
    if (initial.kind == Kind::Equilibrium) return;
    w.keyed("initial");
    w.beginMap();
    w.text("kind", std::string(wordOf<Kind>(kInitialKinds, initial.kind)));
    if (!initial.poses.empty()) {
        w.keyed("poses");
        w.beginList();
        for (const BlockState& pose : initial.poses) writePose(w, pose);
        w.endList();
    }
    if (initial.kind == Kind::FoldAngles) {
        w.keyed("fold_angles");
        w.beginList(true);
        for (double phi : initial.foldAngles) w.raw() << formatAngle(phi);
        w.endList();
    }
    w.endMap();
}

void writeLadder(Writer& w, const LadderSpec& ladder) {
    const LadderSpec d;
    w.keyed("ladder");
    w.beginMap();
    w.integer("blocks", ladder.blocks);
    writeBlockSpec(w, ladder.block);
    writeOverrides(w, ladder.overrides);
    writeRibbonsAndHinges(w, ladder.ribbons, ladder.hinges);
    if (ladder.held != d.held) {
        w.keyed("held");
        w.beginList(true);
        for (int b : ladder.held) w.raw() << std::to_string(b);
        w.endList();
    }
    writeInitial(w, ladder.initial);
    w.endMap();
}

void writeBody(Writer& w, const BodySpec& body) {
    const BodySpec d;
    w.beginMap();
    w.textIf("name", body.name);
    writeNumbers(w, kBodyNumbers, body);
    writeNumbers(w, kMotionNumbers<BodySpec>, body);
    if (body.held) w.flag("held", true);
    w.colorIf("color", body.color, d.color);
    w.endMap();
}

void writeParticle(Writer& w, const ParticleSpec& particle) {
    w.beginMap(true);
    w.textIf("name", particle.name);
    writeNumbers(w, kParticleNumbers, particle);
    w.endMap();
}

void writePointRef(Writer& w, std::string_view key, const PointRef& ref) {
    w.keyed(key);
    w.beginMap(true);
    w.text("body", ref.on);
    writeNumbers(w, kPointRefNumbers, ref);
    w.endMap();
}

void writeLinks(Writer& w, const Scene& scene) {
    if (!scene.pins.empty()) {
        w.keyed("pins");
        w.beginList();
        for (const PinSpec& pin : scene.pins) {
            w.beginMap(true);
            writePointRef(w, "a", pin.a);
            writePointRef(w, "b", pin.b);
            writeNumbers(w, kPinNumbers, pin);
            w.endMap();
        }
        w.endList();
    }
    if (scene.springs.empty()) return;
    w.keyed("springs");
    w.beginList();
    for (const SpringSpec& spring : scene.springs) {
        w.beginMap(true);
        writePointRef(w, "a", spring.a);
        writePointRef(w, "b", spring.b);
        writeNumbers(w, kSpringNumbers, spring);
        w.endMap();
    }
    w.endList();
}

void writeSolver(Writer& w, const SolverSpec& solver) {
    const SolverSpec d;
    if (solver == d) return;
    w.keyed("solver");
    w.beginMap();
    w.choiceIf<Integrator>("integrator", solver.integrator, d.integrator, kIntegrators);
    w.choiceIf<EventPolicy>("events", solver.events, d.events, kEventPolicies);
    w.choiceIf<RigidPairs>("rigid_pairs", solver.rigidPairs, d.rigidPairs, kRigidPairs);
    w.choiceIf<StillTail>("still_tail", solver.stillTail, d.stillTail, kStillTails);
    w.choiceIf<BlockContact>("block_contact", solver.blockContact, d.blockContact, kBlockContacts);
    writeNumbers(w, kSolverNumbers, solver);
    w.endMap();
}

void writeAction(Writer& w, const ScriptAction& a) {
    using Kind = ScriptAction::Kind;
    static constexpr const char* words[] = {"turn", "move", "hold", "release", "push", "cut", "join"};
    w.beginMap(true);
    writeNumber(w, kActionAt, a);
    w.keyed(words[static_cast<int>(a.kind)]);
    w.beginMap(true);
    if (a.kind != Kind::Cut) w.integer("block", a.block);
    switch (a.kind) {
        case Kind::Turn:
            writeNumber(w, kTurnBy, a);
            break;
        case Kind::Move:
            writeNumber(w, kMoveBy, a);
            break;
        case Kind::Push:
            writeNumber(w, kPushImpulse, a);
            writeNumber(w, kPushPoint, a);
            break;
        case Kind::Cut:
            w.integer("hinge", a.hinge);
            break;
        case Kind::Join:
            w.integer("corner", a.corner);
            w.integer("other", a.otherBlock);
            w.integer("other_corner", a.otherCorner);
            break;
        case Kind::Hold:
        case Kind::Release:
            break;
    }
    if (a.kind == Kind::Turn || a.kind == Kind::Move) writeNumber(w, kActionDuration, a);
    w.endMap();
    w.endMap();
}

void writeDrag(Writer& w, const DragRecord& drag) {
    w.beginMap();
    w.integer("block", drag.block);
    writeNumbers(w, kDragNumbers, drag);
    w.keyed("samples");
    w.beginList();
    for (const DragRecord::Sample& s : drag.samples) {
        w.beginList(true);
        w.raw() << formatNumber(s.t) << formatNumber(s.target[0]) << formatNumber(s.target[1]);
        w.endList();
    }
    w.endList();
    w.endMap();
}

void writeTimeline(Writer& w, const Scene& scene) {
    if (!scene.script.empty()) {
        w.keyed("script");
        w.beginList();
        for (const ScriptAction& a : scene.script) writeAction(w, a);
        w.endList();
    }
    if (!scene.drags.empty()) {
        w.keyed("drags");
        w.beginList();
        for (const DragRecord& drag : scene.drags) writeDrag(w, drag);
        w.endList();
    }
}

// Written whole: the height has no default to leave out.
void writeFloor(Writer& w, const std::optional<FloorSpec>& floor) {
    if (!floor) return;
    w.keyed("floor");
    w.beginMap(true);
    writeNumbers(w, kFloorNumbers, *floor);
    w.endMap();
}

void writeView(Writer& w, const ViewSpec& view) {
    const ViewSpec d;
    if (view == d) return;
    w.keyed("view");
    w.beginMap(true);
    writeNumbers(w, kViewNumbers, view);
    w.endMap();
}

template <class T, class Write>
void writeList(Writer& w, std::string_view key, const std::vector<T>& items, Write write) {
    if (items.empty()) return;
    w.keyed(key);
    w.beginList();
    for (const T& item : items) write(w, item);
    w.endList();
}

}  // namespace

std::string sceneToYaml(const Scene& scene) {
    const Scene d;
    YAML::Emitter out;
    out.SetIndent(2);
    Writer w(out);
    w.beginMap();
    w.text("format", std::string(kSceneFormat));
    w.textIf("title", scene.title);
    w.textIf("description", scene.description);
    if (scene.ladder) writeLadder(w, *scene.ladder);
    writeList(w, "bodies", scene.bodies, writeBody);
    writeList(w, "particles", scene.particles, writeParticle);
    writeLinks(w, scene);
    writeNumber(w, kGravityField, scene);
    if (scene.linearDamping != d.linearDamping || scene.angularDamping != d.angularDamping) {
        w.keyed("damping");
        w.beginMap(true);
        writeNumbers(w, kDampingNumbers, scene);
        w.endMap();
    }
    writeNumber(w, kDurationField, scene);
    writeSolver(w, scene.solver);
    writeTimeline(w, scene);
    writeFloor(w, scene.floor);
    writeView(w, scene.view);
    w.endMap();
    if (!out.good()) return {};
    return std::string(out.c_str()) + "\n";
}

}  // namespace jl
