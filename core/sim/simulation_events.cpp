// The ladder's events inside a step: the event functions (the hinges', then
// the block contacts'), and the first instant one of them crosses, located
// on the step's interpolant.
#include "books_between.h"
#include "jl/base/thread_clock.h"
#include "jl/sim/event_bracket.h"
#include "jl/sim/simulation.h"

#include <algorithm>
#include <vector>

namespace jl {

// The smallest event function in the state the world holds, at time t (an
// event function is negative when its event has happened); `forces` gets
// the smallest of the contact-force ones.
double Simulation::smallestEventFunction(double t, double* forces) {
    lastPowers_ = dynamics_.evaluate(world_, t);
    return eventFunctionsNow(forces);
}

// The same in the state the world and the dynamics hold, evaluated already.
//
// The contacts between blocks add their functions after the hinges'; one
// counts only once it has crossed (negative), or, while an event is
// located, if it had crossed at the step's end: a corner near a face with
// nothing happening leaves the bracket and its narrowing exactly as they
// are without contact (docs/model.md section 17.4).
double Simulation::eventFunctionsNow(double* forces) {
    double f = ladder_->eventFunctions(world_, dynamics_, eventValues_);
    hingeForces_ = f;
    hingeFunctions_ = int(eventValues_.size());
    double smallest = 1.0;
    for (int k = 0; k < hingeFunctions_; ++k)
        if (!passed(k)) smallest = std::min(smallest, eventValues_[size_t(k)]);
    const BlockContacts& contacts = ladder_->blockContacts();
    contacts.eventFunctions(world_, dynamics_, *ladder_, eventValues_);
    for (int k = hingeFunctions_; k < int(eventValues_.size()); ++k) {
        const double value = eventValues_[size_t(k)];
        const bool counts =
            locating_ ? std::find(crossed_.begin(), crossed_.end(), k) != crossed_.end() && !passed(k) : value < 0;
        if (!counts) continue;
        smallest = std::min(smallest, value);
        if (!contacts.positional(k - hingeFunctions_)) f = std::min(f, value);
    }
    if (forces) *forces = f;
    return smallest;
}

// The first instant inside the step just taken (length `taken`, event
// function fEnd < 0 at its end) at which an event function turns negative,
// to within the event tolerance; leaves the world there and `taken` set to it.
//
// Narrowed on the step's quintic Hermite interpolant, at one evaluation per
// trial instead of a whole step; when no contact force pulls at either end,
// the event is a hinge reaching a limit, which positions alone tell, and a
// trial needs no dynamics at all. The state at the instant is the
// interpolant's too: its error is O(h^6), below the local error of every
// integrator the engine has (RK4's and Dormand-Prince's are O(h^5)), so
// re-running the step to the instant would cost a whole step of the ladder
// and buy nothing. The books go with it, cubic Hermite in time.
//
// A trial of the angles alone reads the functions that are past their event
// at the end, and only the angles of their bodies: a hinge that crosses and
// crosses back inside one step is not seen in any case (the step's ends
// bracket the first crossing of the smallest function), so the others add
// nothing, and the trial costs the same on a ladder of 10 or 10,000 blocks.
//
// From an instant `from` into the step that settled nothing (settleEvents),
// the narrowing starts there, and the functions past their event there are
// left out: they were looked at and asked for nothing.
bool Simulation::locateEvent(double& taken, double fEnd, double forcesAtEnd, double from) {
    (void)fEnd;
    (void)forcesAtEnd;
    const ThreadSecondsInto clock(timingEvents_ ? &locatingSeconds_ : nullptr);
    // The functions already past their event at the end (eventValues_
    // holds the end's): a trial needs only these and their bodies' poses.
    // The hinges' first, exactly as without contact between blocks; then,
    // if a corner of a block had crossed a face by the end, whether it did
    // so before the hinges' instant (docs/model.md section 17.4).
    std::vector<int> hingesCrossed, contactsCrossed;
    double hingesEnd = 1.0, contactsEnd = 1.0;
    for (size_t k = 0; k < eventValues_.size(); ++k)
        if (eventValues_[k] < 0) {
            const bool hinge = int(k) < hingeFunctions_;
            (hinge ? hingesCrossed : contactsCrossed).push_back(int(k));
            (hinge ? hingesEnd : contactsEnd) = std::min(hinge ? hingesEnd : contactsEnd, eventValues_[k]);
        }
    // The hinges' own smallest function at the end is their smallest crossed
    // one; their force functions' smallest is kept by eventFunctionsNow.
    const double hingeForcesAtEnd = hingeForces_;
    const Powers p1 = world_.pathsOnOnePiece(t_ + taken / 2, t_ + taken) ? lastPowers_ : stepEndAsTaken(taken);
    locating_ = true;
    ladder_->blockContacts().setLocating(true);
    crossed_ = contactsCrossed;
    const Ledger ledgerAtEnd = ledger_;
    interpolant_.setEnd(world_.q, world_.v, world_.a);
    Eigen::VectorXd qEnd, vEnd;
    if (hingesCrossed.empty() || from > 0) qEnd = world_.q, vEnd = world_.v;
    restoreStepStart();
    eventFunctionsAtStart();
    // A corner inside a face by more than the touch band at the step's
    // start already (one the pins held there, too little of its push
    // moving anything to be a contact) did not cross in this step: the
    // narrowing would find the start, the instant there would settle
    // nothing, and the step taken whole again would meet anything else that
    // crossed in it only at its end, inside. The end settles such corners.
    const double band = BlockContacts::touchBand(*ladder_);
    std::erase_if(contactsCrossed, [&](int k) {
        return ladder_->blockContacts().positional(k - hingeFunctions_) && eventValues_[size_t(k)] < -band;
    });
    crossed_ = contactsCrossed;
    const Powers p0 = lastPowers_;
    interpolant_.setStart(taken, stepStartQ_, stepStartV_, world_.a);
    if (from > 0) passFrom(from, hingesCrossed, contactsCrossed);
    if (hingesCrossed.empty() && contactsCrossed.empty()) {
        passed_.clear();
        locating_ = false;
        ladder_->blockContacts().setLocating(false);
        world_.q = qEnd;
        world_.v = vEnd;
        world_.updateKinematics(t_ + taken);
        smallestEventFunction(t_ + taken, nullptr);
        ledger_ = ledgerAtEnd;
        return true;
    }
    double hingesStart = 1.0;
    for (int k = 0; k < hingeFunctions_; ++k)
        if (!passed(k)) hingesStart = std::min(hingesStart, eventValues_[size_t(k)]);
    const double hingeForcesAtStart = hingeForces_;
    double contactsStart = 1.0;
    bool contactForces = false;
    for (int k : contactsCrossed) {
        contactsStart = std::min(contactsStart, eventValues_[size_t(k)]);
        contactForces = contactForces || !ladder_->blockContacts().positional(k - hingeFunctions_);
    }

    EventBracket b{from, 0, taken, 0};
    if (!hingesCrossed.empty())
        b = narrowAmong(hingesCrossed, hingeForcesAtStart >= 0 && hingeForcesAtEnd >= 0,
                        EventBracket{from, hingesStart, taken, hingesEnd});
    if (!contactsCrossed.empty())
        b = narrowContacts(contactsCrossed, !hingesCrossed.empty(), !contactForces, from, contactsStart, contactsEnd,
                           b);
    passed_.clear();
    locating_ = false;
    ladder_->blockContacts().setLocating(false);
    interpolant_.at(b.hi, world_.q, world_.v);
    world_.updateKinematics(t_ + b.hi);
    if (!world_.q.allFinite() || !world_.v.allFinite()) {
        restoreStepStart();
        fail("an event could not be located: the step's interpolant is not finite");
        return false;
    }
    ledger_ = ledgerBetween(stepStartLedger_, p0, ledgerAtEnd, p1, taken, b.hi / taken);
    taken = b.hi;
    return true;
}

// The functions at `from` into the step, read on the interpolant: those
// past their event there are passed_ and dropped from the crossed ones; the
// rest start the narrowing there, with their values at `from` (in
// eventValues_, hingeForces_).
void Simulation::passFrom(double from, std::vector<int>& hinges, std::vector<int>& contacts) {
    interpolant_.at(from, world_.q, world_.v);
    world_.updateKinematics(t_ + from);
    passed_.clear();
    crossed_.clear();
    smallestEventFunction(t_ + from, nullptr);
    for (size_t k = 0; k < eventValues_.size(); ++k)
        if (eventValues_[k] < 0) passed_.push_back(int(k));
    std::erase_if(hinges, [&](int k) { return passed(k); });
    std::erase_if(contacts, [&](int k) { return passed(k); });
    crossed_ = contacts;
}

// The event functions at the step's start as the step found it (the last
// step's end, kept), or evaluated.
void Simulation::eventFunctionsAtStart() {
    if (const Powers* kept = keptStart_.recall(world_, dynamics_, t_)) {
        lastPowers_ = *kept;
        eventFunctionsNow(nullptr);
    } else {
        smallestEventFunction(t_, nullptr);
    }
}

// Narrows [lo, hi] to the first crossing of the functions `among`, on the
// interpolant: by positions alone when none of them is a force.
EventBracket Simulation::narrowAmong(const std::vector<int>& among, bool anglesOnly, EventBracket b) {
    crossed_ = among;
    narrow(b, scene_.solver.eventTolerance, [&](double h) {
        if (!anglesOnly) {
            interpolant_.at(h, world_.q, world_.v);
            return smallestEventFunction(t_ + h);
        }
        return positionFunctions(h);
    });
    return b;
}

// The smallest of the functions crossed_ at h into the step, by positions
// alone: a hinge's from the angles of its bodies, a block's corner at
// another's face from the two bodies' poses.
double Simulation::positionFunctions(double h) {
    const BlockContacts& contacts = ladder_->blockContacts();
    double f = 1.0;
    for (int k : crossed_) {
        if (k >= hingeFunctions_) {
            // A block's corner at another's face: the two bodies' poses.
            for (int body : contacts.bodies(world_, *ladder_, k - hingeFunctions_))
                for (int c = 0; c < 3; ++c) world_.q[3 * body + c] = interpolant_.coordinateAt(h, 3 * body + c);
            f = std::min(f, contacts.positionFunction(world_, *ladder_, k - hingeFunctions_));
            continue;
        }
        for (int body : ladder_->angleEventBodies(world_, k))
            world_.q[3 * body + 2] = interpolant_.coordinateAt(h, 3 * body + 2);
        f = std::min(f, ladder_->angleEventFunction(world_, k));
    }
    return f;
}

// The block contacts past their event at the step's end (`crossed`, their
// functions `atStart` and `atEnd` at its ends): the bracket `b` narrowed to
// their first crossing if they crossed before the hinges' instant (when
// `afterHinges`, b.hi), and the contacts marked as located.
EventBracket Simulation::narrowContacts(const std::vector<int>& crossed, bool afterHinges, bool positionsOnly,
                                        double from, double atStart, double atEnd, EventBracket b) {
    // The corners' functions where the hinges' event is (or the end).
    double atHi = atEnd;
    if (afterHinges) {
        // Crossed by the hinges' instant as the step's end counts it:
        // past the face by more than the pins' tolerance. A corner
        // that grazes a face there (the hinge's event turns it away)
        // leaves the hinges' instant as it is without contact.
        interpolant_.at(b.hi, world_.q, world_.v);
        crossed_ = crossed;
        ladder_->blockContacts().setLocating(false);
        smallestEventFunction(t_ + b.hi, nullptr);
        ladder_->blockContacts().setLocating(true);
        atHi = 1.0;
        for (int k : crossed) atHi = std::min(atHi, eventValues_[size_t(k)]);
    }
    if (atHi < 0) b = narrowAmong(crossed, positionsOnly, EventBracket{from, atStart, b.hi, atHi});
    std::vector<int> located;
    for (int k : crossed) located.push_back(k - hingeFunctions_);
    ladder_->blockContacts().markLocated(located);
    return b;
}

}  // namespace jl
