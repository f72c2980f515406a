// Writing a scene: keys in one fixed order (the order of docs/scene-format.md)
// so files diff well, and only values that differ from the defaults, so a
// file says what is special about its scene.
#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_io.h"

#include <yaml-cpp/emitter.h>
#include <yaml-cpp/emittermanip.h>

#include <string>

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

    // The same, skipped when the value is the default.
    template <class T>
    void numberIf(std::string_view key, const T& value, const T& fallback) {
        if (value != fallback) number(key, value);
    }
    void number(std::string_view key, const std::optional<double>& value) {
        if (value) number(key, *value);
    }
    void angleIf(std::string_view key, double value, double fallback) {
        if (value != fallback) angle(key, value);
    }
    void pointIf(std::string_view key, const Point2& value, const Point2& fallback) {
        if (value != fallback) point(key, value);
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

// A section's numbers from the table, each only where it differs from the
// default of a fresh section.
template <class Section, std::size_t N>
void writeNumbers(Writer& w, const NumberField<Section> (&numbers)[N], const Section& section) {
    const Section d{};
    for (const NumberField<Section>& n : numbers) w.numberIf(n.key, section.*n.member, d.*n.member);
}

void writeBlockSpec(Writer& w, const BlockSpec& block) {
    const BlockSpec d;
    if (block == d) return;
    w.keyed("block");
    w.beginMap(true);
    writeNumbers(w, kBlockNumbers, block);
    w.number("mass", block.mass);
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
        w.number("thickness", o.thickness);
        w.number("width", o.width);
        w.number("density", o.density);
        w.number("mass", o.mass);
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

// Where a block or body is and how it moves; the same four keys everywhere.
void writeMotion(Writer& w, const Point2& position, double angle, const Point2& velocity, double angularVelocity) {
    w.pointIf("position", position, Point2{0, 0});
    w.angleIf("angle", angle, 0.0);
    w.pointIf("velocity", velocity, Point2{0, 0});
    w.numberIf("angular_velocity", angularVelocity, 0.0);
}

void writePose(Writer& w, const BlockState& pose) {
    w.beginMap(true);
    w.integer("block", pose.block);
    writeMotion(w, pose.position, pose.angle, pose.velocity, pose.angularVelocity);
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
    w.numberIf("length", body.length, d.length);
    w.numberIf("thickness", body.thickness, d.thickness);
    w.numberIf("width", body.width, d.width);
    w.numberIf("density", body.density, d.density);
    w.number("mass", body.mass);
    w.number("inertia", body.inertia);
    writeMotion(w, body.position, body.angle, body.velocity, body.angularVelocity);
    if (body.held) w.flag("held", true);
    w.colorIf("color", body.color, d.color);
    w.endMap();
}

void writeParticle(Writer& w, const ParticleSpec& particle) {
    const ParticleSpec d;
    w.beginMap(true);
    w.textIf("name", particle.name);
    w.numberIf("mass", particle.mass, d.mass);
    w.pointIf("position", particle.position, d.position);
    w.pointIf("velocity", particle.velocity, d.velocity);
    w.endMap();
}

void writePointRef(Writer& w, std::string_view key, const PointRef& ref) {
    w.keyed(key);
    w.beginMap(true);
    w.text("body", ref.on);
    w.pointIf("local", ref.local, Point2{0, 0});
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
            w.endMap();
        }
        w.endList();
    }
    if (scene.springs.empty()) return;
    const SpringSpec d;
    w.keyed("springs");
    w.beginList();
    for (const SpringSpec& spring : scene.springs) {
        w.beginMap(true);
        writePointRef(w, "a", spring.a);
        writePointRef(w, "b", spring.b);
        w.numberIf("stiffness", spring.stiffness, d.stiffness);
        w.number("rest_length", spring.restLength);
        w.numberIf("damping", spring.damping, d.damping);
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
    const ScriptAction d;
    w.beginMap(true);
    w.number("at", a.at);
    w.keyed(words[static_cast<int>(a.kind)]);
    w.beginMap(true);
    if (a.kind != Kind::Cut) w.integer("block", a.block);
    switch (a.kind) {
        case Kind::Turn:
            w.angle("by", a.angle);
            break;
        case Kind::Move:
            w.point("by", a.offset);
            break;
        case Kind::Push:
            w.point("impulse", a.impulse);
            w.pointIf("point", a.point, d.point);
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
    if (a.kind == Kind::Turn || a.kind == Kind::Move) w.numberIf("duration", a.duration, d.duration);
    w.endMap();
    w.endMap();
}

void writeDrag(Writer& w, const DragRecord& drag) {
    w.beginMap();
    w.integer("block", drag.block);
    w.pointIf("point", drag.point, Point2{0, 0});
    w.number("end", drag.end);
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
    for (const NumberField<FloorSpec>& n : kFloorNumbers) w.number(n.key, (*floor).*n.member);
    w.endMap();
}

void writeView(Writer& w, const ViewSpec& view) {
    const ViewSpec d;
    if (view == d) return;
    w.keyed("view");
    w.beginMap(true);
    w.pointIf("target", view.target, d.target);
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
    w.pointIf("gravity", scene.gravity, d.gravity);
    if (scene.linearDamping != d.linearDamping || scene.angularDamping != d.angularDamping) {
        w.keyed("damping");
        w.beginMap(true);
        writeNumbers(w, kDampingNumbers, scene);
        w.endMap();
    }
    w.numberIf("duration", scene.duration, d.duration);
    writeSolver(w, scene.solver);
    writeTimeline(w, scene);
    writeFloor(w, scene.floor);
    writeView(w, scene.view);
    w.endMap();
    if (!out.good()) return {};
    return std::string(out.c_str()) + "\n";
}

}  // namespace jl
