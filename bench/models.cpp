#include "bench/models.h"

#include "jl/base/thread_clock.h"
#include "jl/scene/scene_fields.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace jl::bench {

namespace {

// A ladder of `blocks` blocks of the given thickness, its top block turned
// half a turn at 0.2 s: the right way (the cascade of classic.yaml) or the
// wrong way (wrong-way.yaml: hinge 1 locks and the ladder swings round).
Scene cascade(int blocks, double thickness, double duration, bool rightWay) {
    Scene s;
    s.ladder = LadderSpec{};
    s.ladder->blocks = blocks;
    s.ladder->block.thickness = thickness;
    ScriptAction turn;
    turn.at = 0.2;
    turn.angle = rightWay ? std::numbers::pi : -std::numbers::pi;
    turn.duration = 0.3;
    s.script.push_back(turn);
    s.duration = duration;
    return s;
}

struct Model {
    const char* name;
    RigidPairs pairs;
    bool sparse;
};
constexpr Model kModels[] = {{"merged, chain solver", RigidPairs::Merge, false},
                             {"merged, sparse solver", RigidPairs::Merge, true},
                             {"welded, sparse solver", RigidPairs::Weld, true}};

struct Outcome {
    std::vector<Event> events;
    std::vector<Pose> poses;
    std::string failure;
    double bodies = 0, rows = 0;  // mean over steps: dynamic bodies, constraint rows
};

std::unique_ptr<Simulation> start(const Scene& scene, bool sparse) {
    Simulation::Built built = Simulation::build(scene);
    if (built.simulation) built.simulation->useSparseSolver(sparse);
    return std::move(built.simulation);
}

Outcome finish(Simulation& sim) {
    Outcome o;
    Frame f = sim.frame();
    o.events = f.events;
    o.poses = f.poses;
    o.failure = f.failure;
    return o;
}

// The size of the problem each step solves, averaged over the steps.
void countUnknowns(const Scene& scene, Outcome& o) {
    auto sim = start(scene, false);
    long long steps = 0;
    double bodies = 0, rows = 0;
    while (sim->time() < scene.duration && sim->stepOnce()) {
        const World& w = sim->world();
        int dynamic = 0;
        for (int b = 0; b < w.bodyCount(); ++b) dynamic += w.body(b).alive && !w.body(b).kinematic;
        bodies += dynamic;
        rows += w.constraintRows();
        ++steps;
    }
    o.bodies = bodies / double(std::max(steps, 1LL));
    o.rows = rows / double(std::max(steps, 1LL));
}

double worstDistance(const std::vector<Pose>& a, const std::vector<Pose>& b) {
    if (a.size() != b.size()) return NAN;
    double worst = 0;
    for (size_t i = 0; i < a.size(); ++i) worst = std::max(worst, (a[i].position - b[i].position).norm());
    return worst;
}

// How many events match the reference in order (kind and hinge), and the
// worst time difference among them.
std::pair<size_t, double> eventAgreement(const std::vector<Event>& a, const std::vector<Event>& ref) {
    size_t same = 0;
    double worst = 0;
    while (same < a.size() && same < ref.size() && a[same].kind == ref[same].kind && a[same].hinge == ref[same].hinge) {
        worst = std::max(worst, std::abs(a[same].time - ref[same].time));
        ++same;
    }
    return {same, worst};
}

}  // namespace

std::vector<BenchRow> rigidPairModelStudy(const BenchPlan& plan) {
    struct Case {
        const char* study;
        int blocks;
        double thickness, duration;
        bool rightWay;
    };
    // The classic six blocks both ways; the thin 25-block ladder whose
    // ripple runs 23 hinges (docs/model.md section 15); and 25 thick blocks
    // turned the wrong way, where most pairs lock.
    const std::vector<Case> cases = plan.quick ? std::vector<Case>{{"models_classic6", 6, 0.012, 1.2, true}}
                                               : std::vector<Case>{{"models_classic6", 6, 0.012, 1.2, true},
                                                                   {"models_wrongway6", 6, 0.012, 1.2, false},
                                                                   {"models_thin25", 25, 0.003, 3.0, true},
                                                                   {"models_wrongway25", 25, 0.012, 1.2, false}};
    struct Config {
        Integrator kind;
        double parameter;
    };
    const std::vector<Config> configs = plan.quick ? std::vector<Config>{{Integrator::RK4, 1e-3}}
                                                   : std::vector<Config>{{Integrator::RK4, 1e-3},
                                                                         {Integrator::RK4, 2.5e-4},
                                                                         {Integrator::DormandPrince45, 1e-7},
                                                                         {Integrator::DormandPrince45, 1e-10}};
    std::vector<BenchRow> rows;
    for (const Case& c : cases) {
        // One reference for all three models: merged, tight Dormand-Prince.
        Scene tight = cascade(c.blocks, c.thickness, c.duration, c.rightWay);
        tight.solver.integrator = Integrator::DormandPrince45;
        tight.solver.tolerance = 1e-12;
        tight.solver.eventTolerance = 1e-12;
        auto refSim = start(tight, false);
        refSim->advanceExactlyTo(c.duration);
        const Outcome reference = finish(*refSim);
        // The welded model at the same tight settings: how far apart the two
        // models are when the integration error is gone.
        tight.solver.rigidPairs = RigidPairs::Weld;
        auto weldSim = start(tight, true);
        weldSim->advanceExactlyTo(c.duration);
        const Outcome weldedTight = finish(*weldSim);
        BenchRow models{std::string(c.study) + "_tight",
                        "dormand_prince45, welded against merged",
                        c.blocks,
                        1e-12,
                        0,
                        worstDistance(weldedTight.poses, reference.poses),
                        reference.failure.empty() && weldedTight.failure.empty(),
                        ""};
        const auto [agree, worst] = eventAgreement(weldedTight.events, reference.events);
        char line[200];
        std::snprintf(line, sizeof line, "%zu of %zu events in the same order, worst time difference %.1e s", agree,
                      reference.events.size(), worst);
        models.note = line;
        std::fprintf(stderr, "  %s: the two models at tolerance 1e-12 differ by %.2e m; %s\n", c.study, models.error,
                     line);
        rows.push_back(models);
        for (const Config& k : configs)
            for (const Model& m : kModels) {
                Scene s = cascade(c.blocks, c.thickness, c.duration, c.rightWay);
                s.solver.integrator = k.kind;
                if (k.kind == Integrator::DormandPrince45)
                    s.solver.tolerance = k.parameter;
                else
                    s.solver.step = k.parameter;
                s.solver.rigidPairs = m.pairs;
                BenchRow row{
                    c.study, std::string(integratorWord(k.kind)) + ", " + m.name, c.blocks, k.parameter, 0, 0, true,
                    ""};
                Outcome o;
                int runs = 0;
                const double begin = threadSeconds();
                do {
                    auto sim = start(s, m.sparse);
                    sim->advanceExactlyTo(c.duration);
                    o = finish(*sim);
                    ++runs;
                } while (o.failure.empty() && threadSeconds() - begin < plan.minSeconds);
                row.cost = (threadSeconds() - begin) / runs / c.duration;
                row.finished = o.failure.empty();
                countUnknowns(s, o);
                const auto [same, worstTime] = eventAgreement(o.events, reference.events);
                row.error = row.finished ? worstDistance(o.poses, reference.poses) : NAN;
                char note[240];
                std::snprintf(
                    note, sizeof note,
                    "%.1f dynamic bodies, %.1f constraint rows on average; %zu of %zu events in the reference "
                    "order, worst time error %.1e s%s%s",
                    o.bodies, o.rows, same, reference.events.size(), worstTime,
                    row.finished ? "" : "; failed: ", o.failure.c_str());
                row.note = note;
                std::fprintf(stderr, "  %s %-40s cost %.3g error %.3g  %s\n", c.study, row.method.c_str(), row.cost,
                             row.error, note);
                rows.push_back(row);
            }
    }
    return rows;
}

}  // namespace jl::bench
