// Stepping a simulation: one step of the integrator, the check that the
// motion has not blown up, the ladder's events (located in
// simulation_events.cpp) resolved at their instant, and the frames of the
// grid read off the step.
#include "books_between.h"
#include "jl/base/short_number.h"
#include "jl/base/thread_clock.h"
#include "jl/engine/energy.h"
#include "jl/engine/motion.h"
#include "jl/engine/stable_step.h"
#include "jl/scene/scene_ranges.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>

namespace jl {

void Simulation::record(const Event& e) { pending_.push_back(e); }

// The frames of the grid strictly inside the step just taken (from t_, of
// length `taken`, not yet resolved: the world holds its end, in the same
// structure as its start), read off the quintic Hermite interpolant of the
// step; past the instants already emitted. Everything the step computes
// after this is put back as it was, so frames never change the run: the
// dynamics' last evaluation (its pin forces choose the next automatic step)
// and the accelerations. The energy books between the ends are cubic Hermite
// in time, from their values and rates (the powers) at both ends.
void Simulation::emitGridFrames(double taken) {
    if (!(grid_.every > 0)) return;
    const double t0 = t_, t1 = t_ + taken;
    const double eps = 1e-9 * grid_.every;
    const double after = std::max(t0, gridDoneUpTo_);
    double k = std::floor((after - grid_.origin) / grid_.every) + 1;
    if (grid_.at(k) <= after + eps) k += 1;
    if (!(grid_.at(k) < t1 - eps)) return;
    const Dynamics::Last dynamicsAtEnd = dynamics_.last();
    const Eigen::VectorXd q1 = world_.q, v1 = world_.v, a1saved = world_.a;
    const Ledger ledgerAtEnd = ledger_;
    // Both ends as the step evaluated them, when it did (not at a located
    // instant, which only the interpolant gave).
    const Powers p1 = stepEndAsTaken(taken);
    interpolant_.setEnd(world_.q, world_.v, world_.a);
    world_.q = stepStartQ_;
    world_.v = stepStartV_;
    const Powers* kept = keptStart_.recall(world_, dynamics_, t0);
    const Powers p0 = kept ? *kept : dynamics_.evaluate(world_, t0);
    interpolant_.setStart(taken, world_.q, world_.v, world_.a);
    for (; grid_.at(k) < t1 - eps; k += 1) {
        const double t = grid_.at(k);
        const double s = (t - t0) / taken;
        interpolant_.at(t - t0, world_.q, world_.v);
        world_.updateKinematics(t);
        ledger_ = ledgerBetween(stepStartLedger_, p0, ledgerAtEnd, p1, taken, s);
        // The events stay pending: they reach the caller in order, with the
        // frames at the ends of steps (takeEvents, frame).
        const double now = t_;
        std::vector<Event> pending = std::exchange(pending_, {});
        t_ = t;
        gridFrames_.push_back(frame());
        t_ = now;
        pending_ = std::move(pending);
        gridDoneUpTo_ = t;
    }
    world_.q = q1;
    world_.v = v1;
    world_.a = a1saved;
    ledger_ = ledgerAtEnd;
    dynamics_.restoreLast(dynamicsAtEnd);
}

// The scene's step, or the engine's: 1 ms at most, and within the stability
// limit of the fastest vibration the pin forces of the last evaluation allow.
void Simulation::noteStep(double h) {
    stats_.smallestStep = stats_.smallestStep > 0 ? std::min(stats_.smallestStep, h) : h;
    stats_.largestStep = std::max(stats_.largestStep, h);
}

namespace {
constexpr double kLargestAutomaticStep = 1e-3;  // s
}

// The fastest rate the automatic step must follow, in the world as it is and
// with the pin forces of the dynamics' last evaluation.
double Simulation::fastestRate() {
    // 16 x the fastest turn: a turn of at most 0.1 rad per RK4 step, where
    // RK4 loses (omega h)^6 / 72 = 1.4e-8 of a spin's energy per step
    // (docs/model.md section 6.3).
    // Springs carry the scene's energy in their vibration: resolved like a
    // turn, unless that asks for a step under the scene's floor of 1 us (then
    // the books' check stops the run and names the spring, section 12.4).
    const double springs = 16 * fastestSpringVibration(world_);
    const bool resolvable = automaticStep(scene_.solver.integrator, springs, kLargestAutomaticStep) >= 1e-6;
    KeptVibration& kept = keptVibration_;
    if (!kept.known || kept.forces != dynamics_.forcesGeneration() || kept.revision != world_.revision())
        kept = {true, dynamics_.forcesGeneration(), world_.revision(), fastestVibration(world_, dynamics_.pinForces())};
    return std::max({kept.omega, 16 * fastestTurn(world_), resolvable ? springs : 0.0});
}

double Simulation::fixedStep() {
    if (scene_.solver.step > 0) return scene_.solver.step;
    // After a step that stiffened past its length: the rate its end had.
    const double omega = std::max(fastestRate(), stiffenedRate_);
    const double h = stepScale_ * automaticStep(scene_.solver.integrator, omega, kLargestAutomaticStep);
    // The adaptive methods' first try only: their steps are their own.
    if (!isAdaptive(scene_.solver.integrator)) {
        stats_.automaticStep = true;
        noteStep(h);
    }
    return h;
}

// The automatic step is chosen by the stiffness at its start. Where a ladder
// pulls taut within a step (the hanging chain caught after a flip-flop let it
// fall), the pin forces rise a thousandfold in a millisecond, and a step that
// was stable at its start is not at its end: it loses energy that no impact
// took (a fifth of a joule for the 10,000-block classic, docs/model.md
// section 6.3). Such a step, one whose end asks for a rate near or past the
// edge of the method's stability interval, is taken again at the step its
// end allows. Only a step with no event in it: past an event its end is not
// a state the run keeps (a held contact pulls there, with a force of no
// meaning).
bool Simulation::retakeIfStiffened(const StepPlan& plan, double taken) {
    constexpr int kMostRetakes = 8;  // in a row; then the books' check watches
    if (scene_.solver.step > 0 || plan.adaptive) return false;
    // The last evaluation was of the step's end (or, with no events to read
    // there, its last stage, which RK4 takes at the end's time).
    const double rate = fastestRate();
    // 0.8 of the interval, not all of it: inside it but near its edge RK4
    // keeps only a quarter to a third of a vibration's energy per step
    // (omega h = 2.3 to 2.5). The 10,000-block classic's books at 2.5 s:
    // 0.139 J off with 1.0, 0.088 J with 0.8, 0.083 J with 0.7.
    constexpr double kEndLimit = 0.8;
    if (taken * rate <= kEndLimit * imaginaryStabilityLimit(scene_.solver.integrator) || retakes_ >= kMostRetakes)
        return false;
    restoreStepStart();
    world_.updateKinematics(t_);
    dynamics_.evaluate(world_, t_);
    keptEnd_.forget();
    stiffenedRate_ = std::max(stiffenedRate_, rate);
    ++retakes_;
    ++stats_.rejected;
    return true;
}

// A step that blew up with the engine's own step: back to its start, and
// every later step half as long (a tension the bound did not foresee, such
// as a block whipping round). The scene's own step is the user's choice:
// that fails with a diagnostic instead.
bool Simulation::retryWithSmallerStep() {
    constexpr int kMostHalvings = 10;
    // The adaptive integrator chooses its own steps (by its tolerance): a
    // shorter first try would change nothing.
    if (scene_.solver.step > 0 || isAdaptive(scene_.solver.integrator) || stats_.stepHalvings >= kMostHalvings)
        return false;
    restoreStepStart();
    world_.updateKinematics(t_);
    dynamics_.evaluate(world_, t_);
    stepScale_ *= 0.5;
    ++stats_.stepHalvings;
    // What the longer steps lost so far stays in the books (the frames show
    // it); from here the check watches whether the shorter ones run away,
    // else a whip's integration error, once past the threshold, would use up
    // every halving and blame something else.
    imbalanceBase_ = booksImbalance(energy(world_).total());
    return true;
}

namespace {

std::string gapText(double metres) { return shortNumber(metres) + " m"; }

}  // namespace

// One step, as its stages: chosen, taken from a start kept for a retry,
// checked for a blow-up and for books that run away, then (a ladder) its
// end read for events and settled; time moves on to its end and the inputs
// due there are applied.
bool Simulation::takeStep(double limit) {
    if (!failure_.empty()) return false;
    const StepPlan plan = planStep(limit);
    if (plan.h <= 0) return true;
    keepStepStart(plan.adaptive);
    const Powers* atStart = startAsLastEnd();
    MotionStep m = advanceAndProject(world_, dynamics_, stepper_, t_, plan.h, ledger_,
                                     scene_.solver.projectionTolerance, false, atStart);
    if (!m.ok()) return blownUp(m, plan.chosen);
    double taken = m.step.taken;
    stats_.rejected += m.step.rejected;
    if (plan.adaptive && (!plan.lands || taken < plan.h)) {
        stats_.adaptiveStep = true;
        noteStep(taken);
    }
    if (booksDiverged()) {
        if (retryWithSmallerStep()) return true;
        restoreStepStart();
        world_.updateKinematics(t_);
        fail("the energy no longer balances (the motion is running away): " + blowUpAdvice(plan.chosen));
        return false;
    }
    if (ladder_) {
        if (const std::optional<bool> ended = ladderAtStepEnd(m, taken, plan)) return *ended;
    } else if (stops_) {
        if (const std::optional<bool> ended = stopsAtStepEnd(m, taken, plan)) return *ended;
    } else {
        if (retakeIfStiffened(plan, taken)) return true;
        emitGridFrames(taken);
    }
    t_ = (plan.lands && taken == plan.h) ? plan.scheduled : t_ + taken;
    stiffenedRate_ = 0;
    retakes_ = 0;
    booksScale_ = std::max(booksScale_, energyFlowed(energy(world_)));
    ++stats_.steps;
    stats_.lastStep = taken;
    lastResidual_ = m.projection.residual;
    if (nextAction_ < scene_.script.size() && scene_.script[nextAction_].at <= t_ + 1e-12) keepBeforeChange();
    applyDueInputs();
    return stopOnLadderError(plan.start);
}

// The step to take from t_: the adaptive method's own next step, or the
// fixed or automatic one; shortened to land on the next scheduled instant
// (or `limit`) when it would reach it.
Simulation::StepPlan Simulation::planStep(double limit) {
    StepPlan plan;
    plan.adaptive = isAdaptive(scene_.solver.integrator);
    plan.h = plan.adaptive && stepper_.nextStep() > 0 ? stepper_.nextStep() : fixedStep();
    plan.chosen = plan.h;
    plan.scheduled = std::min(nextScheduledTime(), limit);
    plan.lands = t_ + plan.h >= plan.scheduled - 1e-12;
    if (plan.lands) plan.h = plan.scheduled - t_;
    plan.start = t_;
    plan.next0 = stepper_.nextStep();
    return plan;
}

// The state the step starts from, kept for going back to it (a retry, an
// event located inside the step, a stop).
void Simulation::keepStepStart(bool adaptive) {
    changeKept_ = false;
    wokeUnkept_ = false;
    stepStartQ_ = world_.q;
    stepStartV_ = world_.v;
    // The start's accelerations (the last evaluation, of this state), for
    // a limit passed and left within an adaptive step, or a stop within any.
    if ((adaptive && ladder_) || stops_) stepStartA_ = world_.a;
    stepStartLedger_ = ledger_;
}

// A step that produced no state to go on from: a shorter one is tried when
// the step is the engine's own, else the run fails saying why.
bool Simulation::blownUp(const MotionStep& m, double chosen) {
    if (retryWithSmallerStep()) return true;
    fail(m.step.finite
             ? "the projection onto the pins did not converge (gap " + gapText(m.projection.residual) + " after " +
                   std::to_string(m.projection.iterations) + " iterations): " + blowUpAdvice(chosen)
             : "the step produced a non-finite state: " + blowUpAdvice(chosen));
    return false;
}

// The ladder at the step's end: its event functions read there; an event
// located inside the step and settled, or a limit a free hinge swung past
// and back (the step taken again to end at the dip); then its angles and
// its still tail. The step's result when it ends here, else nullopt.
std::optional<bool> Simulation::ladderAtStepEnd(MotionStep& m, double& taken, const StepPlan& plan) {
    double forces = 0;
    const double fEnd = eventFunctionsAtEnd(m, taken, &forces);
    if (fEnd < 0) {
        if (!settleEvents(m, taken, fEnd, forces, plan)) return false;
    } else if (const double dip = plan.adaptive && taken > 100 * scene_.solver.eventTolerance ? limitDip(taken) : 0.0;
               dip > 0) {
        retakeToDip(dip);
        return true;
    } else if (retakeIfStiffened(plan, taken)) {
        return true;
    } else {
        emitGridFrames(taken);
        ladder_->blockContacts().forgetCleared(world_, *ladder_);
    }
    ladder_->updateAngles(world_);
    wakeTailIfReached(taken);
    return std::nullopt;
}

// An event function past its event at the step's end: the event located
// inside the step (when the scene asks), the frames of the grid up to it,
// and the ladder's events settled there. False when the run stops.
bool Simulation::settleEvents(MotionStep& m, double& taken, double fEnd, double forces, const StepPlan& plan) {
    const ThreadSecondsInto clock(timingEvents_ ? &eventSeconds_ : nullptr);
    const SolverSpec& solver = scene_.solver;
    if (solver.events == EventPolicy::Located && taken > solver.eventTolerance) {
        if (!locateEvent(taken, fEnd, forces)) return false;
        stepper_.setNextStep(plan.next0 > 0 ? plan.next0 : plan.chosen);
    }
    emitGridFrames(taken);
    keepBeforeChange();
    const double heldBefore = impactHeldWork_;
    auto settle = [&] { return ladder_->settle(world_, dynamics_, t_ + taken, &impactLoss_, &impactHeldWork_); };
    std::vector<Event> happened = settle();
    // An instant that asked for nothing after all (a function within
    // rounding of its threshold, a corner that grazes a face): the step is
    // taken again, and, where a corner of a block is past a face at its
    // end, what crosses after that instant is located in it. That corner
    // would otherwise be met only at the step's end, inside. A few times
    // over, then the whole step. Hinges alone are resolved at the step's
    // end, as in the paper's model.
    for (int again = 0; happened.empty() && taken < m.step.taken && again < kRelocations; ++again) {
        const double grazed = taken;
        retakeWhole(m, taken);
        double forcesAtEnd = 0;
        const double atEnd = eventFunctionsAtEnd(m, taken, &forcesAtEnd);
        const bool corner =
            std::any_of(eventValues_.begin() + hingeFunctions_, eventValues_.end(), [](double f) { return f < 0; });
        if (atEnd < 0 && corner && !locateEvent(taken, atEnd, forcesAtEnd, grazed)) return false;
        emitGridFrames(taken);
        happened = settle();
    }
    settleOrRetake(m, taken, std::move(happened), settle);
    if (!stopOnLadderError(plan.start)) return false;
    if (const auto why = squeezedByTheHand(heldBefore)) return stopAt(plan.start, *why);
    if (!world_.q.allFinite() || !world_.v.allFinite()) {
        restoreStepStart();
        fail("an impact produced a non-finite state");
        return false;
    }
    // The settled state is the next step's start, evaluated already.
    keptEnd_.keep(world_, dynamics_, t_ + taken, ladder_->settledPowers());
    return true;
}

// The events of the located instant settled (`happened`, by `settle` at
// t_ + taken) and recorded. When the instant asked for nothing after all (a
// function within rounding of its threshold), the whole step is taken
// instead and its end settled, so time can never stall on it.
void Simulation::settleOrRetake(MotionStep& m, double& taken, std::vector<Event> happened,
                                const std::function<std::vector<Event>()>& settle) {
    if (happened.empty() && taken < m.step.taken) {
        retakeWhole(m, taken);
        emitGridFrames(taken);
        happened = settle();
    }
    for (Event& e : happened) record(e);
}

// The step taken again from its start, whole.
void Simulation::retakeWhole(MotionStep& m, double& taken) {
    restoreStepStart();
    m = advanceAndProject(world_, dynamics_, stepper_, t_, m.step.taken, ledger_, scene_.solver.projectionTolerance,
                          true);
    taken = m.step.taken;
    ++stats_.spuriousEvents;
}

// A free hinge swung past a limit and back within this (long, adaptive)
// step: no sign change at its ends shows it. The step is taken again to end
// at the dip, where the crossing shows (docs/model.md section 9.1). Fixed
// steps are short enough.
void Simulation::retakeToDip(double dip) {
    restoreStepStart();
    world_.updateKinematics(t_);
    dynamics_.evaluate(world_, t_);
    stepper_.setNextStep(dip);
    ++stats_.rejected;
}

// The motion has come near the still tail: the next blocks move on their
// own. A change of structure: the end is evaluated anew, so that the next
// step starts from it and the automatic step is chosen from the pin forces
// of the pins there are now.
// A wake parts blocks that hang still from the tail's bodies: the structure
// changes, the state does not. Nothing is copied before it (a copy of the
// whole world at every wake was a third of the CPU time of a 100,000-block
// ladder turned over); a stop later in this step keeps the step's end
// instead of its start (stopAt).
void Simulation::wakeTailIfReached(double taken) {
    const bool kept = changeKept_;
    const int woke = ladder_->wakeIfReached(world_);
    if ((woke > 0 || !ladder_->error().empty()) && !kept) wokeUnkept_ = true;
    if (woke > 0) {
        lastPowers_ = dynamics_.evaluate(world_, t_ + taken);
        keptEnd_.keep(world_, dynamics_, t_ + taken, lastPowers_);
    }
}

double Simulation::limitDip(double taken) {
    Ladder::StepStart start{stepStartQ_, stepStartV_, stepStartA_};
    return ladder_->limitDip(world_, start, taken);
}

bool Simulation::stepOnce() { return takeStep(kOpenEnd); }

bool Simulation::advanceTo(double t) {
    const auto start = std::chrono::steady_clock::now();
    while (t_ < t && failure_.empty())
        if (!takeStep(kOpenEnd)) break;
    stats_.wallSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return failure_.empty();
}

bool Simulation::advanceToNextEvent(double limit) {
    const size_t before = pending_.size();
    while (t_ < limit && failure_.empty() && pending_.size() == before)
        if (!takeStep(kOpenEnd)) break;
    return pending_.size() > before;
}

}  // namespace jl
