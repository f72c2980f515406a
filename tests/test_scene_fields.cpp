// labels: io
// The table of scene fields drives the reader, the writer and the format
// page: every field of the table survives a save and a load with a value of
// its own, every word of every choice does, a value just outside a range is
// refused with the range's words, and docs/scene-format.md holds the
// current tables. JL_UPDATE_DOCS=1 rewrites the page's tables instead.
#include "jl/scene/ladder_blocks.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_io.h"
#include "jl/scene/yaml_comments.h"

#include <QtTest>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

using namespace jl;

namespace {

// A value of the range that no default has: three quarters of the way up
// (a geometric mean for ranges of many decades).
double insideValue(const Bound& b) {
    if (b.lo > 0 && b.hi / b.lo > 1e3) return std::sqrt(b.lo * b.hi) * 1.2345;
    const double hi = std::isfinite(b.hi) ? b.hi : b.lo + 10;
    return b.lo + 0.7513 * (hi - b.lo);
}

Scene ladderScene() {
    Scene s;
    s.ladder.emplace();
    return s;
}

Scene reloaded(const Scene& s) {
    const SceneLoad load = parseScene(sceneToYaml(s), "saved.yaml");
    if (!load.scene) {
        for (const Diagnostic& d : load.errors) qWarning("%s", d.format().c_str());
        return {};
    }
    return *load.scene;
}

// Text pieces joined (GCC 12's -Wrestrict misreads "x" + std::string).
template <class... Pieces>
std::string joined(const Pieces&... pieces) {
    std::string out;
    (out.append(pieces), ...);
    return out;
}

// A value of a field's kind from a number of its range.
void setInside(double& out, double v) { out = v; }
void setInside(std::optional<double>& out, double v) { out = v; }
void setInside(Point2& out, double v) { out = {v, v}; }

// Every number of one section: set in `make`'s scene (one that needs the
// section), saved, loaded back bit for bit.
template <class Section, std::size_t N, class At>
void eachNumberRoundTrips(const NumberField<Section> (&numbers)[N], Scene (*make)(), At at) {
    for (const NumberField<Section>& n : numbers) {
        Scene s = make();
        const double v = insideValue(n.range);
        QVERIFY2(n.range.contains(v), n.key.data());
        std::visit([&](auto member) { setInside(at(s).*member, v); }, n.member);
        const Scene back = reloaded(s);
        QVERIFY2(back == s, n.key.data());
    }
}

// A value just past a range's upper end is refused, and the message says
// the range. The file holds `before`, the key and its value (made an item
// of its own by `item`), then `after`.
template <class Section, std::size_t N>
void eachNumberIsChecked(const NumberField<Section> (&numbers)[N], const std::string& before, const std::string& after,
                         std::string (*item)(const std::string&) = nullptr) {
    for (const NumberField<Section>& n : numbers) {
        if (!std::isfinite(n.range.hi)) continue;
        const std::string past = std::to_string(n.range.hi > 0 ? n.range.hi * 2 + 1 : 1);
        const bool point = std::holds_alternative<Point2 Section::*>(n.member);
        const std::string value = point ? joined(n.key, ": [", past, ", 0]") : joined(n.key, ": ", past);
        const std::string yaml = joined("format: jacobs-ladder/1\n", before, item ? item(value) : value, after, "\n");
        const SceneLoad load = parseScene(yaml, "past.yaml");
        QVERIFY2(!load.scene, yaml.c_str());
        QVERIFY(!load.errors.empty());
        const std::string message = load.errors.front().format();
        QVERIFY2(message.find(std::string(n.key)) != std::string::npos, message.c_str());
        QVERIFY2(message.find(n.range.describe()) != std::string::npos, message.c_str());
    }
}

// Scenes that have each section, as a scene and as the text of a file.
Scene bodyScene() {
    Scene s;
    s.bodies.resize(1);
    s.bodies[0].name = "bob";
    s.particles.resize(1);
    s.particles[0].name = "pip";
    s.springs.resize(1);
    s.springs[0].a.on = "bob";
    s.springs[0].b.on = "pip";
    return s;
}
Scene pinScene() {
    Scene s;
    s.bodies.resize(2);
    s.bodies[0].name = "bob";
    s.bodies[1].name = "ann";
    s.pins.resize(1);
    s.pins[0].a.on = "bob";
    s.pins[0].b.on = "ann";
    s.pins[0].maxAngle = 3.0;  // a stop, which a restitution needs; above any min_angle tried
    return s;
}
Scene poseScene() {
    Scene s = ladderScene();
    s.ladder->blocks = 2;
    s.ladder->initial.kind = InitialState::Kind::Poses;
    s.ladder->initial.poses.resize(2);
    s.ladder->initial.poses[1].block = 1;
    return s;
}
Scene overrideScene() {
    Scene s = ladderScene();
    s.ladder->overrides.resize(1);
    s.ladder->overrides[0].index = 1;
    return s;
}
template <ScriptAction::Kind kind>
Scene actionScene() {
    Scene s = ladderScene();
    s.script.resize(1);
    s.script[0].kind = kind;
    return s;
}
Scene dragScene() {
    Scene s = ladderScene();
    s.drags.resize(1);
    s.drags[0].samples.resize(1);
    return s;
}
// A script entry that holds `item` ("by: 2", "at: 3", ...) where it belongs.
std::string entry(const std::string& item) {
    if (item.starts_with("at:")) return joined("{", item, ", hold: {block: 0}}");
    if (item.starts_with("by: [")) return joined("{at: 0, move: {block: 0, ", item, "}}");
    if (item.starts_with("by:")) return joined("{at: 0, turn: {block: 0, ", item, "}}");
    if (item.starts_with("duration:")) return joined("{at: 0, turn: {block: 0, by: 1, ", item, "}}");
    return joined("{at: 0, push: {block: 0, ", item, item.starts_with("impulse") ? "" : ", impulse: [0, 0]", "}}");
}
// A drag's `item` with the release it needs, unless it is the release.
std::string withEnd(const std::string& item) { return item.starts_with("end:") ? item : joined(item, ", end: 1"); }

// Every word of one choice: its value set (`at` the field it sets, after
// `ready` gives the scene what that value needs), saved, loaded back, and
// the word and the value found from each other.
template <class E, std::size_t N, class At>
void eachWordRoundTrips(const Word<E> (&words)[N], At at, void (*ready)(Scene&, E) = nullptr) {
    for (const Word<E>& w : words) {
        Scene s = ladderScene();
        if (ready) ready(s, w.value);
        at(s) = w.value;
        const Scene back = reloaded(s);
        QVERIFY2(back.ladder, w.word.data());
        QVERIFY2(at(const_cast<Scene&>(back)) == w.value, w.word.data());
        QVERIFY(valueOf<E>(words, w.word) == w.value);
        QCOMPARE(wordOf<E>(words, w.value), w.word);
    }
}

// What a ladder's start of each kind needs: a pose per block, an angle per hinge.
void startOfKind(Scene& s, InitialState::Kind kind) {
    if (kind == InitialState::Kind::Poses)
        for (int b = 0; b < s.ladder->blocks; ++b) s.ladder->initial.poses.push_back(BlockState{.block = b});
    if (kind == InitialState::Kind::FoldAngles) s.ladder->initial.foldAngles.assign(size_t(s.ladder->blocks - 1), 0.3);
}

}  // namespace

class TestSceneFields : public QObject {
    Q_OBJECT
private slots:
    void everyNumberOfTheTableIsReadAndWritten() {
        eachNumberRoundTrips(kSceneNumbers, &ladderScene, [](Scene& s) -> Scene& { return s; });
        eachNumberRoundTrips(kBlockNumbers, &ladderScene, [](Scene& s) -> BlockSpec& { return s.ladder->block; });
        eachNumberRoundTrips(kOverrideNumbers, &overrideScene,
                             [](Scene& s) -> BlockOverride& { return s.ladder->overrides[0]; });
        eachNumberRoundTrips(kRibbonNumbers, &ladderScene, [](Scene& s) -> RibbonSpec& { return s.ladder->ribbons; });
        eachNumberRoundTrips(kHingeNumbers, &ladderScene, [](Scene& s) -> HingeOptions& { return s.ladder->hinges; });
        eachNumberRoundTrips(kMotionNumbers<BlockState>, &poseScene,
                             [](Scene& s) -> BlockState& { return s.ladder->initial.poses[1]; });
        eachNumberRoundTrips(kBodyNumbers, &bodyScene, [](Scene& s) -> BodySpec& { return s.bodies[0]; });
        eachNumberRoundTrips(kMotionNumbers<BodySpec>, &bodyScene, [](Scene& s) -> BodySpec& { return s.bodies[0]; });
        eachNumberRoundTrips(kParticleNumbers, &bodyScene, [](Scene& s) -> ParticleSpec& { return s.particles[0]; });
        eachNumberRoundTrips(kPointRefNumbers, &bodyScene, [](Scene& s) -> PointRef& { return s.springs[0].b; });
        eachNumberRoundTrips(kPinNumbers, &pinScene, [](Scene& s) -> PinSpec& { return s.pins[0]; });
        eachNumberRoundTrips(kSpringNumbers, &bodyScene, [](Scene& s) -> SpringSpec& { return s.springs[0]; });
        eachNumberRoundTrips(kDampingNumbers, &ladderScene, [](Scene& s) -> Scene& { return s; });
        eachNumberRoundTrips(kSolverNumbers, &ladderScene, [](Scene& s) -> SolverSpec& { return s.solver; });
        const NumberField<ScriptAction> turn[] = {kActionAt, kTurnBy, kActionDuration};
        const NumberField<ScriptAction> move[] = {kMoveBy};
        const NumberField<ScriptAction> push[] = {kPushImpulse, kPushPoint};
        auto action = [](Scene& s) -> ScriptAction& { return s.script[0]; };
        eachNumberRoundTrips(turn, &actionScene<ScriptAction::Kind::Turn>, action);
        eachNumberRoundTrips(move, &actionScene<ScriptAction::Kind::Move>, action);
        eachNumberRoundTrips(push, &actionScene<ScriptAction::Kind::Push>, action);
        eachNumberRoundTrips(kDragNumbers, &dragScene, [](Scene& s) -> DragRecord& { return s.drags[0]; });
        eachNumberRoundTrips(kViewNumbers, &ladderScene, [](Scene& s) -> ViewSpec& { return s.view; });
    }

    void everyNumberIsCheckedAgainstItsRange() {
        const std::string ladder = "ladder: {blocks: 3";
        eachNumberIsChecked(kSceneNumbers, ladder + "}\n", "");
        eachNumberIsChecked(kBlockNumbers, ladder + ", block: {", "}}");
        eachNumberIsChecked(kOverrideNumbers, ladder + ", overrides: [{index: 1, ", "}]}");
        eachNumberIsChecked(kRibbonNumbers, ladder + ", ribbons: {", "}}");
        eachNumberIsChecked(kHingeNumbers, ladder + ", hinges: {", "}}");
        eachNumberIsChecked(kMotionNumbers<BlockState>, ladder + ", initial: {kind: fold_angles, poses: [{block: 0, ",
                            "}], fold_angles: [0.1, 0.1]}}");
        const std::string top = ladder + "}\n";
        eachNumberIsChecked(kBodyNumbers, top + "bodies: [{", "}]");
        eachNumberIsChecked(kMotionNumbers<BodySpec>, top + "bodies: [{", "}]");
        eachNumberIsChecked(kParticleNumbers, top + "particles: [{", "}]");
        eachNumberIsChecked(kPointRefNumbers, top + "pins: [{a: {body: world, ", "}, b: {body: 'block:0'}}]");
        eachNumberIsChecked(kPinNumbers, "bodies: [{name: bob}, {name: ann}]\npins: [{a: {body: bob}, b: {body: ann}, ",
                            "}]");
        eachNumberIsChecked(kSpringNumbers, top + "springs: [{a: {body: world}, b: {body: 'block:0'}, ", "}]");
        eachNumberIsChecked(kDampingNumbers, top + "damping: {", "}");
        eachNumberIsChecked(kSolverNumbers, top + "solver: {", "}");
        eachNumberIsChecked(kActionNumbers, top + "script: [", "]", &entry);
        eachNumberIsChecked(kDragNumbers, top + "drags: [{block: 0, samples: [[0, 0, 0]], ", "}]", &withEnd);
        eachNumberIsChecked(kFloorNumbers, top + "floor: {", "}");
        eachNumberIsChecked(kViewNumbers, top + "view: {", "}");
    }

    void everyWordOfEveryChoiceIsReadAndWritten() {
        eachWordRoundTrips(kIntegrators, [](Scene& s) -> Integrator& { return s.solver.integrator; });
        eachWordRoundTrips(kEventPolicies, [](Scene& s) -> EventPolicy& { return s.solver.events; });
        eachWordRoundTrips(kRigidPairs, [](Scene& s) -> RigidPairs& { return s.solver.rigidPairs; });
        eachWordRoundTrips(kStillTails, [](Scene& s) -> StillTail& { return s.solver.stillTail; });
        eachWordRoundTrips(kBlockContacts, [](Scene& s) -> BlockContact& { return s.solver.blockContact; });
        eachWordRoundTrips(
            kInitialKinds, [](Scene& s) -> InitialState::Kind& { return s.ladder->initial.kind; }, &startOfKind);
        QVERIFY(!valueOf<Integrator>(kIntegrators, "rk5"));
    }

    // The view's default is the program's (three-quarters), so a file that
    // asks for yaw 0, edge-on, keeps it through a save and a load.
    void anEdgeOnViewIsKeptAsWritten() {
        QVERIFY(ViewSpec{}.yaw != 0);
        const SceneLoad load =
            parseScene("format: jacobs-ladder/1\nladder: {blocks: 3}\nview: {yaw: 0}\n", "edge.yaml");
        QVERIFY(load.scene);
        QCOMPARE(load.scene->view.yaw, 0.0);
        QCOMPARE(reloaded(*load.scene).view.yaw, 0.0);
    }

    void aLadderHasTheSameBlockLimitsEverywhere() {
        const SceneLoad one = parseScene("format: jacobs-ladder/1\nladder: {blocks: 1}\n", "one.yaml");
        QVERIFY(!one.scene);
        QVERIFY2(one.errors.front().format().find(">= 2") != std::string::npos, one.errors.front().format().c_str());
        QCOMPARE(LoadLimits{}.maxBlocks, range::kMostBlocks);
        const std::string most =
            "format: jacobs-ladder/1\nladder: {blocks: " + std::to_string(range::kMostBlocks + 1) + "}\n";
        QVERIFY(!parseScene(most, "most.yaml").scene);
    }

    // The override rule, stated once (jl/scene/ladder_blocks.h): sizes and
    // colours replace the ladder's; a density without a mass lets the mass
    // follow from it; a given mass wins over any density.
    void eachBlockIsTheLadderBlockWithItsOverrides() {
        LadderSpec l;
        l.blocks = 4;
        l.block.mass = 0.05;
        BlockOverride thick, dense, heavy, missing;
        thick.index = 1, thick.thickness = 0.02, thick.color = Color{1, 2, 3};
        dense.index = 2, dense.density = 900;
        heavy.index = 3, heavy.density = 900, heavy.mass = 0.2;
        missing.index = 7, missing.width = 1;
        l.overrides = {thick, dense, heavy, missing};
        const std::vector<BlockSpec> b = ladderBlocks(l);
        QCOMPARE(b.size(), size_t(4));
        QCOMPARE(b[0], l.block);
        QCOMPARE(b[1].thickness, 0.02);
        QVERIFY(b[1].color == (Color{1, 2, 3}));
        QCOMPARE(massOf(b[1]), 0.05);
        QVERIFY(!b[2].mass);
        QCOMPARE(massOf(b[2]), 900 * l.block.length * l.block.thickness * l.block.width);
        QCOMPARE(massOf(b[3]), 0.2);
    }

    void commentsAreFoundOutsideQuotes() {
        QVERIFY(hasComments("# a scene\nformat: jacobs-ladder/1\n"));
        QVERIFY(hasComments("ladder: {blocks: 3}  # three\n"));
        QVERIFY(hasComments("ladder:\n  # indented\n  blocks: 3\n"));
        QVERIFY(!hasComments("format: jacobs-ladder/1\ntitle: \"No. #1\"\n"));
        QVERIFY(!hasComments("block: {color: '#c8a26b'}\n"));
        QVERIFY(!hasComments("title: issue#3\n"));  // '#' inside a word is text
        QVERIFY(!hasComments(""));
    }

    void theFormatPageHoldsTheCurrentTables() {
        const std::filesystem::path page = std::filesystem::path(JL_SOURCE_DIR) / "docs" / "scene-format.md";
        std::ifstream in(page, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        const std::string committed = text.str();
        for (std::string_view section : kDocumentedSections) {
            QVERIFY2(committed.find("<!-- fields: " + std::string(section) + " -->") != std::string::npos,
                     section.data());
            const std::string table = fieldTable(section);  // a header and rows
            QVERIFY2(std::count(table.begin(), table.end(), '\n') > 2, section.data());
        }
        const std::string current = withCurrentFieldTables(committed);
        if (current != committed && std::getenv("JL_UPDATE_DOCS")) {
            std::ofstream(page, std::ios::binary) << current;
            qInfo("rewrote %s", page.c_str());
            return;
        }
        QVERIFY2(current == committed,
                 "docs/scene-format.md is not current: run JL_UPDATE_DOCS=1 build/bin/test_scene_fields");
        QVERIFY(current.find("| `thickness` | number | m | `0.012` |") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(TestSceneFields)
#include "test_scene_fields.moc"
