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

// Every number of one section: set, saved, loaded back bit for bit.
template <class Section, std::size_t N, class At>
void eachNumberRoundTrips(const NumberField<Section> (&numbers)[N], At at) {
    for (const NumberField<Section>& n : numbers) {
        Scene s = ladderScene();
        const double v = insideValue(n.range);
        QVERIFY2(n.range.contains(v), n.key.data());
        at(s).*n.member = v;
        const Scene back = reloaded(s);
        QVERIFY2(back.ladder, n.key.data());
        QVERIFY2(at(const_cast<Scene&>(back)).*n.member == v, n.key.data());
    }
}

// A value just past a range's upper end is refused, and the message says the range.
template <class Section, std::size_t N>
void eachNumberIsChecked(std::string_view section, const NumberField<Section> (&numbers)[N]) {
    for (const NumberField<Section>& n : numbers) {
        if (!std::isfinite(n.range.hi)) continue;
        const double past = n.range.hi > 0 ? n.range.hi * 2 + 1 : 1;
        std::string yaml = "format: jacobs-ladder/1\nladder: {blocks: 3}\n";
        const std::size_t dot = section.find('.');
        if (dot == std::string_view::npos)
            yaml += std::string(section) + ": {" + std::string(n.key) + ": " + std::to_string(past) + "}\n";
        else
            yaml = "format: jacobs-ladder/1\nladder: {blocks: 3, " + std::string(section.substr(dot + 1)) + ": {" +
                   std::string(n.key) + ": " + std::to_string(past) + "}}\n";
        const SceneLoad load = parseScene(yaml, "past.yaml");
        QVERIFY2(!load.scene, (std::string(section) + "." + std::string(n.key)).c_str());
        QVERIFY(!load.errors.empty());
        const std::string message = load.errors.front().format();
        QVERIFY2(message.find(std::string(n.key)) != std::string::npos, message.c_str());
        QVERIFY2(message.find(n.range.describe()) != std::string::npos, message.c_str());
    }
}

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
        eachNumberRoundTrips(kBlockNumbers, [](Scene& s) -> BlockSpec& { return s.ladder->block; });
        eachNumberRoundTrips(kRibbonNumbers, [](Scene& s) -> RibbonSpec& { return s.ladder->ribbons; });
        eachNumberRoundTrips(kHingeNumbers, [](Scene& s) -> HingeOptions& { return s.ladder->hinges; });
        eachNumberRoundTrips(kDampingNumbers, [](Scene& s) -> Scene& { return s; });
        eachNumberRoundTrips(kSolverNumbers, [](Scene& s) -> SolverSpec& { return s.solver; });
        eachNumberRoundTrips(kViewNumbers, [](Scene& s) -> ViewSpec& { return s.view; });
    }

    void everyNumberIsCheckedAgainstItsRange() {
        eachNumberIsChecked("ladder.block", kBlockNumbers);
        eachNumberIsChecked("ladder.ribbons", kRibbonNumbers);
        eachNumberIsChecked("ladder.hinges", kHingeNumbers);
        eachNumberIsChecked("damping", kDampingNumbers);
        eachNumberIsChecked("solver", kSolverNumbers);
        eachNumberIsChecked("view", kViewNumbers);
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
        for (std::string_view section : kDocumentedSections)
            QVERIFY2(committed.find("<!-- fields: " + std::string(section) + " -->") != std::string::npos,
                     section.data());
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
