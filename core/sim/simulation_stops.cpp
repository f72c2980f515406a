// The stops of a general scene's pins at a step's end: their event
// functions read there, the first crossing located on the step's
// interpolant, and their events settled (docs/model.md section 18). The
// same flow as the ladder's (simulation_step.cpp, simulation_events.cpp),
// on a handful of stops: no still tail, no block contacts.
#include "books_between.h"
#include "jl/base/thread_clock.h"
#include "jl/engine/motion.h"
#include "jl/sim/event_bracket.h"
#include "jl/sim/simulation.h"

#include <algorithm>

namespace jl {

// The smallest of the stops' functions that had crossed at the step's end
// (crossed_), in the state the world holds at time t; `forces`: a closed
// stop is among them, and its push needs the dynamics.
double Simulation::stopFunctionsAmong(double t, bool forces) {
    world_.updateKinematics(t);
    if (forces) lastPowers_ = dynamics_.evaluate(world_, t);
    stops_->eventFunctions(world_, dynamics_, eventValues_);
    double f = 1.0;
    for (int k : crossed_) f = std::min(f, eventValues_[size_t(k)]);
    return f;
}

// The first instant inside the step just taken at which a stop's function
// turns negative, to within the event tolerance, on the step's quintic
// Hermite interpolant (as Simulation::locateEvent); leaves the world there,
// the books interpolated, and `taken` set to it.
void Simulation::locateStop(double& taken) {
    const ThreadSecondsInto clock(timingEvents_ ? &locatingSeconds_ : nullptr);
    crossed_.clear();
    bool forces = false;
    double fEnd = 1.0;
    for (int k = 0; k < int(eventValues_.size()); ++k)
        if (eventValues_[size_t(k)] < 0) {
            crossed_.push_back(k);
            forces = forces || !stops_->positional(k);
            fEnd = std::min(fEnd, eventValues_[size_t(k)]);
        }
    const Powers p1 = stepEndAsTaken(taken);
    const Ledger ledgerAtEnd = ledger_;
    interpolant_.setEnd(world_.q, world_.v, world_.a);
    restoreStepStart();
    const Powers* kept = keptStart_.recall(world_, dynamics_, t_);
    const Powers p0 = kept ? *kept : dynamics_.evaluate(world_, t_);
    interpolant_.setStart(taken, stepStartQ_, stepStartV_, world_.a);
    EventBracket b{0, stopFunctionsAmong(t_, false), taken, fEnd};
    narrow(b, scene_.solver.eventTolerance, [&](double h) {
        interpolant_.at(h, world_.q, world_.v);
        return stopFunctionsAmong(t_ + h, forces);
    });
    interpolant_.at(b.hi, world_.q, world_.v);
    world_.updateKinematics(t_ + b.hi);
    ledger_ = ledgerBetween(stepStartLedger_, p0, ledgerAtEnd, p1, taken, b.hi / taken);
    taken = b.hi;
}

// The stops at the end of the step just taken. A free stop that swung past
// a limit and back within the step shows no sign change at its ends
// (docs/model.md section 9.1): an adaptive step is then taken again to end
// at the dip, as a ladder's is, and a fixed one too, once (a stop's range
// can be a degree or two, which a step of 1 ms swings through and back; a
// fixed step cannot be shortened for the next try). That holds also when
// another stop's function has crossed: the dip may come first. Then
// nothing when no function has crossed; else the event located (when the
// scene asks) and settled. The step's result when it ends here, else
// nullopt.
std::optional<bool> Simulation::stopsAtStepEnd(MotionStep& m, double& taken, const StepPlan& plan) {
    // The end evaluated (a closed stop's push needs its accelerations, and so
    // does the search for a dip; the next step starts from this evaluation),
    // and the stops' functions read there. True when one has crossed.
    const auto functionsAtEnd = [&] {
        lastPowers_ = m.step.endEvaluated && world_.pathsOnOnePiece(t_ + taken / 2, t_ + taken)
                          ? m.step.endPowers
                          : dynamics_.evaluate(world_, t_ + taken);
        keptEnd_.keep(world_, dynamics_, t_ + taken, lastPowers_);
        stops_->eventFunctions(world_, dynamics_, eventValues_);
        return !std::all_of(eventValues_.begin(), eventValues_.end(), [](double f) { return f >= 0; });
    };
    bool crossed = functionsAtEnd();
    if (taken > 100 * scene_.solver.eventTolerance)
        if (const double dip = stops_->limitDip(world_, stepStartQ_, stepStartV_, stepStartA_, taken); dip > 0) {
            if (plan.adaptive) {
                retakeToDip(dip);
                return true;
            }
            restoreStepStart();
            m = advanceAndProject(world_, dynamics_, stepper_, t_, dip, ledger_, scene_.solver.projectionTolerance,
                                  true);
            if (!m.ok()) return blownUp(m, plan.chosen);
            taken = m.step.taken;
            crossed = functionsAtEnd();
        }
    if (!crossed) {
        if (retakeIfStiffened(plan, taken)) return true;
        emitGridFrames(taken);
        stops_->track(world_);
        return std::nullopt;
    }
    const ThreadSecondsInto clock(timingEvents_ ? &eventSeconds_ : nullptr);
    const SolverSpec& solver = scene_.solver;
    if (solver.events == EventPolicy::Located && taken > solver.eventTolerance) {
        locateStop(taken);
        stepper_.setNextStep(plan.next0 > 0 ? plan.next0 : plan.chosen);
    }
    if (!world_.q.allFinite() || !world_.v.allFinite()) {
        restoreStepStart();
        fail("an event could not be located: the step's interpolant is not finite");
        return false;
    }
    emitGridFrames(taken);
    keepBeforeChange();
    auto settle = [&] { return stops_->settle(world_, dynamics_, t_ + taken, &impactLoss_, &impactHeldWork_); };
    settleOrRetake(m, taken, settle(), settle);
    if (!stops_->error().empty()) return stopAt(plan.start, stops_->error());
    if (!world_.q.allFinite() || !world_.v.allFinite()) {
        restoreStepStart();
        fail("an impact produced a non-finite state");
        return false;
    }
    keptEnd_.keep(world_, dynamics_, t_ + taken, stops_->settledPowers());
    stops_->track(world_);
    return std::nullopt;
}

}  // namespace jl
