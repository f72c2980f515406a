// A step's two ends, each evaluated once: the last step's end is this
// step's first stage when nothing has changed since, and the end's
// evaluation (the event functions need its pin forces) is kept for the
// next step. Evaluating either again gives the same numbers bit for bit and
// costs a whole pass over the ladder.
#include "jl/engine/motion.h"
#include "jl/sim/simulation.h"

#include <utility>

namespace jl {

// The last step's end, recalled as this step's start (null when the world
// has changed since: the step evaluates its start itself).
const Powers* Simulation::startAsLastEnd() {
    std::swap(keptStart_, keptEnd_);
    keptEnd_.forget();
    const Powers* atStart = keptStart_.recall(world_, dynamics_, t_);
    if (!atStart) keptStart_.forget();
    return atStart;
}

// The end of the step just taken (of length `taken`; the world holds it),
// evaluated for the ladder's event functions and kept as the next step's
// first stage: by the step itself if its last stage was the projected end
// (Dormand-Prince), unless a move of the hand starts or stops there: its
// stage saw the other side. Returns the smallest event function; `forces`
// gets the smallest of the contact-force ones.
double Simulation::eventFunctionsAtEnd(const MotionStep& m, double taken, double* forces) {
    // The corners to watch at the step's end: the same list at its start,
    // for the bracket.
    ladder_->blockContacts().refresh(world_, *ladder_);
    double fEnd = 0;
    if (m.step.endEvaluated && world_.pathsOnOnePiece(t_ + taken / 2, t_ + taken)) {
        lastPowers_ = m.step.endPowers;
        fEnd = eventFunctionsNow(forces);
    } else {
        fEnd = smallestEventFunction(t_ + taken, forces);
    }
    keptEnd_.keep(world_, dynamics_, t_ + taken, lastPowers_);
    return fEnd;
}

// The end of the step just taken (from t_, of length `taken`; the world
// holds it) evaluated as the step itself saw it, for the interpolant and the
// books between its ends. Where a move of the hand starts or stops, the
// hand's acceleration jumps: the step's own side of the jump is that of its
// stages, and the end's evaluation for the event functions and the next
// step (kept) is the other side.
Powers Simulation::stepEndAsTaken(double taken) {
    const double t1 = t_ + taken, mid = t_ + taken / 2;
    if (world_.pathsOnOnePiece(mid, t1))
        if (const Powers* kept = keptEnd_.recall(world_, dynamics_, t1)) return *kept;
    return dynamics_.evaluate(world_, t1, mid);
}

}  // namespace jl
