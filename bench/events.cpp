#include "bench/events.h"

#include "jl/base/thread_clock.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

namespace jl::bench {

namespace {

// The ladder of the study: 60 x 3 x 45 mm blocks, density 600, block 0 held;
// turned: half a turn counter-clockwise from t = 0.2 s over 0.3 s. Default
// solver settings (RK4, the engine's automatic step, located events) on the
// full model: with the still tail (docs/model.md section 3.7) the hanging
// ladder would be a few bodies and its step next to nothing, and a plain
// step of the same ladder, which the study subtracts, would not be one.
Scene eventScene(int blocks, bool turned) {
    Scene s;
    s.solver.stillTail = StillTail::Separate;
    LadderSpec l;
    l.blocks = blocks;
    l.block.length = 0.06;
    l.block.thickness = 0.003;
    l.block.width = 0.045;
    l.block.density = 600;
    l.held = {0};
    s.ladder = l;
    if (turned) s.script.push_back(halfTurn(0.2));
    return s;
}

// The hinge events (the script's own entries left out) of the steps since
// the last call.
void collect(Simulation& sim, std::vector<Event>& into) {
    for (Event& e : sim.takeEvents())
        if (e.hinge > 0) into.push_back(std::move(e));
}

bool sameEvents(const std::vector<Event>& a, const std::vector<Event>& b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
        if (a[i].kind != b[i].kind || a[i].hinge != b[i].hinge || a[i].time != b[i].time) return false;
    return true;
}

std::string kindsOf(const std::vector<Event>& events) {
    std::map<std::string, int> count;
    for (const Event& e : events) ++count[toString(e.kind)];
    std::string s;
    for (const auto& [kind, n] : count) s += (s.empty() ? "" : ", ") + std::to_string(n) + " " + kind;
    return s.empty() ? "none" : s;
}

// A stretch of a run timed again and again from one snapshot: up to time
// `until`, or `count` steps. The fastest repetition counts. From the second
// repetition on, the steps that recorded events in the first are also
// timed one by one (each its fastest).
struct Stretch {
    Simulation* sim = nullptr;
    std::shared_ptr<const Snapshot> start;
    double until = 0;
    long long count = 0;  // > 0: this many steps instead
    double best = INFINITY, meanStep = 0;
    long long steps = 0;
    std::vector<Event> events;        // of the first repetition
    std::vector<long long> eventful;  // the steps (0-based) that recorded them
    std::vector<double> eventfulCpu;  // CPU s of each, the fastest repetition's
    int repetitions = 0;
    bool repeatable = true;
    std::string failure;

    double once() {
        if (repetitions > 0) sim->restore(*start);
        const double from = sim->time();
        std::vector<Event> these;
        long long n = 0;
        size_t next = 0;  // the next eventful step to time alone
        const double t0 = threadSeconds();
        while (count > 0 ? n < count : sim->time() < until) {
            const bool alone = repetitions > 0 && next < eventful.size() && eventful[next] == n;
            const double s0 = alone ? threadSeconds() : 0.0;
            const bool ok = sim->stepOnce();
            if (alone) {
                eventfulCpu[next] = std::min(eventfulCpu[next], threadSeconds() - s0);
                ++next;
            }
            if (!ok) break;
            const size_t before = these.size();
            collect(*sim, these);
            if (repetitions == 0 && these.size() > before) eventful.push_back(n);
            ++n;
        }
        const double cpu = threadSeconds() - t0;
        best = std::min(best, cpu);
        if (!sim->failure().empty() && failure.empty()) failure = sim->failure();
        if (repetitions == 0) {
            events = std::move(these);
            steps = n;
            meanStep = (sim->time() - from) / double(std::max<long long>(n, 1));
            eventfulCpu.assign(eventful.size(), INFINITY);
        } else if (n != steps || !sameEvents(these, events)) {
            repeatable = false;
        }
        ++repetitions;
        return cpu;
    }
    double perStep() const { return best / double(std::max<long long>(steps, 1)); }
};

}  // namespace

std::vector<EventCostRow> eventCostStudy(const BenchPlan& plan) {
    // The window: the end of the turn, where every ladder of the study has
    // its first events (hinge 1 folds and flips at once at 0.48 s from 200
    // blocks up; the 12-block ladder locks and unlocks lower hinges from
    // 0.41 s). The control: the turn before it, with no events.
    constexpr double kTurn = 0.2, kFrom = 0.4, kTo = 0.6;
    const std::vector<int> sizes =
        plan.quick ? std::vector<int>{12, 200, 1000} : std::vector<int>{12, 200, 1000, 10000};
    const int leastRepetitions = plan.quick ? 3 : 5;
    std::vector<EventCostRow> rows;
    for (int blocks : sizes) {
        const double setupStart = threadSeconds();
        EventCostRow row;
        row.blocks = blocks;
        row.from = kFrom;
        row.to = kTo;
        Simulation::Built turned = Simulation::build(eventScene(blocks, true));
        Simulation::Built hanging = Simulation::build(eventScene(blocks, false));
        if (!turned.simulation || !hanging.simulation) {
            row.failure = turned.errors.empty() ? (hanging.errors.empty() ? "not built" : hanging.errors.front())
                                                : turned.errors.front();
            rows.push_back(row);
            continue;
        }
        // The turned-over ladder, untimed up to the turn; the control and
        // the window each from its own snapshot; the hanging ladder after a
        // few steps that warm the caches, for as many steps as the window.
        // The three are timed in turn, repetition after repetition, so that
        // a change in the machine's load touches all three alike.
        Simulation& sim = *turned.simulation;
        sim.advanceTo(kTurn);
        sim.takeEvents();
        Stretch control, window, plain;
        control.sim = window.sim = &sim;
        control.start = sim.snapshot();
        control.until = kFrom;
        window.until = kTo;
        Simulation& rest = *hanging.simulation;
        for (int i = 0; i < 10; ++i) rest.stepOnce();
        rest.takeEvents();
        plain.sim = &rest;
        plain.start = rest.snapshot();
        double spent = 0;
        for (int rep = 0; rep < leastRepetitions || spent < plan.minSeconds; ++rep) {
            spent += control.once();
            if (!control.failure.empty()) break;
            if (rep == 0) {  // the control has left the run at the window's start
                sim.takeEvents();
                window.start = sim.snapshot();
            }
            spent += window.once();
            if (rep == 0) plain.count = std::max<long long>(window.steps, 1);
            spent += plain.once();
            if (!window.failure.empty() || !plain.failure.empty()) break;
        }
        row.failure = !control.failure.empty()  ? control.failure
                      : !window.failure.empty() ? window.failure
                      : !plain.failure.empty()  ? "hanging: " + plain.failure
                                                : "";
        row.steps = window.steps;
        row.meanStep = window.meanStep;
        row.runCpu = window.best;
        row.runRepetitions = window.repetitions;
        row.repeatable = control.repeatable && window.repeatable && plain.repeatable;
        const std::vector<Event>& first = window.events;
        row.events = int(first.size());
        for (size_t i = 0; i < first.size(); ++i)
            if (i == 0 || first[i].time != first[i - 1].time) ++row.instants;
        row.kinds = kindsOf(first);
        row.controlSteps = control.steps;
        row.controlEvents = int(control.events.size());
        row.controlRepetitions = control.repetitions;
        row.controlStep = control.meanStep;
        row.controlStepCpu = control.perStep();
        row.plainSteps = plain.steps;
        row.plainStep = plain.meanStep;
        row.plainEvents = int(plain.events.size());
        row.plainRepetitions = plain.repetitions;
        row.plainStepCpu = plain.perStep();
        row.eventfulSteps = int(window.eventful.size());
        row.eventfulCpu = 0;
        for (double c : window.eventfulCpu) row.eventfulCpu += c;

        const double eventCpu = row.runCpu - double(row.steps) * row.plainStepCpu;
        row.perEvent = row.events > 0 ? eventCpu / row.events : NAN;
        row.perEventControl = row.events > 0 ? (row.runCpu - double(row.steps) * row.controlStepCpu) / row.events : NAN;
        row.perInstant = row.instants > 0 ? eventCpu / row.instants : NAN;
        row.perEventInStep = row.events > 0 && window.repetitions > 1
                                 ? (row.eventfulCpu - row.eventfulSteps * row.plainStepCpu) / row.events
                                 : NAN;
        row.eventShare = row.runCpu > 0 ? eventCpu / row.runCpu : NAN;
        row.setupCpu = threadSeconds() - setupStart;
        std::fprintf(stderr,
                     "  events N=%-6d window %.2f..%.2f s: %lld steps (mean %.3e s), %d events at %d instants (%s), "
                     "%.4f CPU s (best of %d%s); hanging: %.3e s step, %.3e CPU s per step (best of %d, %lld steps%s) "
                     "-> %.3e CPU s per event (%.0f%% of the window); turning, %.2f..%.2f s: %lld steps, %d events, "
                     "%.3e CPU s per step -> %.3e CPU s per event; in the %d steps that record events: %.3e CPU s per "
                     "event%s%s\n",
                     blocks, row.from, row.to, row.steps, row.meanStep, row.events, row.instants, row.kinds.c_str(),
                     row.runCpu, row.runRepetitions, row.repeatable ? "" : ", repetitions differ", row.plainStep,
                     row.plainStepCpu, row.plainRepetitions, row.plainSteps, row.plainEvents ? ", with events!" : "",
                     row.perEvent, 100 * row.eventShare, kTurn, kFrom, row.controlSteps, row.controlEvents,
                     row.controlStepCpu, row.perEventControl, row.eventfulSteps, row.perEventInStep,
                     row.failure.empty() ? "" : "; ", row.failure.c_str());
        rows.push_back(row);
    }
    return rows;
}

}  // namespace jl::bench
