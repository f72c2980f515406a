#include "bench/contacts.h"

#include "jl/base/thread_clock.h"
#include "jl/ladder/block_contact.h"
#include "jl/ladder/ladder.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/recording.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace jl::bench {

namespace {

struct Run {
    double cpu = 0;
    long long steps = 0;
    double balance = 0;
    std::vector<Event> events;
    std::string failure;
};

Run runOnce(Scene scene, BlockContact contact, double horizon) {
    scene.solver.blockContact = contact;
    Run r;
    const double t0 = threadSeconds();
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        r.failure = built.errors.empty() ? "not built" : built.errors.front();
        return r;
    }
    // Every event, and the books on a frame every tenth of a second
    // (jl/sim/recording.h).
    WholeRun whole;
    const Recording recorded = record(*built.simulation, std::min(horizon, scene.duration), FrameGrid{0, 0.1}, &whole);
    r.events = std::move(whole.events);
    r.cpu = threadSeconds() - t0;
    r.balance = recorded.worstBalance;
    r.steps = recorded.steps;
    r.failure = recorded.failure;
    return r;
}

// Whether two runs' events are the same sequence (kinds and hinges), and
// then the largest difference of their times; else where they part.
struct EventsCompared {
    bool sameSequence = true;
    double largestShift = 0;  // s, when the same sequence
    double partAt = -1;       // s, the first event that differs in kind or hinge
};

EventsCompared compareEvents(const std::vector<Event>& a, const std::vector<Event>& b) {
    EventsCompared c;
    const size_t n = std::min(a.size(), b.size());
    for (size_t i = 0; i < n; ++i) {
        if (a[i].kind != b[i].kind || a[i].hinge != b[i].hinge) {
            c.sameSequence = false;
            c.partAt = std::min(a[i].time, b[i].time);
            return c;
        }
        c.largestShift = std::max(c.largestShift, std::abs(a[i].time - b[i].time));
    }
    if (a.size() != b.size()) {
        c.sameSequence = false;
        c.partAt = a.size() > n ? a[n].time : b[n].time;
    }
    return c;
}

// Off and on taken in turn, at least `repetitions` times and until each
// has run `minSeconds` of CPU time in all, each the least of its runs: most
// examples run in about 10 ms, where one of three runs took whatever else
// the machine did (heavy-middle read 0.99x, 1.09x and 1.11x minutes apart).
// The ratio is the median of each turn's on / off: the two runs of a turn
// meet the same machine, so a slow spell cancels in it. The ratio of the
// least times moved by 0.13 between runs of this study a minute apart
// (heavy-middle 1.07x and 1.20x, its instructions 1.066x).
ContactExampleRow exampleRow(const std::string& name, const Scene& scene, double horizon, int repetitions,
                             double minSeconds) {
    ContactExampleRow row;
    row.scene = name;
    row.asked = std::min(horizon, scene.duration);
    Run off, on;
    double spentOff = 0, spentOn = 0;
    std::vector<double> ratios;
    for (int k = 0; k < 1000 && (k < repetitions || std::min(spentOff, spentOn) < minSeconds); ++k) {
        Run a = runOnce(scene, BlockContact::Off, horizon), b = runOnce(scene, BlockContact::On, horizon);
        spentOff += a.cpu, spentOn += b.cpu;
        if (a.cpu > 0) ratios.push_back(b.cpu / a.cpu);
        if (k == 0 || a.cpu < off.cpu) off = std::move(a);
        if (k == 0 || b.cpu < on.cpu) on = std::move(b);
    }
    row.cpuOff = off.cpu, row.cpuOn = on.cpu;
    row.turns = int(ratios.size());
    if (!ratios.empty()) {
        std::sort(ratios.begin(), ratios.end());
        const size_t m = ratios.size() / 2;
        row.ratio = ratios.size() % 2 ? ratios[m] : (ratios[m - 1] + ratios[m]) / 2;
    }
    row.stepsOff = off.steps, row.stepsOn = on.steps;
    row.eventsOff = int(off.events.size()), row.eventsOn = int(on.events.size());
    row.touches = int(
        std::count_if(on.events.begin(), on.events.end(), [](const Event& e) { return e.kind == EventKind::Touch; }));
    const EventsCompared compared = compareEvents(off.events, on.events);
    row.sameSequence = compared.sameSequence;
    row.largestShift = compared.largestShift;
    row.partAt = compared.partAt;
    row.balanceOn = on.balance;
    row.failureOff = off.failure, row.failureOn = on.failure;
    std::fprintf(stderr, "  contacts %-28s off %.3f CPU s, on %.3f CPU s (%.2fx), %d strikes%s\n", name.c_str(),
                 off.cpu, on.cpu, off.cpu > 0 ? on.cpu / off.cpu : 0.0, row.touches,
                 on.failure.empty() ? "" : (", failed: " + on.failure).c_str());
    return row;
}

BroadPhaseRow broadPhaseRow(Scene scene, int blocks, double minSeconds) {
    BroadPhaseRow row;
    row.blocks = blocks;
    scene.ladder->blocks = blocks;
    scene.solver.blockContact = BlockContact::On;
    const double t0 = threadSeconds();
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation) {
        row.failure = built.errors.empty() ? "not built" : built.errors.front();
        return row;
    }
    Simulation& sim = *built.simulation;
    sim.advanceTo(std::min(0.5, scene.duration));
    row.buildCpu = threadSeconds() - t0;
    row.failure = sim.failure();
    const Ladder& ladder = *sim.ladder();
    row.stillFrom = ladder.stillFrom() < ladder.blockCount() ? ladder.stillFrom() : -1;
    BlockPairs broad;
    std::vector<std::pair<int, int>> pairs;
    broad.find(sim.world(), ladder, pairs);  // warm: the grid's buffers sized once
    // In batches: reading the thread's CPU clock is a system call of about
    // a microsecond, as long as the whole call on a dozen blocks.
    // The fastest of five windows of a fifth of minSeconds each: another
    // job on a shared machine slows some windows, and never speeds one up.
    // A search (what every call cost until the pairs were kept), and a call
    // that finds its pairs kept (what most steps of a run cost).
    const int batch = std::max(1, 100000 / blocks);
    const auto fastestCall = [&](bool search) {
        double fastest = std::numeric_limits<double>::infinity();
        for (int window = 0; window < 5; ++window) {
            int calls = 0;
            const double start = threadSeconds();
            double took = 0;
            do {
                for (int k = 0; k < batch; ++k) {
                    if (search) broad.forget();
                    broad.find(sim.world(), ladder, pairs);
                }
                calls += batch;
                took = threadSeconds() - start;
            } while (took < minSeconds / 5);
            row.calls += calls;
            fastest = std::min(fastest, took / calls);
        }
        return fastest;
    };
    row.perBlock = fastestCall(true) / blocks;
    row.perBlockKept = fastestCall(false) / blocks;
    row.pairs = int(pairs.size());
    std::fprintf(stderr, "  broad phase %6d blocks: %.3g s per block per search, %.3g kept, %d pairs, still from %d\n",
                 blocks, row.perBlock, row.perBlockKept, row.pairs, row.stillFrom);
    return row;
}

}  // namespace

ContactsStudy contactsStudy(const BenchPlan& plan, const std::filesystem::path& dir) {
    ContactsStudy s;
    std::vector<std::filesystem::path> files;
    std::error_code ec;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".yaml") files.push_back(entry.path());
    if (ec || files.empty()) {
        s.error = "no scenes in " + dir.string() + (ec ? ": " + ec.message() : "");
        std::fprintf(stderr, "  %s\n", s.error.c_str());
        return s;
    }
    std::sort(files.begin(), files.end());
    const double horizon = plan.quick ? 1.0 : 3.0;
    const int repetitions = plan.quick ? 1 : 3;
    for (const std::filesystem::path& file : files) {
        const SceneLoad load = loadScene(file.string());
        if (!load.scene) continue;
        s.examples.push_back(
            exampleRow(file.filename().string(), *load.scene, horizon, repetitions, plan.quick ? 0.0 : 0.5));
        if (file.filename() == "classic.yaml" && load.scene->ladder) {
            const std::vector<int> sizes =
                plan.quick ? std::vector<int>{12, 100, 1000, 10000} : std::vector<int>{12, 100, 1000, 10000, 100000};
            for (int n : sizes) s.broad.push_back(broadPhaseRow(*load.scene, n, plan.quick ? 0.02 : 0.2));
        }
    }
    return s;
}

}  // namespace jl::bench
