// A deterministic fuzz test of the scene loader: seeded mutations of the good
// and bad scene files must each give a scene or errors, quickly, and a
// loaded scene must survive a save and load unchanged, and run: every step
// moves time on or the run stops with a reason (what the ranges of
// docs/scene-format.md promise).
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

std::vector<std::string> seeds() {
    std::vector<std::string> texts;
    for (const char* dir : {"examples", "tests/fixtures/bad"})
        for (const auto& entry : fs::directory_iterator(fs::path(JL_SOURCE_DIR) / dir)) {
            if (entry.path().extension() != ".yaml") continue;
            std::ifstream in(entry.path(), std::ios::binary);
            texts.emplace_back(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        }
    return texts;
}

// The pieces most likely to confuse a YAML reader or a validator.
const std::vector<std::string> kPieces = {
    ":",
    "-",
    "[",
    "]",
    "{",
    "}",
    ",",
    "#",
    "&a ",
    "*a",
    "!!str ",
    "'",
    "\"",
    "\n",
    "  ",
    "\t",
    "---\n",
    "? ",
    "|",
    ">",
    "\\",
    "%",
    "@",
    "\xc3",
    "\xff",
    "\0",
    "~",
    "null",
    "1e-300",
    "1e300",
    "!!str ",
    "\r",
    "[[[[[[[[[[[[[[[[",
    "#c8a26b",
    "\\x01",
    "1e999",
    "-0",
    ".nan",
    ".inf",
    "99999999999999999999",
    "1000000000",
    "-1",
    "0",
    "180deg",
    "block:9",
    "\"#zz\"",
};

std::string mutate(std::string text, std::mt19937_64& rng) {
    auto pick = [&](std::size_t n) { return n == 0 ? 0 : std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
    const int count = 1 + static_cast<int>(pick(4));
    for (int k = 0; k < count; ++k) {
        const std::size_t at = pick(text.size() + 1);
        switch (pick(6)) {
            case 0:  // flip a byte
                if (!text.empty()) text[pick(text.size())] ^= static_cast<char>(1 << pick(8));
                break;
            case 1:
                text.erase(at, pick(16));
                break;
            case 2:
                text.insert(at, kPieces[pick(kPieces.size())]);
                break;
            case 3: {  // duplicate a line
                const std::size_t begin = text.rfind('\n', at == 0 ? 0 : at - 1);
                const std::size_t start = begin == std::string::npos ? 0 : begin + 1;
                const std::size_t end = text.find('\n', start);
                const std::string line =
                    text.substr(start, end == std::string::npos ? std::string::npos : end - start + 1);
                text.insert(start, line);
                break;
            }
            case 4: {  // replace a number with an extreme one
                const std::size_t digit = text.find_first_of("0123456789", at);
                if (digit != std::string::npos) text.replace(digit, 1, kPieces[kPieces.size() - 9 + pick(6)]);
                break;
            }
            default:
                text.resize(at);
                break;  // truncate
        }
    }
    return text;
}

// A few steps of a small loaded scene: time moves on, or the run stops with
// a reason. A step may return without moving time when it is retried
// shorter, but only a bounded number of times. (Large scenes are left out:
// building them is slow.)
long scenesRun = 0;

bool runs(const jl::Scene& scene, long iteration) {
    const std::size_t parts =
        (scene.ladder ? std::size_t(scene.ladder->blocks) : 0) + scene.bodies.size() + scene.particles.size();
    if (parts > 64) return true;
    jl::Simulation::Built built = jl::Simulation::build(scene);
    if (!built.simulation) return true;  // refused with errors: a reason
    jl::Simulation& sim = *built.simulation;
    ++scenesRun;
    int moved = 0, stood = 0;
    while (moved < 20) {
        const double before = sim.time();
        if (!sim.stepOnce()) {
            if (!sim.failure().empty()) return true;
            std::fprintf(stderr, "iteration %ld: a step failed without a reason\n", iteration);
            return false;
        }
        if (sim.time() > before)
            ++moved;
        else if (++stood > 100) {
            std::fprintf(stderr, "iteration %ld: time stands at %g s\n", iteration, before);
            return false;
        }
    }
    return true;
}

bool check(const std::string& text, long iteration) {
    const auto start = std::chrono::steady_clock::now();
    jl::SceneLoad load;
    try {
        load = jl::parseScene(text, "mutant.yaml");
    } catch (...) {
        std::fprintf(stderr, "iteration %ld: parseScene threw\n", iteration);
        return false;
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    bool ok = true;
    if (load.scene.has_value() == !load.errors.empty()) {
        std::fprintf(stderr, "iteration %ld: expected a scene or errors, not both or neither\n", iteration);
        ok = false;
    }
    if (seconds > 5.0) {
        std::fprintf(stderr, "iteration %ld: took %.1f s\n", iteration, seconds);
        ok = false;
    }
    if (load.scene) {
        const jl::SceneLoad back = jl::parseScene(jl::sceneToYaml(*load.scene), "saved.yaml");
        if (!back.scene || !(*back.scene == *load.scene)) {
            std::fprintf(stderr, "iteration %ld: the loaded scene does not survive a save and load\n", iteration);
            ok = false;
        }
        ok = runs(*load.scene, iteration) && ok;
    }
    if (!ok) std::fprintf(stderr, "---- input ----\n%s\n---------------\n", text.c_str());
    return ok;
}

}  // namespace

int main() {
    const char* env = std::getenv("JL_FUZZ_ITERATIONS");
    const long iterations = env ? std::atol(env) : 3000;  // small for CI; raise it by hand
    const std::vector<std::string> texts = seeds();
    if (texts.empty()) {
        std::fprintf(stderr, "no seed files found under %s\n", JL_SOURCE_DIR);
        return 1;
    }
    std::mt19937_64 rng(20240611);
    int failures = 0;
    for (long i = 0; i < iterations && failures < 10; ++i) {
        const std::string& seed = texts[static_cast<std::size_t>(i) % texts.size()];
        if (!check(mutate(seed, rng), i)) ++failures;
    }
    std::printf("%ld mutated scene files (%ld loaded and run), %d failures\n", iterations, scenesRun, failures);
    return failures == 0 ? 0 : 1;
}
