#include "bench/report.h"

#include "bench/contacts_report.h"
#include "bench/report_text.h"
#include "bench/save_text.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <sstream>
#include <thread>

namespace jl::bench {

namespace {

bool isPeer(const BenchRow& r) {
    return r.method.find("mujoco") == 0 || r.method.find("box2d") == 0 || r.method.find("bullet") == 0;
}

void table(std::ostream& md, const std::vector<BenchRow>& rows, const char* parameter, const char* error) {
    md << "| method | N | " << parameter << " | CPU s per simulated s | " << error
       << " | note |\n|---|---:|---:|---:|---:|---|\n";
    for (const BenchRow& r : rows)
        md << "| " << r.method << " | " << r.blocks << " | " << num(r.parameter) << " | " << num(r.cost) << " | "
           << (r.finished ? num(r.error) : "failed") << " | " << r.note << " |\n";
    md << '\n';
}

// Our lowest error among runs that cost no more than `cost`.
double bestErrorWithin(const std::vector<BenchRow>& rows, double cost) {
    double best = INFINITY;
    for (const BenchRow& r : rows)
        if (!isPeer(r) && r.finished && r.cost <= cost) best = std::min(best, r.error);
    return best;
}

// Our lowest cost among runs at least as accurate as `error`.
double bestCostWithin(const std::vector<BenchRow>& rows, double error) {
    double best = INFINITY;
    for (const BenchRow& r : rows)
        if (!isPeer(r) && r.finished && r.error <= error) best = std::min(best, r.cost);
    return best;
}

std::string whole(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.0f", x);
    return s;
}

std::string ms(double seconds) { return std::isfinite(seconds) ? sig(1e3 * seconds, 4) + " ms" : "—"; }

// |R(i y)| of RK4 (and of every 4-stage 4th-order explicit Runge-Kutta method).
double rk4Growth(double y) { return std::sqrt(1 - std::pow(y, 6) / 72 + std::pow(y, 8) / 576); }

// The paragraph on the long-ladder target: RK4 at 1 ms beyond or within its limit.
std::string stabilityTarget(const StabilityStudy& s, bool quick, bool& ok) {
    if (s.rows.empty()) return "";
    const StabilityRow& big = s.rows.back();
    const double y = big.omegaMax * 1e-3;
    TemplateValues v{{"blocks", std::to_string(big.blocks)},
                     {"quick_note", quick ? ", the largest of this quick run" : ""},
                     {"y", sig(y, 3)},
                     {"rk4_imaginary", sig(s.imaginaryRk4, 4)}};
    if (y <= s.imaginaryRk4) {
        v["cost"] = std::isfinite(big.turnedCost)
                        ? " At the largest step that ran, the turned-over ladder cost " + sig(big.turnedCost, 3) +
                              " CPU s per simulated s (" + sig(1 / big.turnedCost, 3) + "x real time)."
                        : "";
        return filled("stability_within", v, ok);
    }
    const double yTurn = y * std::sqrt(big.peakTension);
    v["growth"] = sig(rk4Growth(y), 3);
    v["rk4_limit"] = ms(big.rk4Limit);
    v["seeded_pass"] = ms(big.seededPass);
    v["seeded_fail"] = ms(big.seededFail);
    v["peak_tension"] = sig(big.peakTension, 3);
    v["horizon"] = sig(big.horizon, 2);
    v["turned_pass"] = ms(big.turnedPass);
    v["turned_fail"] = ms(big.turnedFail);
    v["y_turn"] = sig(yTurn, 3);
    v["stages"] = std::to_string(int(std::ceil(y + 1)));
    v["stages_turn"] = std::to_string(int(std::ceil(yTurn + 1)));
    v["evaluations"] = whole(std::ceil(y + 1) * 1e3);
    v["evaluations_turn"] = whole(std::ceil(yTurn + 1) * 1e3);
    v["rk4_evaluations"] = whole(4 / big.rk4Limit);
    v["rk4_evaluations_turn"] = whole(4 / big.turnedPass);
    v["cost"] = "";
    if (std::isfinite(big.turnedCost)) {
        const double evaluations = 4 / big.turnedPass * big.blocks;  // block-evaluations per simulated second
        v["cost"] = " At the largest step that ran, the turned-over ladder cost " + sig(big.turnedCost, 3) +
                    " CPU s per simulated s (" + sig(1 / big.turnedCost, 3) + "x real time, " +
                    sig(1e9 * big.turnedCost / evaluations, 3) + " ns per block per evaluation): faster than real " +
                    "time at that step needs " + sig(1e9 / evaluations, 3) + " ns, " + sig(big.turnedCost, 2) +
                    "x less.";
    }
    return filled("stability_beyond", v, ok);
}

std::string stability(const StabilityStudy& s, bool quick, bool& ok) {
    std::ostringstream checks, limits, tension, integrators, omegas;
    for (const StabilityCheck& c : s.checks)
        checks << "| " << c.what << " | " << sig(c.engine, 10) << " | " << sig(c.reference, 10) << " | "
               << sig(c.exact, 10) << " | " << sig(c.engine / c.exact - 1, 2) << " |\n";
    for (const StabilityRow& r : s.rows) {
        limits << "| " << r.blocks << " | " << sig(r.omegaMax, 5) << " | " << ms(r.rk4Limit) << " | "
               << ms(r.seededPass) << " / " << ms(r.seededFail) << " | " << ms(r.hangingPass) << " / "
               << ms(r.hangingFail) << " | " << ms(r.turnedPass) << " / " << ms(r.turnedFail) << " | "
               << sig(r.horizon, 3) << " s |\n";
        tension << "| " << r.blocks << " | " << sig(r.handTension, 4) << " | " << sig(r.peakTension, 4) << " | "
                << sig(r.peakTime, 3) << " s | " << ms(r.turnedPeakLimit) << " | " << ms(r.turnedPass) << " | "
                << sig(r.turnedCost, 3) << " |\n";
        integrators << "| " << r.blocks << " | unstable at any dt | " << ms(r.symplecticLimit) << " | "
                    << ms(r.rk4Limit) << " | " << ms(r.dopriLimit) << " | " << ms(r.dopriMeanStep) << " ("
                    << r.dopriRejected << " of " << r.dopriSteps << " steps rejected), " << sig(r.dopriCost, 3)
                    << (r.dopriFailure.empty() ? "" : "; " + r.dopriFailure) << " |\n";
        const double ref = std::sqrt(r.referenceOmega2);
        omegas << "| " << r.blocks << " | " << sig(r.omegaMax, 7) << " | " << r.engine.iterations << " | "
               << sig(r.engine.residual / r.engine.omega2, 2) << " | " << sig(ref, 7) << " | "
               << sig(r.omegaMax / ref - 1, 2) << " | " << sig(r.handUpper, 5) << " | " << sig(r.handAiry, 5) << " |\n";
    }
    // Where a turned-over run survived a step above the limit at rest (as
    // the hanging runs do, a few per cent over a short run).
    std::string above;
    for (const StabilityRow& r : s.rows)
        if (r.turnedPass > r.rk4Limit) above += (above.empty() ? "N = " : ", ") + std::to_string(r.blocks);
    return filled("stability",
                  {{"rk4_imaginary", sig(s.imaginaryRk4, 5)},
                   {"dopri_imaginary", sig(s.imaginaryDopri, 4)},
                   {"checks_rows", checks.str()},
                   {"limits_rows", limits.str()},
                   {"tension_rows", tension.str()},
                   {"above_rest",
                    above.empty() ? "" : ", or, like the hanging runs, a little above the one at rest (" + above + ")"},
                   {"integrator_rows", integrators.str()},
                   {"omega_rows", omegas.str()},
                   {"target", stabilityTarget(s, quick, ok)}},
                  ok);
}

// Merged pairs against welded ones: one line per case and integrator
// setting with the three models' cost and error side by side.
std::string models(const std::vector<BenchRow>& rows, bool quick, bool& ok) {
    std::ostringstream table_, tightList, runsTable;
    std::vector<BenchRow> runs, tight;
    for (const BenchRow& r : rows) (r.study.ends_with("_tight") ? tight : runs).push_back(r);
    double lowChain = INFINITY, highChain = 0, lowSparse = INFINITY, highSparse = 0;
    for (size_t i = 0; i + 2 < runs.size(); i += 3) {
        const BenchRow &chain = runs[i], &sparse = runs[i + 1], &weld = runs[i + 2];
        lowChain = std::min(lowChain, weld.cost / chain.cost);
        highChain = std::max(highChain, weld.cost / chain.cost);
        lowSparse = std::min(lowSparse, weld.cost / sparse.cost);
        highSparse = std::max(highSparse, weld.cost / sparse.cost);
        const std::string integrator = chain.method.substr(0, chain.method.find(','));
        auto unknowns = [](const BenchRow& r) { return r.note.substr(0, r.note.find(';')); };
        table_ << "| " << chain.study << " (" << chain.blocks << " blocks) | " << integrator << " "
               << num(chain.parameter) << " | " << num(chain.cost) << " | " << num(sparse.cost) << " | "
               << num(weld.cost) << " | " << num(weld.cost / chain.cost) << "x | " << num(weld.cost / sparse.cost)
               << "x | " << num(chain.error) << " | " << num(weld.error) << " | " << unknowns(chain) << " | "
               << unknowns(weld) << " |\n";
    }
    for (const BenchRow& t : tight)
        tightList << "- " << t.study.substr(0, t.study.size() - 6) << ": final block centres " << num(t.error)
                  << " m apart; " << t.note << ".\n";
    table(runsTable, runs, "step (s) / tolerance", "error (m)");
    return filled("models",
                  {{"quick_flag", quick ? " --quick" : ""},
                   {"rows", table_.str()},
                   {"chain_low", num(lowChain)},
                   {"chain_high", num(highChain)},
                   {"sparse_low", num(lowSparse)},
                   {"sparse_high", num(highSparse)},
                   {"tight", tightList.str()},
                   {"runs", runsTable.str()}},
                  ok);
}

// The cost of an event: per-event CPU across N, and the flatness target.
std::string eventCost(const std::vector<EventCostRow>& rows, bool quick, bool& ok) {
    const double from = rows.empty() ? 0.4 : rows.front().from, to = rows.empty() ? 0.6 : rows.front().to;
    std::ostringstream md, verdicts;
    struct Spread {
        double lo = INFINITY, hi = 0;
        int loN = 0, hiN = 0;
        void add(double x, int n) {
            if (!std::isfinite(x) || !(x > 0)) return;
            if (x < lo) lo = x, loN = n;
            if (x > hi) hi = x, hiN = n;
        }
    } window, direct;
    // A window whose steps cost less than as many plain steps (the events a
    // small share of it, the plain step measured a little slow) says nothing
    // about its events: it is left out of the spread, and said so.
    std::vector<int> belowNoise;
    for (const EventCostRow& r : rows) {
        const double eventCpu = r.runCpu - double(r.steps) * r.plainStepCpu;
        md << "| " << r.blocks << " | " << r.steps << " (" << ms(r.meanStep) << ") | " << r.events << " at "
           << r.instants << " (" << r.kinds << ") | " << sig(r.runCpu, 3) << " s (best of " << r.runRepetitions
           << (r.repeatable ? "" : "; the repetitions differ") << ") | " << cpuTime(r.plainStepCpu) << " ("
           << ms(r.plainStep) << ")" << (r.plainEvents ? " (with events!)" : "") << " / " << cpuTime(r.controlStepCpu)
           << (r.controlEvents ? " (with events!)" : "") << " | " << sig(eventCpu, 3) << " s ("
           << sig(100 * r.eventShare, 2) << " %) | **" << cpuTime(r.perEvent) << "**"
           << (r.perEvent > 0 ? "" : ": below the subtraction's noise") << " (" << cpuTime(r.perEventControl)
           << " against the turning step) | " << sig(r.perEvent / r.plainStepCpu, 3) << " | "
           << cpuTime(r.perEventInStep) << " in " << r.eventfulSteps << (r.eventfulSteps == 1 ? " step (" : " steps (")
           << sig(r.perEventInStep / r.plainStepCpu, 3) << " plain steps) |"
           << (r.failure.empty() ? "" : " " + r.failure) << "\n";
        if (r.events > 0) {
            window.add(r.perEvent, r.blocks);
            direct.add(r.perEventInStep, r.blocks);
            if (!(r.perEvent > 0)) belowNoise.push_back(r.blocks);
        }
    }
    auto verdict = [&](const char* what, const Spread& s) {
        if (!(s.hi > 0) || !std::isfinite(s.lo)) return;
        const double ratio = s.hi / s.lo;
        auto factor = [](double x) { return x >= 100 ? whole(x) : sig(x, 3); };
        verdicts << "- " << what << ": largest over smallest " << factor(ratio) << "x (N = " << s.hiN << ": "
                 << cpuTime(s.hi) << "; N = " << s.loN << ": " << cpuTime(s.lo) << ") — **"
                 << (ratio <= 2 ? "met" : "missed") << "**";
        if (ratio > 2) verdicts << ", by a factor of " << factor(ratio / 2);
        verdicts << ".\n";
    };
    verdict("CPU per event", window);
    for (int n : belowNoise)
        verdicts << "  (N = " << n << " left out: its window cost less than its steps would have as plain steps, "
                 << "so its cost per event is below the subtraction's noise.)\n";
    verdict("Directly, in the steps that record them", direct);
    return filled("events",
                  {{"from", sig(from, 3)},
                   {"to", sig(to, 3)},
                   {"quick_flag", quick ? " --quick" : ""},
                   {"rows", md.str()},
                   {"quick_note", quick ? " (quick run: N up to 1,000)" : ""},
                   {"verdicts", verdicts.str()}},
                  ok);
}

// The example that the targets name; its 1,000-block row is this name
// followed by " x 1,000 blocks".
constexpr const char* kLongExample = "long-ladder.yaml";

std::string exampleStep(const ExampleRow& r) {
    const std::string who = r.automaticStep ? "engine: " : "scene: ";
    std::string step;
    if (r.adaptive)
        step =
            "adaptive, tolerance " + sig(r.tolerance, 3) + ", mean " + ms(r.simulated / double(std::max(r.steps, 1LL)));
    else if (r.smallestStep == r.largestStep)
        step = who + ms(r.smallestStep);
    else
        step = who + ms(r.smallestStep) + " .. " + ms(r.largestStep);
    if (r.stepHalvings > 0) step += ", halved " + std::to_string(r.stepHalvings) + "x";
    return step + " (" + r.integrator + ")";
}

// A CPU budget for 3 s of simulated time, scaled to the time run (quick: 1 s).
void exampleBudget(std::ostream& md, const ExampleRow* r, const std::string& what, double cpuFor3s) {
    if (!r) {
        md << "- " << what << ": not measured.\n";
        return;
    }
    const double limit = cpuFor3s * r->asked / 3.0;
    const bool met = r->failure.empty() && r->simulated >= r->asked - 1e-9 && r->cpu <= limit;
    md << "- " << what << " for " << sig(r->asked, 3) << " s in at most " << sig(limit, 3) << " CPU s"
       << (r->asked < 3 ? " (" + sig(cpuFor3s, 3) + " CPU s for 3 s, scaled)" : std::string()) << ": " << sig(r->cpu, 3)
       << " CPU s — **" << (met ? "met" : "missed") << "**"
       << (r->failure.empty() ? "" : " (failed: " + r->failure + ")") << ".\n";
}

std::string examplesSection(const ExamplesStudy& s, bool quick, bool& ok) {
    const double horizon = quick ? 1.0 : 3.0;
    std::ostringstream md;
    const auto finish = [&] {
        return filled("examples",
                      {{"dir", s.dir.generic_string()},
                       {"horizon", sig(horizon, 1)},
                       {"long_note", quick ? "" : ", plus the long-ladder design with 1,000 blocks"},
                       {"quick_flag", quick ? " --quick" : ""},
                       {"quick_note", quick ? " **Quick run**: 1 s of simulated time instead of 3, and no 1,000-block "
                                              "row; the CPU budgets below are scaled to 1 s."
                                            : ""},
                       {"body", md.str()}},
                      ok);
    };
    if (!s.error.empty()) {
        md << "Not measured: " << s.error << ".\n\n";
        return finish();
    }
    md << "| scene | blocks | simulated s | CPU s | CPU s per simulated s | steps | step | hinge events | failure |\n"
       << "|---|---:|---:|---:|---:|---:|---|---:|---|\n";
    for (const ExampleRow& r : s.rows) {
        const double per = r.perSimulated();
        md << "| " << r.scene << " | " << r.blocks << " | " << sig(r.simulated, 3) << " | " << sig(r.cpu, 3) << " | "
           << sig(per, 3)
           << (r.simulated > 0 ? (per <= 1 ? " (faster than real time)" : " (slower than real time)") : "") << " | "
           << r.steps << " | " << exampleStep(r) << " | " << r.hingeEvents << " | " << r.failure << " |\n";
    }
    md << "\nTargets:\n\n";
    auto find = [&](const std::string& name) -> const ExampleRow* {
        for (const ExampleRow& r : s.rows)
            if (r.scene == name) return &r;
        return nullptr;
    };
    exampleBudget(md, find(kLongExample), std::string("`") + kLongExample + "`", 1.5);
    if (quick)
        md << "- The same design with 1,000 blocks for 3 s in at most 3 CPU s: not run in the quick form.\n";
    else
        exampleBudget(md, find(std::string(kLongExample) + " x 1,000 blocks"), "The same design with 1,000 blocks",
                      3.0);
    const ExampleRow* worst = nullptr;
    int slow = 0;
    for (const ExampleRow& r : s.rows) {
        if (r.scene.find(" x ") != std::string::npos) continue;  // the 1,000-block design is not an example
        if (!r.failure.empty() || r.simulated <= 0 || r.perSimulated() > 1) ++slow;
        if (!worst || r.perSimulated() > worst->perSimulated()) worst = &r;
    }
    md << "- Every example at most 1 CPU s per simulated second (it can play at 1x): the slowest is "
       << (worst ? worst->scene + " at " + sig(worst->perSimulated(), 3) : std::string("none")) << "; " << slow
       << " over or failed — **" << (slow == 0 && worst ? "met" : "missed") << "**.\n";
    return finish();
}

// The long ladders' targets: 0.5 s in real time at 100,000 and 10,000
// blocks and in 0.05 CPU s at 1,000, within 1e-6 m of the reference; at
// 100,000 blocks at the engine's defaults too; and the classic design with
// 10,000 blocks for 3 s at the defaults in 3 CPU s.
std::string longLadderTargets(const std::vector<BenchRow>& rows, const LongClassicRun& classic, bool quick) {
    std::ostringstream md;
    for (const BenchRow& l : rows)
        if (l.blocks == 100000 && l.method.find("engine's step") != std::string::npos)
            md << "- Long ladder, 100000 blocks turned over, 0.5 s at the engine's default settings (RK4 at the "
                  "engine's step) in at most 0.5 CPU s: **"
               << (l.finished && l.cost * 0.5 <= 0.5 ? "met" : "missed") << "**: " << num(l.cost * 0.5) << " CPU s ("
               << num(l.cost) << "x the budget), block-centre error " << num(l.error) << " m.\n";
    for (const auto& [blocks, budget] : {std::pair{100000, 0.5}, std::pair{10000, 0.5}, std::pair{1000, 0.05}}) {
        const BenchRow* best = nullptr;  // the cheapest run within 1e-6 m
        bool ran = false;
        for (const BenchRow& l : rows) {
            if (l.blocks != blocks) continue;
            ran = true;
            if (l.finished && l.error > 0 && l.error <= 1e-6 && (!best || l.cost < best->cost)) best = &l;
        }
        md << "- Long ladder, " << blocks << " blocks turned over, 0.5 s in at most " << num(budget)
           << " CPU s with a block-centre error at most 1e-6 m: ";
        if (!ran)
            md << "not run" << (quick ? " in --quick mode (1,000 blocks for 0.03 s only)" : "") << ".\n";
        else if (!best)
            md << "**missed**: no run reached 1e-6 m (see the long-ladder rows).\n";
        else
            md << "**" << (best->cost * 0.5 <= budget ? "met" : "missed") << "**: the cheapest run within 1e-6 m is "
               << best->method << " at " << num(best->parameter) << ", " << num(best->cost * 0.5) << " CPU s ("
               << num(best->cost * 0.5 / budget) << "x the budget)" << (quick ? "; quick run: 0.03 s only" : "")
               << ".\n";
    }
    md << "- The classic design with 10,000 blocks, 3 s at the default settings in at most 3 CPU s: ";
    if (classic.runs == 0)
        md << "not run" << (quick ? " in --quick mode" : "") << ".\n";
    else if (!(classic.cpu > 0))
        md << "**missed**: not built: " << classic.failure << ".\n";
    else
        md << "**"
           << (classic.failure.empty() && classic.simulated >= classic.asked && classic.cpu <= 3.0 ? "met" : "missed")
           << "**: " << num(classic.cpu) << " CPU s (" << num(classic.cpu / 3.0) << "x the budget), " << classic.steps
           << " steps.\n";
    return md.str();
}

// What the classic design with many blocks did, in words.
std::string longClassicText(const LongClassicRun& c) {
    if (c.runs == 0) return "not run in the quick form.";
    std::ostringstream md;
    if (!(c.cpu > 0)) return "not built: " + c.failure + ".";
    md << "simulated " << num(c.simulated) << " s of " << num(c.asked) << " in " << num(c.cpu) << " CPU s ("
       << num(c.simulated / c.cpu) << "x real time), " << c.steps << " steps and " << c.evaluations << " evaluations; "
       << c.rejected
       << " steps taken again because their end was near the edge of RK4's stability (docs/model.md section 6.3), "
       << c.halvings << " halvings of the step; the energy books " << num(std::abs(c.books)) << " J off at the end"
       << (c.failure.empty() ? "" : "; stopped: " + c.failure) << ".";
    return md.str();
}

// The section "A long ladder turned over", its rows and the classic run.
std::string longLadderSection(const std::vector<BenchRow>& rows, const LongClassicRun& classic, bool quick,
                              const std::string& charts, bool& ok) {
    std::ostringstream list;
    for (const BenchRow& l : rows) {
        list << "- " << l.blocks << " blocks, " << l.method;
        if (namesAdaptiveMethod(l.method))
            list << ", tolerance " << num(l.parameter);
        else if (l.parameter > 0)
            list << ", dt = " << num(l.parameter) << " s";
        list << ": " << l.note << "\n";
    }
    return filled("long_ladder",
                  {{"quick_flag", quick ? " --quick" : ""},
                   {"quick_note", quick ? " Quick form: 1,000 blocks for 0.03 s only." : ""},
                   {"charts", charts},
                   {"rows", list.str()},
                   {"classic", longClassicText(classic)}},
                  ok);
}

std::string targets(const BenchResults& r) {
    std::ostringstream md;
    // 1. N = 100: at every peer's cost, an error 100x below.
    if (auto it = r.chains.find(100); it != r.chains.end()) {
        int met = 0, total = 0;
        std::ostringstream detail;
        for (const BenchRow& p : it->second) {
            if (!isPeer(p)) continue;
            ++total;
            const double ours = bestErrorWithin(it->second, p.cost);
            const double ratio = p.finished ? p.error / ours : INFINITY;
            if (ratio >= 100) ++met;
            detail << "  - " << p.method << " h = " << num(p.parameter) << ": peer error " << num(p.error) << " m at "
                   << num(p.cost) << " s/s; ours at that cost " << num(ours) << " m (ratio " << num(ratio) << ")\n";
        }
        if (total == 0)
            md << "- Falling chain N = 100, error 100x below each peer at its cost: **not measured** (" << r.peers
               << ").\n";
        else
            md << "- Falling chain N = 100, error at least 100x below each peer at the peer's cost: **"
               << (met == total ? "met" : "missed") << "** (met in " << met << " of " << total << " peer runs).\n"
               << detail.str();
    }
    // 2. N = 1,000: 5x cheaper than Bullet Featherstone + RK4 at equal error.
    if (auto it = r.chains.find(1000); it != r.chains.end()) {
        int met = 0, total = 0;
        std::ostringstream detail;
        for (const BenchRow& p : it->second) {
            if (p.method != "bullet featherstone rk4") continue;
            ++total;
            const double ours = bestCostWithin(it->second, p.error);
            if (p.finished && p.cost / ours >= 5) ++met;
            detail << "  - h = " << num(p.parameter) << ": Bullet " << num(p.cost) << " s/s at error " << num(p.error)
                   << " m; ours " << num(ours) << " s/s at an error no larger (" << num(p.cost / ours)
                   << "x cheaper)\n";
        }
        if (total == 0)
            md << "- N = 1,000, 5x cheaper than Bullet Featherstone + RK4: **not measured** (" << r.peers << ").\n";
        else
            md << "- N = 1,000, at least 5x cheaper than Bullet Featherstone + RK4 at equal error: **"
               << (met == total ? "met" : "missed") << "** (met in " << met << " of " << total << " runs).\n"
               << detail.str();
    } else {
        md << "- N = 1,000 against Bullet: not run in --quick mode.\n";
    }
    // 3. Long ladders.
    md << longLadderTargets(r.longLadder, r.longClassic, r.quick);
    // 4. Flat cost per block-step.
    std::vector<std::string> methods;
    for (const BenchRow& s : r.scaling)
        if (std::find(methods.begin(), methods.end(), s.method) == methods.end()) methods.push_back(s.method);
    for (const std::string& m : methods) {
        double lo = INFINITY, hi = 0;
        int largest = 0;
        for (const BenchRow& s : r.scaling)
            if (s.method == m) {
                lo = std::min(lo, s.error);
                hi = std::max(hi, s.error);
                largest = std::max(largest, s.blocks);
            }
        md << "- Cost per block-step flat within 1.5x, " << m << ", N = 10 .. " << largest
           << ": max/min = " << num(hi / lo) << " — **" << (hi / lo <= 1.5 ? "met" : "missed") << "**"
           << (largest < 100000 ? " (quick run: not up to 100,000)" : "") << ".\n";
    }
    return md.str();
}

}  // namespace

bool writeReport(const BenchResults& r, const std::filesystem::path& plots, const std::filesystem::path& report) {
    const std::filesystem::path base = report.has_parent_path() ? report.parent_path() : ".";
    const std::string dir = std::filesystem::relative(plots, base).generic_string();
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    bool ok = true;
    std::ostringstream pendulum, chains, ladder, scaling;
    table(pendulum, r.pendulum, "step (s) / tolerance", "error");
    for (const auto& [n, rows] : r.chains) {
        chains << "## Falling chain, N = " << n << "\n\n![chain" << n << "](" << dir << "/chain" << n << ".svg)\n\n";
        table(chains, rows, "step (s) / tolerance", "error (m)");
    }
    table(ladder, r.ladder, "step (s) / tolerance", "error (m)");
    for (const BenchRow& s : r.scaling)
        scaling << "| " << s.method << " | " << s.blocks << " | " << s.note << " | " << num(s.error) << " | "
                << num(s.cost) << " |\n";
    const std::string text = filled("performance",
                                    {{"quick_flag", r.quick ? " --quick" : ""},
                                     {"out", plots.generic_string()},
                                     {"date", date},
                                     {"cpu", cpuModel()},
                                     {"cores", std::to_string(std::thread::hardware_concurrency())},
                                     {"compiler", __VERSION__},
                                     {"min_time", r.quick ? "5 ms" : "50 ms"},
                                     {"peers", r.peers},
                                     {"charts", dir},
                                     {"pendulum_table", pendulum.str()},
                                     {"chains", chains.str()},
                                     {"ladder_table", ladder.str()},
                                     {"scaling_rows", scaling.str()},
                                     {"long_ladder", longLadderSection(r.longLadder, r.longClassic, r.quick, dir, ok)},
                                     {"stability", stability(r.stability, r.quick, ok)},
                                     {"models", models(r.models, r.quick, ok)},
                                     {"events", eventCost(r.eventCost, r.quick, ok)},
                                     {"examples", examplesSection(r.examples, r.quick, ok)},
                                     {"contacts", contactsSection(r.contacts, r.quick, ok)},
                                     {"targets", targets(r)}},
                                    ok);
    return saveText(report, text) && ok;
}

bool writeModelsReport(const std::vector<BenchRow>& rows, bool quick, const std::filesystem::path& report) {
    bool ok = true;
    const std::string text = models(rows, quick, ok);
    return writeSection("models", quick, report, text, ok);
}

bool writeEventCostReport(const std::vector<EventCostRow>& rows, bool quick, const std::filesystem::path& report) {
    bool ok = true;
    const std::string text = eventCost(rows, quick, ok);
    return writeSection("events", quick, report, text, ok);
}

bool writeExamplesReport(const ExamplesStudy& s, bool quick, const std::filesystem::path& report) {
    bool ok = true;
    const std::string text = examplesSection(s, quick, ok);
    return writeSection("examples", quick, report, text, ok);
}

bool writeLongLadderReport(const std::vector<BenchRow>& rows, const LongClassicRun& classic, bool quick,
                           const std::filesystem::path& plots, const std::filesystem::path& report) {
    bool ok = true;
    const std::filesystem::path base = report.has_parent_path() ? report.parent_path() : ".";
    const std::string charts = std::filesystem::relative(plots, base).generic_string();
    const std::string text = longLadderSection(rows, classic, quick, charts, ok) +
                             "\nTargets (in the list of docs/model.md section 16.2's targets):\n\n" +
                             longLadderTargets(rows, classic, quick);
    return writeSection("long_ladder", quick, report, text, ok);
}

bool writeStabilityReport(const StabilityStudy& s, bool quick, const std::filesystem::path& report) {
    bool ok = true;
    const std::string text = stability(s, quick, ok);
    return writeSection("stability", quick, report, text, ok);
}

}  // namespace jl::bench
