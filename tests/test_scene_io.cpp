// labels: io
// Scene files: round trips, atomic saves, and a corpus of bad files each with
// the message it must produce ("# expect: line:column: text" in the file).
#include "jl/base/output_file.h"
#include "jl/scene/scalar_text.h"
#include "jl/scene/scene_io.h"

#include <QtTest>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace jl;

namespace {

std::string readBytes(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void writeBytes(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

std::string allErrors(const SceneLoad& load) {
    std::string out;
    for (const Diagnostic& d : load.errors) out += d.format() + "\n";
    return out;
}

// A ladder scene that sets nearly every field to something not the default,
// with numbers that only read back exactly if written with full precision.
Scene ladderScene() {
    Scene s;
    s.title = "Tricky: \"quotes\", #hash, 'ticks' and ünïcödé";
    s.description = "Line one\nline two\twith a tab\n  indented, trailing space ";
    LadderSpec& l = s.ladder.emplace();
    l.blocks = 9;
    l.block = {0.061, 0.1 + 0.2, 0.047, 612.5, 0.0123456789012345678, Color{1, 2, 3}};
    l.overrides = {{3, 0.004, std::nullopt, 800.0, std::nullopt, Color{255, 0, 128}}, {7, {}, 0.05, {}, 0.2, {}}};
    l.ribbons = {0.009, 0.014, 0.0004, 0.005, Color{10, 20, 30}, Color{200, 30, 30}, false};
    l.hinges = {1e-6, 0.25, 3e-4};
    l.held = {0, 4};
    l.initial.kind = InitialState::Kind::Poses;
    for (int i = 0; i < l.blocks; ++i)
        l.initial.poses.push_back(
            {i, {0.001 * i, -0.06 * i - 1e-17}, std::numbers::pi / (i + 3), {i * 0.5, -0.25}, 1.0 / 3.0});
    s.gravity = {0.5, -9.80665};
    s.linearDamping = 0.01;
    s.angularDamping = 2e-5;
    s.duration = 12.75;
    s.solver = {Integrator::DormandPrince45, 2.5e-4, 1e-9,        1e-12,
                EventPolicy::EndOfStep,      1e-10,  1.0 / 120.0, RigidPairs::Weld};
    using K = ScriptAction::Kind;
    ScriptAction turn{.kind = K::Turn, .at = 0.2, .block = 0, .angle = -std::numbers::pi, .duration = 0.3};
    ScriptAction turn2{.kind = K::Turn, .at = 1.1, .block = 4, .angle = 1.2345678901234567, .duration = 0.7};
    ScriptAction move{.kind = K::Move, .at = 2, .block = 0, .offset = {0.01, -0.02}, .duration = 0.25};
    ScriptAction hold{.kind = K::Hold, .at = 3, .block = 2};
    ScriptAction release{.kind = K::Release, .at = 3.5, .block = 4};
    ScriptAction push{.kind = K::Push, .at = 4, .block = 5, .impulse = {0.01, 0}, .point = {0.002, 0.03}};
    ScriptAction cut{.kind = K::Cut, .at = 5, .hinge = 8};
    ScriptAction join{.kind = K::Join, .at = 6, .block = 1, .otherBlock = 2, .corner = 3, .otherCorner = 1};
    s.script = {turn, turn2, move, hold, release, push, cut, join};
    s.drags = {{3, {0.001, -0.02}, {{0.5, {0.1, -0.2}}, {0.51, {0.11, -0.21}}, {0.75, {0.3, 1e-300}}}, 1.25}};
    s.view = {{0.01, -0.4}, 1.5, -30, 45};
    s.floor = FloorSpec{-0.75};
    return s;
}

// A general scene: bodies, particles, pins and springs, no ladder.
Scene generalScene() {
    Scene s;
    s.title = "123";  // looks like a number; must stay text
    BodySpec a;
    a.name = "arm";
    a.length = 0.1;
    a.mass = 0.3;
    a.inertia = 2.5e-4;
    a.position = {0.1, -0.05};
    a.angle = 0.3;
    a.velocity = {0, -1};
    a.angularVelocity = -2;
    a.held = true;
    a.color = {0, 0, 0};
    BodySpec b;
    b.name = "true";
    s.bodies = {a, b};
    s.particles = {{"bob", 0.02, {0.3, -0.1}, {1, 0}}, {"p2", 1e-3, {}, {}}};
    s.pins = {{{"world", {0, 0}}, {"arm", {0, 0.05}}, std::nullopt, std::nullopt}};
    s.springs = {{{"arm", {0, -0.05}}, {"bob", {}}, 250, 0.08, 0.1}, {{"bob", {}}, {"p2", {}}, 50, std::nullopt, 0}};
    s.gravity = {0, 0};
    return s;
}

}  // namespace

class TestSceneIo : public QObject {
    Q_OBJECT

private slots:
    void diagnosticFormatsLikeACompiler() {
        QCOMPARE(Diagnostic({"a.yaml", 3, 7, "bad"}).format(), std::string("a.yaml:3:7: bad"));
        QCOMPARE(Diagnostic({"a.yaml", 0, 0, "gone"}).format(), std::string("a.yaml: gone"));
    }

    void roundTripKeepsEveryField() {
        for (const Scene& scene : {ladderScene(), generalScene(), Scene{}}) {
            Scene s = scene;
            if (!s.ladder && s.bodies.empty()) s.ladder.emplace();  // a scene must hold something
            const std::string text = sceneToYaml(s);
            const SceneLoad back = parseScene(text, "saved.yaml");
            QVERIFY2(back.scene, (allErrors(back) + text).c_str());
            QVERIFY2(*back.scene == s, text.c_str());
            QCOMPARE(sceneToYaml(*back.scene), text);
        }
    }

    void roundTripFoldAnglesAndAwkwardNumbers() {
        Scene s;
        LadderSpec& l = s.ladder.emplace();
        l.blocks = 4;
        l.initial.kind = InitialState::Kind::FoldAngles;
        l.initial.foldAngles = {0, std::atan(0.2), std::nextafter(std::numbers::pi, 0.0)};
        l.initial.poses = {{0, {0.5, 5e-324}, 0.1, {}, 0}};  // the smallest double
        l.block.density = std::nextafter(1.0, 2.0);          // just inside the range
        s.duration = std::nextafter(5.0, 6.0);
        const SceneLoad back = parseScene(sceneToYaml(s), "saved.yaml");
        QVERIFY2(back.scene, allErrors(back).c_str());
        QVERIFY(*back.scene == s);
    }

    void saveWritesOnlyWhatDiffersFromDefaults() {
        Scene s;
        s.ladder.emplace();
        QCOMPARE(sceneToYaml(s), std::string("format: jacobs-ladder/1\nladder:\n  blocks: 6\n"));
    }

    void savingTwiceGivesIdenticalBytes() {
        QTemporaryDir dir;
        const fs::path a = fs::path(dir.path().toStdString()) / "a.yaml";
        const fs::path b = fs::path(dir.path().toStdString()) / "b.yaml";
        QVERIFY(!saveScene(ladderScene(), a.string()));
        const SceneLoad loaded = loadScene(a.string());
        QVERIFY2(loaded.scene, allErrors(loaded).c_str());
        QVERIFY(!saveScene(*loaded.scene, b.string()));
        QCOMPARE(readBytes(a), readBytes(b));
    }

    void saveReplacesAnExistingFileWhole() {
        QTemporaryDir dir;
        const fs::path path = fs::path(dir.path().toStdString()) / "scene.yaml";
        writeBytes(path, std::string(100000, 'x'));  // longer than the scene
        QVERIFY(!saveScene(generalScene(), path.string()));
        QCOMPARE(readBytes(path), sceneToYaml(generalScene()));
        QCOMPARE(std::distance(fs::directory_iterator(path.parent_path()), fs::directory_iterator{}), 1L);
    }

    void failedSaveLeavesTheOldFileAndNoTemporary() {
        QTemporaryDir dir;
        const fs::path root(dir.path().toStdString());
        // The target is a directory: the rename must fail (even for root).
        const fs::path target = root / "taken.yaml";
        fs::create_directory(target);
        writeBytes(target / "inside", "old");
        const auto error = saveScene(ladderScene(), target.string());
        QVERIFY(error);
        QVERIFY(error->message.find("cannot save") != std::string::npos);
        QCOMPARE(readBytes(target / "inside"), std::string("old"));
        QCOMPARE(std::distance(fs::directory_iterator(root), fs::directory_iterator{}), 1L);
        // A directory that does not exist.
        QVERIFY(saveScene(ladderScene(), (root / "no" / "such.yaml").string()));
    }

    void saveIntoAnUnwritableDirectoryFails() {
        if (::geteuid() == 0) QSKIP("root can write anywhere; covered by the rename test");
        QTemporaryDir dir;
        const fs::path locked = fs::path(dir.path().toStdString()) / "locked";
        fs::create_directory(locked);
        writeBytes(locked / "scene.yaml", "old contents");
        ::chmod(locked.c_str(), 0555);
        const auto error = saveScene(ladderScene(), (locked / "scene.yaml").string());
        ::chmod(locked.c_str(), 0755);
        QVERIFY(error);
        QCOMPARE(readBytes(locked / "scene.yaml"), std::string("old contents"));
    }

    void saveThroughALinkReplacesWhatItPointsTo() {
        QTemporaryDir dir;
        const fs::path root(dir.path().toStdString());
        writeBytes(root / "real.yaml", "old");
        fs::create_symlink("real.yaml", root / "link.yaml");
        QVERIFY(!saveScene(generalScene(), (root / "link.yaml").string()));
        QVERIFY(fs::is_symlink(root / "link.yaml"));
        QCOMPARE(readBytes(root / "real.yaml"), sceneToYaml(generalScene()));
        QCOMPARE(std::distance(fs::directory_iterator(root), fs::directory_iterator{}), 2L);
    }

    void outputFileShowsNothingUntilCommitted() {
        QTemporaryDir dir;
        const fs::path root(dir.path().toStdString());
        const fs::path path = root / "out.csv";
        writeBytes(path, "old\n");
        {
            OutputFile out;
            QVERIFY(out.open(path.string()));
            QVERIFY(!out.direct());
            QVERIFY(out.write("new\n") && out.flush());
            QCOMPARE(readBytes(path), std::string("old\n"));
            QCOMPARE(readBytes(out.temporary()), std::string("new\n"));  // a killed process leaves this
            QVERIFY(out.commit());
        }
        QCOMPARE(readBytes(path), std::string("new\n"));
        {
            OutputFile out;  // abandoned: the temporary goes, the file stays
            QVERIFY(out.open(path.string()) && out.write("lost\n") && out.flush());
        }
        QCOMPARE(readBytes(path), std::string("new\n"));
        {
            OutputFile out;  // kept aside: the file stays, the partial result is kept
            QVERIFY(out.open(path.string()) && out.write("partial\n"));
            QVERIFY(out.keepAs(path.string() + ".partial"));
        }
        QCOMPARE(readBytes(path), std::string("new\n"));
        QCOMPARE(readBytes(path.string() + ".partial"), std::string("partial\n"));
        QCOMPARE(std::distance(fs::directory_iterator(root), fs::directory_iterator{}), 2L);
        {
            OutputFile out;  // kept aside again: the older result stays, the new one keeps its temporary
            QVERIFY(out.open(path.string()) && out.write("again\n"));
            QVERIFY(out.keepAs(path.string() + ".partial"));
            QVERIFY(out.kept() != path.string() + ".partial");
            QCOMPARE(readBytes(out.kept()), std::string("again\n"));
        }
        QCOMPARE(readBytes(path.string() + ".partial"), std::string("partial\n"));
        QCOMPARE(std::distance(fs::directory_iterator(root), fs::directory_iterator{}), 3L);
    }

    void outputFileChecksEveryWrite() {
        OutputFile full;
        QVERIFY(full.open("/dev/full"));
        QVERIFY(full.direct());
        full.write(std::string(100, 'x'));
        QVERIFY(!full.commit());
        QVERIFY2(full.error().find(std::strerror(ENOSPC)) != std::string::npos, full.error().c_str());
        OutputFile none;
        QVERIFY(!none.open("/no/such/directory/out.csv"));
        QVERIFY(none.error().find("/no/such/directory") != std::string::npos);
        QTemporaryDir dir;
        OutputFile folder;
        QVERIFY(!folder.open(dir.path().toStdString()));
        QVERIFY(!folder.write("x"));
    }

    void badFilesReportTheExpectedErrors() {
        const fs::path dir = fs::path(JL_SOURCE_DIR) / "tests" / "fixtures" / "bad";
        int files = 0;
        for (const auto& entry : fs::directory_iterator(dir)) {
            if (entry.path().extension() != ".yaml") continue;
            ++files;
            checkExpectations(entry.path());
        }
        QVERIFY2(files >= 40, std::to_string(files).c_str());
    }

    void examplesLoadAndRoundTrip() {
        int files = 0;
        for (const auto& entry : fs::directory_iterator(fs::path(JL_SOURCE_DIR) / "examples")) {
            if (entry.path().extension() != ".yaml") continue;
            ++files;
            const SceneLoad load = loadScene(entry.path().string());
            QVERIFY2(load.scene && load.errors.empty(), allErrors(load).c_str());
            QVERIFY2(!load.scene->title.empty() && !load.scene->description.empty(), entry.path().c_str());
            const SceneLoad back = parseScene(sceneToYaml(*load.scene), "saved.yaml");
            QVERIFY(back.scene && *back.scene == *load.scene);
        }
        QVERIFY(files >= 8);
    }

    void fileProblemsAreReported() {
        QTemporaryDir dir;
        const fs::path root(dir.path().toStdString());
        expectOne(loadScene((root / "missing.yaml").string()), "cannot open");
        expectOne(loadScene(root.string()), "directory");
        writeBytes(root / "empty.yaml", "");
        expectOne(loadScene((root / "empty.yaml").string()), "empty");
        writeBytes(root / "big.yaml", "format: jacobs-ladder/1\nladder: {blocks: 6}\n");
        LoadLimits tiny;
        tiny.maxFileBytes = 10;
        expectOne(loadScene((root / "big.yaml").string(), tiny), "larger than");
        QVERIFY(loadScene((root / "big.yaml").string()).scene);
    }

    // Text that no scene has is refused before the YAML reader spends time on
    // it: a line of megabytes, a value longer than any description, a title
    // longer than a title bar (each with its place in the file).
    void overlongTextIsRefusedWithItsPlace() {
        const std::string head = "format: jacobs-ladder/1\nladder: {blocks: 6}\n";
        expectOne(parseScene(head + "title: " + std::string(2u << 20, 'a') + "\n", "s.yaml"),
                  "this line is 2048 KiB long, more than the 1024 KiB");
        std::string description = "description: \"";
        for (int i = 0; i < 2000; ++i) description += "a line of words, forty characters long.\n  ";
        expectOne(parseScene(head + description + "\"\n", "s.yaml"), "this value is 78 KiB long, more than the 64 KiB");
        const std::string accents = "title: \"" + [] {
            std::string s;
            for (int i = 0; i < 200; ++i) s += "\xc3\xa9";  // 200 characters, 400 bytes
            return s;
        }() + "\"\n";
        QVERIFY(parseScene(head + accents, "s.yaml").scene);
        expectOne(parseScene(head + "description: \"" + std::string(20'001, 'w') + "\"\n", "s.yaml"),
                  "description: at most 20000 characters, got 20001");
    }

    void limitsAreConfigurable() {
        LoadLimits limits;
        limits.maxBlocks = 10;
        expectOne(parseScene("format: jacobs-ladder/1\nladder: {blocks: 11}\n", "s.yaml", limits), "limit of 10");
        limits.maxNodes = 20;
        std::string many = "format: jacobs-ladder/1\nladder: {blocks: 6}\ngravity: [";
        for (int i = 0; i < 30; ++i) many += "1, ";
        expectOne(parseScene(many + "1]\n", "s.yaml", limits), "more than 20 YAML values");
    }

    // Both ends of a range are allowed and the next double beyond is not,
    // so that docs/scene-format.md's "a .. b" means what it says.
    void rangesIncludeTheirEnds_data() {
        QTest::addColumn<QString>("key");
        QTest::addColumn<double>("lo");
        QTest::addColumn<double>("hi");
        QTest::newRow("step") << "solver: {step: %1}" << 1e-6 << 0.1;
        QTest::newRow("tolerance") << "solver: {tolerance: %1}" << 1e-14 << 0.1;
        QTest::newRow("projection_tolerance") << "solver: {projection_tolerance: %1}" << 1e-15 << 1e-3;
        QTest::newRow("event_tolerance") << "solver: {event_tolerance: %1}" << 1e-14 << 0.1;
        QTest::newRow("frame_interval") << "solver: {frame_interval: %1}" << 1e-6 << 1e5;
        QTest::newRow("block length") << "ladder: {block: {length: %1}}" << 1e-4 << 100.0;
        QTest::newRow("block mass") << "ladder: {block: {mass: %1}}" << 1e-6 << 1e6;
        QTest::newRow("gravity") << "gravity: [0, %1]" << -1e3 << 1e3;
        QTest::newRow("at") << "script: [{at: %1, hold: {block: 1}}]" << 0.0 << 1e5;
        QTest::newRow("stiffness")
            << "particles: [{name: p}]\nsprings: [{a: {body: world}, b: {body: p}, stiffness: %1}]" << 0.0 << 1e7;
    }

    void rangesIncludeTheirEnds() {
        QFETCH(QString, key);
        QFETCH(double, lo);
        QFETCH(double, hi);
        const auto load = [&](double x) {
            const std::string ladder = key.startsWith("ladder") ? "" : "ladder: {blocks: 6}\n";
            const std::string value = key.arg(QString::fromStdString(formatNumber(x))).toStdString();
            return parseScene("format: jacobs-ladder/1\n" + ladder + value + "\n", "s.yaml");
        };
        const double inf = std::numeric_limits<double>::infinity();
        for (double x : {lo, hi}) QVERIFY2(load(x).scene, allErrors(load(x)).c_str());
        for (double x : {std::nextafter(lo, -inf), std::nextafter(hi, inf)}) expectOne(load(x), "expected a number in");
    }

    void loadNeverHalfApplies() {
        // One bad value anywhere and there is no scene at all.
        const SceneLoad load = parseScene("format: jacobs-ladder/1\nladder: {blocks: 6}\nduration: -1\n", "s.yaml");
        QVERIFY(!load.scene);
        QCOMPARE(load.errors.size(), std::size_t(1));
    }

private:
    static void expectOne(const SceneLoad& load, const std::string& text) {
        QVERIFY(!load.scene);
        QVERIFY2(load.errors.size() == 1 && load.errors[0].message.find(text) != std::string::npos,
                 (allErrors(load) + " (wanted: " + text + ")").c_str());
    }

    // Every "# expect: L:C: text" line names an error the file must produce.
    static void checkExpectations(const fs::path& file) {
        const SceneLoad load = loadScene(file.string());
        const std::string name = file.filename().string();
        QVERIFY2(!load.scene, (name + " loaded").c_str());
        std::istringstream lines(readBytes(file));
        int expectations = 0;
        for (std::string line; std::getline(lines, line);) {
            if (!line.starts_with("# expect: ")) continue;
            ++expectations;
            int l = 0, c = 0, used = 0;
            QVERIFY2(std::sscanf(line.c_str(), "# expect: %d:%d: %n", &l, &c, &used) == 2, line.c_str());
            const std::string text = line.substr(static_cast<std::size_t>(used));
            const bool found = std::any_of(load.errors.begin(), load.errors.end(), [&](const Diagnostic& d) {
                return d.line == l && d.column == c && d.message.find(text) != std::string::npos;
            });
            QVERIFY2(found, (name + ": wanted " + line.substr(10) + "\ngot:\n" + allErrors(load)).c_str());
        }
        QVERIFY2(expectations > 0, (name + " has no '# expect:' line").c_str());
    }
};

QTEST_GUILESS_MAIN(TestSceneIo)
#include "test_scene_io.moc"
