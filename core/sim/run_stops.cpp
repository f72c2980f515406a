// Why a run stops, and what it says: the books running away (an unstable
// step), an impact that took without bound from the hand, an error of the
// ladder's; with the state kept as it was before the step that failed.
#include "jl/base/short_number.h"
#include "jl/engine/energy.h"
#include "jl/engine/stable_step.h"
#include "jl/scene/scene_ranges.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace jl {

// An unstable integrator makes energy from nothing long before a NaN or a
// failed projection shows it: compare E with E0 + work - losses, against the
// size of every term of the books.
bool Simulation::booksDiverged() const {
    // RK4 and Dormand-Prince keep the books to 1e-5 of this scale or better
    // wherever their step is stable (the heavy-middle example at 1 ms: 3e-5);
    // a thousandth is a motion running away. The Euler methods drift by O(h)
    // even when stable: for them only a twentieth is.
    const Integrator method = scene_.solver.integrator;
    const bool euler = method == Integrator::ExplicitEuler || method == Integrator::SymplecticEuler;
    const double kDivergence = euler ? 0.05 : 1e-3;
    const Energy e = energy(world_);
    const double scale = std::max(booksScale_, energyFlowed(e));
    return !(std::abs(booksImbalance(e.total()) - imbalanceBase_) <= kDivergence * scale);
}

// What "large" means for the books: the energy that has flowed, none of it
// measured from the arbitrary zero of the potential (a 10,000-block ladder
// has -5.8e5 J of it, which would hide any blow-up). Of the state now;
// booksDiverged takes the largest of the steps kept, since a chain that
// swings back up to where it started has as little potential energy to
// show as at the start: the falling chain's fell from 0.63 to 0.12 J at
// 2.66 s, the RK4 error it had gathered (1.8e-4 J) passed a thousandth of
// that, and the step was halved for a motion that was not running away.
double Simulation::energyFlowed(const Energy& e) const {
    const double held = ledger_.held + impactHeldWork_;
    return energyFloor_ + initialKinetic_ + std::abs(e.potential - initialPotential_) + std::abs(held) +
           std::abs(ledger_.user) + impactLoss_ + ledger_.damping + 1e-9;
}

// E - (E0 + W_held + W_user - D_impacts - D_damping), E = `total`: zero when the books balance.
double Simulation::booksImbalance(double total) const {
    return total - (initialEnergy_ + ledger_.held + impactHeldWork_ + ledger_.user - impactLoss_ - ledger_.damping);
}

void Simulation::fail(const std::string& why) { failure_ = "at t = " + std::to_string(t_) + " s: " + why; }

void Simulation::restoreStepStart() {
    world_.q = stepStartQ_;
    world_.v = stepStartV_;
    ledger_ = stepStartLedger_;
}

// A ladder error raised anywhere in the step (an event's settling, a script
// action, a grab or push taking up its contacts, a held contact let go, a
// wake of the still tail) stops the run in this step, and what is kept is
// the step's start: the structure from before the step's first change, the
// motion from before the step, and none of its frames or events
// (docs/model.md section 12.4). Nothing half-restructured is left to show.
bool Simulation::stopOnLadderError(double stepStart) {
    if (!ladder_ || ladder_->error().empty()) return true;
    return stopAt(stepStart, ladder_->error());
}

// An instant's impacts that took from the hand many times all the energy
// the run has otherwise seen: a held block driving blocks where they cannot
// go (into the floor, or against another held block through blocks the
// pins keep nearly straight). The ideal plastic impact's answer there is an
// impulse without bound, booked alike as the hand's work and as loss, so
// the books still balance and only its size tells (docs/model.md section
// 17.8: a 3-block ladder lowered onto a table, 0.29 J from the hand at one
// instant, and blocks of 20 g flung at metres a second).
std::optional<std::string> Simulation::squeezedByTheHand(double heldBefore) const {
    constexpr double kSqueeze = 3;
    const double took = impactHeldWork_ - heldBefore;
    const Energy e = energy(world_);
    const double seen = energyFloor_ + initialKinetic_ + std::abs(e.potential - initialPotential_) +
                        std::abs(ledger_.held) + std::abs(ledger_.user) + ledger_.damping + std::abs(heldBefore);
    if (!(std::abs(took) > kSqueeze * seen)) return std::nullopt;
    return "an impact took " + shortNumber(took) + " J from the hand, " + shortNumber(took / seen) +
           " times all the energy the run has otherwise seen (" + shortNumber(seen) +
           " J): a held block drives the blocks where they cannot go (into the floor, or against another held "
           "block); the state before the step is kept";
}

// Stops the run, `why`, with the state as it was at the step's start; or,
// when the still tail woke at the step's end with nothing kept before the
// wake, at the step's end (before whatever came after the wake), since the
// step's start has another structure.
bool Simulation::stopAt(double stepStart, std::string why) {
    const bool back = !wokeUnkept_;
    const double keep = back ? stepStart : t_;
    std::vector<Event> earlier;
    for (const Event& e : pending_)
        if (e.time <= keep) earlier.push_back(e);
    if (changeKept_) restore(*beforeChange_);  // the structure, the ladder's state, no error
    if (back) restoreStepStart();
    t_ = keep;
    world_.updateKinematics(t_);
    dynamics_.evaluate(world_, t_);
    keptStart_.forget();
    keptEnd_.forget();
    std::erase_if(gridFrames_, [&](const Frame& f) { return f.time > keep; });
    gridDoneUpTo_ = std::min(gridDoneUpTo_, keep);
    pending_ = std::move(earlier);
    fail(why);
    return false;
}

StiffMode Simulation::stiffestMode() const { return jl::stiffestMode(world_, dynamics_.pinForces()); }

namespace {

// Why a projection tolerance cannot be met where the bodies are: below the
// rounding of their coordinates (a few units in the last place of the
// largest), or "".
std::string roundingNote(const World& w, double tolerance) {
    double largest = 0;
    for (int b = 0; b < w.bodyCount(); ++b)
        if (w.body(b).alive) largest = std::max(largest, w.bodyPose(b).position.cwiseAbs().maxCoeff());
    const double rounding = 8 * std::numeric_limits<double>::epsilon() * largest;
    if (tolerance >= rounding) return {};
    return "the projection tolerance " + shortNumber(tolerance) + " m is below the rounding of coordinates near " +
           shortNumber(largest) + " m (about " + shortNumber(rounding) + " m): give a larger projection_tolerance";
}

}  // namespace

// What to try after a step blew up, from what sets the step: the stiffest
// mode of the motion (a stiff spring, heavy damping on a light body, a taut
// pin on a small inertia), which an explicit step must resolve and the
// linearly implicit rosenbrock_w need not. A user's step or tolerance may be
// too coarse; at their floors, or with the engine's own step halved ten
// times, the advice names the mode, and held blocks only in a scene that
// holds some.
std::string Simulation::blowUpAdvice(double h) const {
    if (std::string note = roundingNote(world_, scene_.solver.projectionTolerance); !note.empty()) return note;
    const SolverSpec& solver = scene_.solver;
    const StiffMode mode = stiffestMode();
    const bool unresolved = mode.rate * h > 1;  // more than a radian (or a decay time) per step
    const std::string stiff = "the stiffest mode is " + describe(mode);
    const std::string cope =
        solver.integrator == Integrator::RosenbrockW
            ? "; it is faster than the engine can follow: make the scene less stiff"
            : "; the linearly implicit rosenbrock_w is not held to a step under such a mode's time scale: try it";
    if (isAdaptive(solver.integrator)) {
        const std::string tolerance = "the adaptive integrator's tolerance " + shortNumber(solver.tolerance);
        if (solver.tolerance > range::tolerance.lo)
            return tolerance + " lets too much error through here; try a tighter tolerance" +
                   (unresolved ? " (" + stiff + ")" : "");
        return tolerance + " is at its floor and still lets too much error through: " + stiff + cope;
    }
    const std::string step = shortNumber(h) + " s";
    if (solver.step > 0 && solver.step > range::step.lo)
        return "the step " + step + " is too large for this integrator here (" +
               (unresolved ? stiff : "a fast vibration grows at every step") +
               "); try a smaller step, or leave the step to the engine, or the adaptive integrator";
    if (solver.step > 0) return "the step " + step + " is at its floor and still too large here: " + stiff + cope;
    std::string text =
        "it still does at a step of " + step + ", halved " + std::to_string(stats_.stepHalvings) + " times";
    if (unresolved) return text + ": " + stiff + cope;
    bool held = false;  // part 0 is the ground, held still, not a block
    for (PartId p = 1; p < PartId(world_.partCount()); ++p) held = held || world_.part(p).drive.has_value();
    return text + ", so the step is not the cause: it resolves the stiffest mode, " + describe(mode) + ". Look for " +
           (held ? "held blocks driven against each other or " : "") + "forces the bodies cannot follow";
}

}  // namespace jl
