#include "bench/report.h"

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

// What dominates the cost of an event, from a profile (not measured by the
// benchmark itself: profile again after changing event handling).
constexpr const char* kEventProfile =
    "**What dominates** (a profile taken when this table was added, not re-measured by the benchmark: "
    "`valgrind --tool=callgrind`, instructions executed, on the 1,000-block ladder of this table). The one step "
    "that records hinge 1's fold and flip at 0.480 s executes 28.4 million instructions, 5.4 plain steps' worth "
    "(a plain step just before it: 5.2 million); the step proper is 14 % of that. Locating the instant "
    "(`Simulation::locateEvent`) is 41 %: the step re-run twice from its start (29 %), three evaluations of the "
    "whole ladder for the force functions (8 %), the trials on the interpolant, angles only (3 %). "
    "`Ladder::resolve` is another 41 %: four evaluations of the whole world (11 %); `World::combine` for the fold "
    "and `World::separate` for the flip, 9 % each, nearly all of it `makeConsistent`, a position and velocity "
    "projection of the whole world that also rebuilds the list of pins; the impact's velocity projection over the "
    "whole world (3 %); `touchingLimit` over every hinge in every round (4 %). `Ladder::pullingContact` is below "
    "1 %, and this event needs no rule-6 trial. Counted by function, `Dynamics::evaluate` of the whole world takes "
    "52 % (20 evaluations; `PinSolver::assemble` 38 %). None of it is local to hinge 1: each part is a pass over "
    "all 1,000 blocks, which is why the step that records an event costs 2 to 3 plain steps per event at every N. "
    "The rest of the window's cost per event is not event handling at all: after the flip, block 1 swings fast, "
    "the position projection needs one more Newton iteration per step (twice the instructions in `pinGaps`), and "
    "every later step costs about 15 % more (6.0 against 5.2 million instructions). A cost per event flat in N "
    "needs the event's own work made local: evaluating and projecting only what the hinges involved touch.";

std::string num(double x) {
    if (!std::isfinite(x)) return "failed";
    char s[32];
    std::snprintf(s, sizeof s, "%.3g", x);
    return s;
}

bool isPeer(const BenchRow& r) {
    return r.method.find("mujoco") == 0 || r.method.find("box2d") == 0 || r.method.find("bullet") == 0;
}

std::string cpuModel() {
    std::ifstream f("/proc/cpuinfo");
    std::string line;
    while (std::getline(f, line))
        if (line.rfind("model name", 0) == 0) return line.substr(line.find(':') + 2);
    return "unknown CPU";
}

void table(std::ostream& md, const std::vector<BenchRow>& rows, const char* parameter, const char* error) {
    md << "| method | N | " << parameter << " | CPU s per simulated s | " << error << " | note |\n|---|---:|---:|---:|---:|---|\n";
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

std::string sig(double x, int digits) {
    if (!std::isfinite(x)) return "—";
    char s[32];
    std::snprintf(s, sizeof s, "%.*g", digits, x);
    return s;
}

std::string whole(double x) {
    char s[32];
    std::snprintf(s, sizeof s, "%.0f", x);
    return s;
}

std::string ms(double seconds) { return std::isfinite(seconds) ? sig(1e3 * seconds, 4) + " ms" : "—"; }

// A CPU time in us below 1 ms, else in ms, 3 digits.
std::string cpuTime(double seconds) {
    if (!std::isfinite(seconds)) return "—";
    return std::abs(seconds) < 1e-3 ? sig(1e6 * seconds, 3) + " us" : sig(1e3 * seconds, 3) + " ms";
}

// |R(i y)| of RK4 (and of every 4-stage 4th-order explicit Runge-Kutta method).
double rk4Growth(double y) { return std::sqrt(1 - std::pow(y, 6) / 72 + std::pow(y, 8) / 576); }

void stability(std::ostream& md, const StabilityStudy& s, bool quick) {
    md << "## Stability limit of long ladders\n\n"
       << "RK4 at dt = 1 ms blows up on a 10,000-block ladder because the physics is stiff, not because of a bug. "
       << "Each block hangs between two diagonally opposite corners, so it moves like a uniform rod of length "
       << "l = sqrt(L^2 + T^2) (61.2 mm for the default 60 x 12 mm blocks of 19.4 g). The links near the top carry "
       << "the weight of the whole ladder, a tension of about (N - 1.5) m g, and the fastest vibration is "
       << "neighbouring blocks rocking in opposite senses about their centres with that tension as the spring: "
       << "omega^2 = 12 T / (m l) for one link, so omega_max grows like sqrt(N). An explicit method is stable on an "
       << "undamped oscillation only while omega dt lies in its stability region on the imaginary axis: RK4 up to "
       << sig(s.imaginaryRk4, 5) << " (= 2 sqrt 2; every 4-stage 4th-order explicit Runge-Kutta method has the "
       << "same stability polynomial), symplectic Euler up to 2, Dormand-Prince 5(4) only up to "
       << sig(s.imaginaryDopri, 4) << " (beyond it weakly unstable: |R| - 1 = 1e-6 at 1, 0.03 at 2, 0.44 at 3; "
       << "its error control has to catch that), explicit Euler nowhere (each step multiplies the amplitude by "
       << "sqrt(1 + (omega dt)^2)).\n\n"
       << "**omega_max from the engine**: Lanczos iteration (mass inner product, fully reorthogonalised) on "
       << "K x = -(da/dq) x, with da/dq a central difference (largest displacement 1e-6 m or rad) of "
       << "`Dynamics::evaluate` about the hanging equilibrium that `Simulation::build` makes, applied to "
       << "displacements projected onto the pins' tangent space by the engine's velocity projection; stopped when "
       << "the Ritz residual bound is below 1e-9 omega^2. **Independently**, the reduced model of a hanging chain "
       << "of rods (sideways hinge positions as coordinates, M and K tridiagonal, the largest eigenvalue by "
       << "Sturm-sequence bisection, O(N)). Both against known answers first:\n\n"
       << "| case | engine omega^2 (rad/s)^2 | reduced model | exact | engine / exact - 1 |\n|---|---:|---:|---:|---:|\n";
    for (const StabilityCheck& c : s.checks)
        md << "| " << c.what << " | " << sig(c.engine, 10) << " | " << sig(c.reference, 10) << " | " << sig(c.exact, 10)
           << " | " << sig(c.engine / c.exact - 1, 2) << " |\n";
    md << "\n**Step limits of RK4**, predicted from omega_max and measured three ways by bisection over dt (each "
       << "trial a `Simulation::build` + `advanceTo`; each pair is the largest step that passed and the smallest "
       << "that did not). *Seeded*: the hanging ladder started with a small velocity (1e-4 at most) along its "
       << "fastest mode; it passes if that mode's amplitude sqrt(omega^2 a^2 + b^2) has not grown by the end (this "
       << "measures the linear limit itself). *Hanging* and *turned over*: the run reports no failure (turned over: "
       << "the top block turns half a turn in 0.3 s from t = 0, as in the long-ladder study). "
       << "Each run lasts max(0.1 s, 100 predicted steps).\n\n"
       << "| N | omega_max (rad/s) | predicted RK4 dt limit | measured, seeded mode (stays / grows) | measured, "
       << "hanging (runs / fails) | measured, turned over (runs / fails) | length of each run |\n"
       << "|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const StabilityRow& r : s.rows)
        md << "| " << r.blocks << " | " << sig(r.omegaMax, 5) << " | " << ms(r.rk4Limit) << " | " << ms(r.seededPass)
           << " / " << ms(r.seededFail) << " | " << ms(r.hangingPass) << " / " << ms(r.hangingFail) << " | "
           << ms(r.turnedPass) << " / " << ms(r.turnedFail) << " | " << sig(r.horizon, 3) << " s |\n";
    md << "\nThe seeded runs bracket the prediction within 0.1 %. A run without a seed only fails once the "
       << "rounding error in the fastest mode has grown to something the engine notices (a projection that does not "
       << "converge, or energy books that no longer balance), a growth of 1e15 or more, so over a short run it "
       << "survives a step a few per cent above the limit. Turning the top block pulls on the chain and lowers the "
       << "limit: the tension, and omega_max^2 with it, rises with the upward acceleration of hinge 1 (the hand's "
       << "path alone: (g + a_up) / g) and, later in a cascade, with the swing of each flipped block. The largest "
       << "pin force of an accurate run (Dormand-Prince 5(4), tolerance 1e-8, after every step) over its value at "
       << "rest, and the RK4 limit at that peak:\n\n"
       << "| N | hand's path: peak (g + a_up) / g | run: peak pin force / at rest | at t | RK4 limit at the peak | "
       << "measured, turned over (runs) | that run's CPU s per simulated s |\n|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const StabilityRow& r : s.rows)
        md << "| " << r.blocks << " | " << sig(r.handTension, 4) << " | " << sig(r.peakTension, 4) << " | "
           << sig(r.peakTime, 3) << " s | " << ms(r.turnedPeakLimit) << " | " << ms(r.turnedPass) << " | "
           << sig(r.turnedCost, 3) << " |\n";
    // Where a turned-over run survived a step above the limit at rest (as
    // the hanging runs do, a few per cent over a short run).
    std::string above;
    for (const StabilityRow& r : s.rows)
        if (r.turnedPass > r.rk4Limit) above += (above.empty() ? "N = " : ", ") + std::to_string(r.blocks);
    md << "\nA short peak lowers the limit less than a lasting one: the measured step lies between the limit at "
       << "the peak and the one at rest"
       << (above.empty() ? std::string()
                         : ", or, like the hanging runs, a little above the one at rest (" + above + ")")
       << ".\n\n"
       << "**The other integrators** (predicted from omega_max; Dormand-Prince also measured: its own steps on the "
       << "turned-over ladder at its default tolerance):\n\n"
       << "| N | explicit Euler | symplectic Euler 2 / omega | RK4 2 sqrt 2 / omega | Dormand-Prince 5(4) "
       << sig(s.imaginaryDopri, 4) << " / omega | Dormand-Prince 5(4), tol 1e-8: mean step (rejected), CPU s per "
       << "simulated s |\n|---:|---|---:|---:|---:|---|\n";
    for (const StabilityRow& r : s.rows)
        md << "| " << r.blocks << " | unstable at any dt | " << ms(r.symplecticLimit) << " | " << ms(r.rk4Limit) << " | "
           << ms(r.dopriLimit) << " | " << ms(r.dopriMeanStep) << " (" << r.dopriRejected << " of " << r.dopriSteps
           << " steps rejected), " << sig(r.dopriCost, 3) << (r.dopriFailure.empty() ? "" : "; " + r.dopriFailure)
           << " |\n";
    md << "\n**omega_max four ways** (rad/s): the engine, the reduced model, and two hand estimates: the most "
       << "loaded link alone, sqrt(12 (N - 1.5) g / l) (an upper bound: each link's pencil bounds the assembled "
       << "one), and the top-of-chain estimate derived below, sqrt((12 g / l)(n - a1 (3n/4)^(1/3))), n = N - 1, "
       << "a1 = 2.3381:\n\n"
       << "| N | engine | Lanczos steps | Ritz residual / omega^2 | reduced model | engine / model - 1 | "
       << "hand: most loaded link | hand: top of chain |\n|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const StabilityRow& r : s.rows) {
        const double ref = std::sqrt(r.referenceOmega2);
        md << "| " << r.blocks << " | " << sig(r.omegaMax, 7) << " | " << r.engine.iterations << " | "
           << sig(r.engine.residual / r.engine.omega2, 2) << " | " << sig(ref, 7) << " | " << sig(r.omegaMax / ref - 1, 2)
           << " | " << sig(r.handUpper, 5) << " | " << sig(r.handAiry, 5) << " |\n";
    }
    md << "\n*The top-of-chain estimate.* In the sideways positions y_j of the hinges, link j (tension T_j at its "
       << "centre) has kinetic energy (m/2)[((y'_j + y'_j+1)/2)^2 + (y'_j+1 - y'_j)^2/12] and potential energy "
       << "T_j (y_j+1 - y_j)^2 / (2 l) (exactly the linearised V = -sum T_j l cos(theta_j) of the hanging chain). "
       << "Under a uniform tension T a wave y_j ~ exp(i k j) has omega^2 = (4 T / l) sin^2(k/2) / "
       << "(m [cos^2(k/2) + sin^2(k/2)/3]), largest at k = pi, the zigzag in which blocks rock about fixed centres: "
       << "12 T / (m l). Near it, k = pi - kappa, omega^2 = (12 T / (m l))(1 - 3 kappa^2/4). Down the ladder the "
       << "tension falls, T(s) = (n - s) m g at s links below the held block's hinge, where the zigzag must vanish. "
       << "With kappa^2 -> -d^2/ds^2 this is an Airy problem, -(3n/4) u'' + s u = delta u, u(0) = 0, whose lowest "
       << "delta is a1 (3n/4)^(1/3): omega_max^2 = (12 g / l)(n - a1 (3n/4)^(1/3)). The fastest mode is a zigzag "
       << "confined to the top (3n/4)^(1/3) links or so (about 20 of 10,000).\n\n";
    if (s.rows.empty()) return;
    const StabilityRow& big = s.rows.back();
    const double y = big.omegaMax * 1e-3;
    md << "**The long-ladder target of docs/model.md section 16.2** (" << big.blocks << " blocks" << (quick ? ", the largest of this quick run" : "")
       << "): at dt = 1 ms, omega_max dt = " << sig(y, 3) << (y > s.imaginaryRk4 ? " > " : " <= ")
       << sig(s.imaginaryRk4, 4) << ", so ";
    if (y > s.imaginaryRk4) {
        const double yTurn = y * std::sqrt(big.peakTension);
        md << "**RK4 at dt = 1 ms is physically out of reach**: every step multiplies the fastest mode by "
           << sig(rk4Growth(y), 3) << ", and every explicit 4-stage 4th-order method (they all have RK4's stability "
           << "polynomial) fails the same way. RK4 is stable below " << ms(big.rk4Limit) << " on the hanging ladder "
           << "(seeded: stays at " << ms(big.seededPass) << ", grows at " << ms(big.seededFail) << "); turned over, "
           << "the pull of the turn raises the tension " << sig(big.peakTension, 3) << "x within " << sig(big.horizon, 2)
           << " s and the run survives " << ms(big.turnedPass) << " but fails at " << ms(big.turnedFail)
           << " (later in a cascade the swing of a flipped block can pull much harder: see the tension table above). More stages do not buy "
           << "speed: an explicit s-stage Runge-Kutta method is stable on the imaginary axis at most up to s - 1 "
           << "(Vichnevetsky 1983; Kinnmark & Gray 1984), so a method stable at 1 ms (omega_max dt = " << sig(y, 3)
           << ", " << sig(yTurn, 3) << " during the turn) needs at least " << int(std::ceil(y + 1)) << " ("
           << int(std::ceil(yTurn + 1)) << ") evaluations per step, " << whole(std::ceil(y + 1) * 1e3) << " ("
           << whole(std::ceil(yTurn + 1) * 1e3) << ") per simulated second, against RK4's "
           << whole(4 / big.rk4Limit) << " (" << whole(4 / big.turnedPass) << ") at its own limit.";
        if (std::isfinite(big.turnedCost)) {
            const double evaluations = 4 / big.turnedPass * big.blocks;  // block-evaluations per simulated second
            md << " At the largest step that ran, the turned-over ladder cost " << sig(big.turnedCost, 3)
               << " CPU s per simulated s (" << sig(1 / big.turnedCost, 3) << "x real time, "
               << sig(1e9 * big.turnedCost / evaluations, 3) << " ns per block per evaluation): faster than real time "
               << "at that step needs " << sig(1e9 / evaluations, 3) << " ns, " << sig(big.turnedCost, 2)
               << "x less.";
        }
    } else {
        md << "RK4 at dt = 1 ms is inside its stability region.";
        if (std::isfinite(big.turnedCost))
            md << " At the largest step that ran, the turned-over ladder cost " << sig(big.turnedCost, 3)
               << " CPU s per simulated s (" << sig(1 / big.turnedCost, 3) << "x real time).";
    }
    md << "\n\n";
}

// Merged pairs against welded ones: one line per case and integrator
// setting with the three models' cost and error side by side.
void models(std::ostream& md, const std::vector<BenchRow>& rows, bool quick) {
    md << "## Model only what a scene needs: locked pairs merged or welded\n\n"
       << "The same cascades run three ways (`solver.rigid_pairs` in a scene): a locked or folded pair **merged** into "
          "one body (the paper's combine: 3 unknowns fewer per pair and no constraint to keep), once on the O(N) chain "
          "solver and once on the sparse LDLT solver, and kept as two bodies **welded** by a pin and an angle row (3 "
          "constraint rows; only the sparse solver takes welds). The error is the largest block-centre distance at the "
          "end from one reference, the merged model with Dormand-Prince at tolerance 1e-12. Cost: CPU s per "
          "simulated s. Run alone with `jladder bench --only models" << (quick ? " --quick" : "") << "`.\n\n"
       << "| case | integrator | merged, chain: cost | merged, sparse: cost | welded, sparse: cost | welded / merged "
          "(chain) | welded / merged (sparse) | error merged | error welded | unknowns merged | unknowns welded |\n"
       << "|---|---|---:|---:|---:|---:|---:|---:|---:|---|---|\n";
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
        md << "| " << chain.study << " (" << chain.blocks << " blocks) | " << integrator << " " << num(chain.parameter)
           << " | " << num(chain.cost) << " | " << num(sparse.cost) << " | " << num(weld.cost) << " | "
           << num(weld.cost / chain.cost) << "x | " << num(weld.cost / sparse.cost) << "x | " << num(chain.error) << " | "
           << num(weld.error) << " | " << unknowns(chain) << " | " << unknowns(weld) << " |\n";
    }
    md << "\nMeasured: welding costs " << num(lowChain) << "x to " << num(highChain)
       << "x the merged model on the chain solver, and " << num(lowSparse) << "x to " << num(highSparse)
       << "x the merged model on the same sparse solver. The two models themselves, both at tolerance 1e-12:\n\n";
    for (const BenchRow& t : tight)
        md << "- " << t.study.substr(0, t.study.size() - 6) << ": final block centres " << num(t.error) << " m apart; "
           << t.note << ".\n";
    md << "\nEvery run, with the events it reproduces:\n\n";
    table(md, runs, "step (s) / tolerance", "error (m)");
}

// The cost of an event: per-event CPU across N, and the flatness target.
void eventCost(std::ostream& md, const std::vector<EventCostRow>& rows, bool quick) {
    const double from = rows.empty() ? 0.4 : rows.front().from, to = rows.empty() ? 0.6 : rows.front().to;
    md << "## Cost of an event\n\n"
       << "What a hinge event (lock, unlock, fold, unfold, flip-flop, bounce) costs on top of the steps around it, on "
          "ladders of N blocks of 60 x 3 mm (45 mm wide, density 600), block 0 held and turned half a turn "
          "counter-clockwise from t = 0.2 s over 0.3 s, with the default solver settings (RK4, the engine's automatic "
          "step, located events). **Definition**: the CPU time of the window "
       << sig(from, 3) << " .. " << sig(to, 3)
       << " s of that run, less the window's number of steps times the CPU time of one plain step, measured on the "
          "same ladder hanging at rest (no script, so no events) with the engine's step, divided by the number of "
          "hinge events recorded in the window. Each is timed again and again from a snapshot, in turn, and the "
          "fastest repetition counts. This counts everything the events add: the interpolant trials and step "
          "re-runs that locate an instant, `resolve` with its impacts and rule-6 trials, the following of held "
          "contacts and the trials that decide whether to let one go, located instants that come to nothing, and "
          "also what the events make the later steps cost (a block that has just flipped swings fast, and the "
          "projection needs more iterations). Extra steps are not counted (if the automatic step shrinks after an "
          "impact, those steps are charged as plain ones). **Directly**, the steps that record the events are "
          "also timed one by one: their CPU time less a plain step each, per event, leaves out the later steps and "
          "any trial in a step that records nothing. A fold that turns into a flip-flop at once is two events at "
          "one instant, located and resolved once. The CPU per step of the turned run over 0.2 .. "
       << sig(from, 3) << " s (turning, no events) is a second baseline: a plain step of the moving ladder costs "
          "what one at rest does to within a few per cent, and the cost per event against it shows how far the "
          "subtraction's noise moves the first measure (the events are a tenth of the window from 200 blocks up, so "
          "a 1 % error in a plain step moves the cost per event by 10 %); the direct measure has no such "
          "subtraction. Run alone with `jladder bench --only events" << (quick ? " --quick" : "") << "`.\n\n"
       << "| N | steps in the window (mean step) | events at instants (kinds) | CPU of the window | CPU per plain "
          "step: hanging (its step) / turning | events' CPU (share of the window) | **CPU per event** | per event, "
          "in plain steps | directly, in the steps that record them: per event |\n"
          "|---:|---:|---|---:|---:|---:|---:|---:|---:|\n";
    struct Spread {
        double lo = INFINITY, hi = 0;
        int loN = 0, hiN = 0;
        void add(double x, int n) {
            if (!std::isfinite(x) || !(x > 0)) return;
            if (x < lo) lo = x, loN = n;
            if (x > hi) hi = x, hiN = n;
        }
    } window, direct;
    for (const EventCostRow& r : rows) {
        const double eventCpu = r.runCpu - double(r.steps) * r.plainStepCpu;
        md << "| " << r.blocks << " | " << r.steps << " (" << ms(r.meanStep) << ") | " << r.events << " at "
           << r.instants << " (" << r.kinds << ") | " << sig(r.runCpu, 3) << " s (best of " << r.runRepetitions
           << (r.repeatable ? "" : "; the repetitions differ") << ") | " << cpuTime(r.plainStepCpu) << " ("
           << ms(r.plainStep) << ")" << (r.plainEvents ? " (with events!)" : "") << " / " << cpuTime(r.controlStepCpu)
           << (r.controlEvents ? " (with events!)" : "") << " | " << sig(eventCpu, 3) << " s ("
           << sig(100 * r.eventShare, 2) << " %) | **" << cpuTime(r.perEvent) << "** (" << cpuTime(r.perEventControl)
           << " against the turning step) | " << sig(r.perEvent / r.plainStepCpu, 3) << " | "
           << cpuTime(r.perEventInStep) << " in " << r.eventfulSteps << (r.eventfulSteps == 1 ? " step (" : " steps (")
           << sig(r.perEventInStep / r.plainStepCpu, 3) << " plain steps) |" << (r.failure.empty() ? "" : " " + r.failure)
           << "\n";
        if (r.events > 0) {
            window.add(r.perEvent, r.blocks);
            direct.add(r.perEventInStep, r.blocks);
        }
    }
    auto verdict = [&](const char* what, const Spread& s) {
        if (!(s.hi > 0) || !std::isfinite(s.lo)) return;
        const double ratio = s.hi / s.lo;
        auto factor = [](double x) { return x >= 100 ? whole(x) : sig(x, 3); };
        md << "- " << what << ": largest over smallest " << factor(ratio) << "x (N = " << s.hiN << ": "
           << cpuTime(s.hi) << "; N = " << s.loN << ": " << cpuTime(s.lo) << ") — **"
           << (ratio <= 2 ? "met" : "missed") << "**";
        if (ratio > 2) md << ", by a factor of " << factor(ratio / 2);
        md << ".\n";
    };
    md << "\nTarget: the cost of an event flat within 2x across N" << (quick ? " (quick run: N up to 1,000)" : "")
       << ".\n\n";
    verdict("CPU per event", window);
    verdict("Directly, in the steps that record them", direct);
    md << "\nThe columns in plain steps give the cost of an event over the cost of a plain step of the same ladder. "
          "Were event handling local to the hinges involved, they would fall as N grows; where they stay level or "
          "rise, an event costs a fixed number of whole-ladder passes or more, and so grows like N.\n\n"
       << kEventProfile << "\n\n";
}

// The example that the targets name; its 1,000-block row is this name
// followed by " x 1,000 blocks".
constexpr const char* kLongExample = "long-ladder.yaml";

std::string exampleStep(const ExampleRow& r) {
    const std::string who = r.automaticStep ? "engine: " : "scene: ";
    std::string step;
    if (r.adaptive)
        step = "adaptive, tolerance " + sig(r.tolerance, 3) + ", mean " +
               ms(r.simulated / double(std::max(r.steps, 1LL)));
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
       << (r->asked < 3 ? " (" + sig(cpuFor3s, 3) + " CPU s for 3 s, scaled)" : std::string()) << ": "
       << sig(r->cpu, 3) << " CPU s — **" << (met ? "met" : "missed") << "**"
       << (r->failure.empty() ? "" : " (failed: " + r->failure + ")") << ".\n";
}

void examplesSection(std::ostream& md, const ExamplesStudy& s, bool quick) {
    const double horizon = quick ? 1.0 : 3.0;
    md << "## Examples at default settings\n\n"
       << "Every scene of `" << s.dir.generic_string() << "` (read from `--examples DIR`, default `examples` "
       << "relative to the current directory: run from the source tree), loaded and run headless with "
       << "`jl::Simulation` at the scene's own settings for " << sig(horizon, 1)
       << " s of simulated time (the scene's duration if shorter)"
       << (quick ? "" : ", plus the long-ladder design with 1,000 blocks") << ". CPU is the thread's CPU time "
       << "(`CLOCK_THREAD_CPUTIME_ID`) of one run, building the scene included. The step: the scene's own, or "
       << "chosen by the engine (smallest .. largest it used; halvings after a step that blew up); Dormand-Prince "
       << "adapts its step to its tolerance (its mean step shown). Run alone with `jladder bench --only examples"
       << (quick ? " --quick" : "") << "`."
       << (quick ? " **Quick run**: 1 s of simulated time instead of 3, and no 1,000-block row; the CPU budgets "
                   "below are scaled to 1 s."
                 : "")
       << "\n\n";
    if (!s.error.empty()) {
        md << "Not measured: " << s.error << ".\n\n";
        return;
    }
    md << "| scene | blocks | simulated s | CPU s | CPU s per simulated s | steps | step | hinge events | failure |\n"
       << "|---|---:|---:|---:|---:|---:|---|---:|---|\n";
    for (const ExampleRow& r : s.rows) {
        const double per = r.perSimulated();
        md << "| " << r.scene << " | " << r.blocks << " | " << sig(r.simulated, 3) << " | " << sig(r.cpu, 3)
           << " | " << sig(per, 3)
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
       << " over or failed — **" << (slow == 0 && worst ? "met" : "missed") << "**.\n\n"
       << "The desktop program also draws every frame, so its real-time factor is measured separately (the status "
          "bar shows it).\n\n";
}

void targets(std::ostream& md, const BenchResults& r) {
    md << "## Targets of docs/model.md section 16.2, checked against the numbers above\n\n";
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
            detail << "  - " << p.method << " h = " << num(p.parameter) << ": peer error " << num(p.error)
                   << " m at " << num(p.cost) << " s/s; ours at that cost " << num(ours) << " m (ratio "
                   << num(ratio) << ")\n";
        }
        if (total == 0) md << "- Falling chain N = 100, error 100x below each peer at its cost: **not measured** (" << r.peers << ").\n";
        else
            md << "- Falling chain N = 100, error at least 100x below each peer at the peer's cost: **" << (met == total ? "met" : "missed")
               << "** (met in " << met << " of " << total << " peer runs).\n" << detail.str();
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
                   << " m; ours " << num(ours) << " s/s at an error no larger (" << num(p.cost / ours) << "x cheaper)\n";
        }
        if (total == 0) md << "- N = 1,000, 5x cheaper than Bullet Featherstone + RK4: **not measured** (" << r.peers << ").\n";
        else md << "- N = 1,000, at least 5x cheaper than Bullet Featherstone + RK4 at equal error: **" << (met == total ? "met" : "missed")
                << "** (met in " << met << " of " << total << " runs).\n" << detail.str();
    } else {
        md << "- N = 1,000 against Bullet: not run in --quick mode.\n";
    }
    // 3. A 10,000-block ladder faster than real time, RK4 at 1 ms.
    for (const BenchRow& l : r.longLadder) {
        md << "- Long ladder, " << l.blocks << " blocks, RK4 at dt = " << num(l.parameter) << " s: " << l.note << ". "
           << (l.blocks == 10000 && l.parameter == 1e-3
                   ? (l.finished && l.cost < 1 ? "**met**" : "**missed**")
                   : "");
        for (const StabilityRow& s : r.stability.rows)
            if (s.blocks == l.blocks && l.parameter > s.rk4Limit)
                md << " (beyond RK4's stability limit for " << s.blocks << " blocks, " << ms(s.rk4Limit)
                   << ": see \"Stability limit of long ladders\")";
        md << "\n";
    }
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
        md << "- Cost per block-step flat within 1.5x, " << m << ", N = 10 .. " << largest << ": max/min = " << num(hi / lo)
           << " — **" << (hi / lo <= 1.5 ? "met" : "missed") << "**" << (largest < 100000 ? " (quick run: not up to 100,000)" : "")
           << ".\n";
    }
    md << '\n';
}

}  // namespace

bool writeReport(const BenchResults& r, const std::filesystem::path& plots, const std::filesystem::path& report) {
    std::ofstream md(report);
    const std::filesystem::path base = report.has_parent_path() ? report.parent_path() : ".";
    const std::string dir = std::filesystem::relative(plots, base).generic_string();
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    md << "# Performance: speed against error\n\n"
       << "Generated by `jladder bench" << (r.quick ? " --quick" : "") << " --out " << plots.generic_string()
       << "` on " << date << ". Regenerate with `build/bin/jladder bench --out docs/bench` (full run; `--quick` for CI), "
       << "with the peers: configure with `-DJL_BENCH_PEERS=ON` after "
       << "`apt-get install libmujoco-dev libbox2d-dev libbullet-dev`.\n\n"
       << "Machine: " << cpuModel() << ", " << std::thread::hardware_concurrency()
       << " logical cores (shared with other jobs while measured), compiler " << __VERSION__
       << ", Release build. **Cost** is the CPU time of the one thread that simulates "
       << "(`CLOCK_THREAD_CPUTIME_ID`) per simulated second, so that other work on a shared machine does not count; "
       << "each configuration is repeated until it has run at least " << (r.quick ? "5 ms" : "50 ms") << ". "
       << "Peers: " << r.peers << ".\n\n"
       << "Errors: pendulum — distance from the start state after one exact period (angle in rad plus angular speed "
       << "scaled by the small-swing frequency; exact period from the complete elliptic integral). Falling chain — "
       << "the largest distance of a block centre from the reference at t = 0.5 s; the reference for N = 10 and 100 is "
       << "`core/reference_chain` (reduced coordinates, dense mass matrix, its own Dormand-Prince at tolerance 1e-12; "
       << "tests/test_reference_chain checks it against the elliptic period to 6e-13 rad, its energy to 1e-15 and the "
       << "engine to 1e-11 m); for N = 1,000 it is the engine with RK4 at dt = 20 us (not independent). Ladder — the "
       << "largest block-centre distance at t = 1.2 s from a Dormand-Prince run at tolerance 1e-12 with located events, "
       << "plus how many events happen in the reference order and their worst time error.\n\n";

    md << "## Physical pendulum\n\n![pendulum](" << dir << "/pendulum.svg)\n\n";
    table(md, r.pendulum, "step (s) / tolerance", "error");
    for (const auto& [n, rows] : r.chains) {
        md << "## Falling chain, N = " << n << "\n\n![chain" << n << "](" << dir << "/chain" << n << ".svg)\n\n";
        table(md, rows, "step (s) / tolerance", "error (m)");
    }
    md << "## Ladder cascade (6 blocks; the paper's way is explicit Euler with end-of-step events)\n\n![ladder](" << dir
       << "/ladder.svg)\n\n";
    table(md, r.ladder, "step (s) / tolerance", "error (m)");
    md << "## Scaling: cost per block-step\n\n![scaling](" << dir << "/scaling.svg)\n\n"
       << "| method | N | steps | ns per block-step | CPU s per simulated s |\n|---|---:|---:|---:|---:|\n";
    for (const BenchRow& s : r.scaling)
        md << "| " << s.method << " | " << s.blocks << " | " << s.note << " | " << num(s.error) << " | " << num(s.cost) << " |\n";
    md << "\n## A long ladder turned over (RK4, located events)\n\n";
    for (const BenchRow& l : r.longLadder)
        md << "- " << l.blocks << " blocks, dt = " << num(l.parameter) << " s: " << l.note << "\n";
    md << '\n';
    stability(md, r.stability, r.quick);
    models(md, r.models, r.quick);
    eventCost(md, r.eventCost, r.quick);
    examplesSection(md, r.examples, r.quick);
    targets(md, r);
    return bool(md);
}

// One section alone, as `jladder bench --only NAME` writes it.
template <class Section>
bool writeSection(const char* name, bool quick, const std::filesystem::path& report, const Section& section) {
    std::ofstream md(report);
    md << "<!-- Generated by `jladder bench --only " << name << (quick ? " --quick" : "") << "` on " << cpuModel()
       << ". -->\n\n";
    section(md);
    return bool(md);
}

bool writeModelsReport(const std::vector<BenchRow>& rows, bool quick, const std::filesystem::path& report) {
    return writeSection("models", quick, report, [&](std::ostream& md) { models(md, rows, quick); });
}

bool writeEventCostReport(const std::vector<EventCostRow>& rows, bool quick, const std::filesystem::path& report) {
    return writeSection("events", quick, report, [&](std::ostream& md) { eventCost(md, rows, quick); });
}

bool writeExamplesReport(const ExamplesStudy& s, bool quick, const std::filesystem::path& report) {
    return writeSection("examples", quick, report, [&](std::ostream& md) { examplesSection(md, s, quick); });
}

bool writeStabilityReport(const StabilityStudy& s, bool quick, const std::filesystem::path& report) {
    return writeSection("stability", quick, report, [&](std::ostream& md) { stability(md, s, quick); });
}

}  // namespace jl::bench
