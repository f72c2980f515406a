// The whole state of a run, as Simulation::snapshot copies it out and
// Simulation::restore puts it back (simulation_snapshot.cpp). Private to the
// library: the timeline holds snapshots only as opaque pointers.
#pragma once

#include "jl/sim/simulation.h"

#include <tuple>

namespace jl {

struct Snapshot {
    World world;
    std::optional<Ladder> ladder;
    std::optional<PinStops> stops;
    Stepper stepper;
    Ledger ledger;
    double t = 0, impactLoss = 0, impactHeldWork = 0;
    size_t nextAction = 0;
    std::vector<size_t> nextDragSample;
    SolverFrame stats;
    // The automatic step's scale (halved after each step that blew up) and
    // the books' imbalance at the last halving: without them a restored run
    // would take the un-halved step again.
    double stepScale = 1, imbalanceBase = 0;
    // The largest energy that has flowed (the books' scale, run_stops.cpp).
    double booksScale = 0;
    // The fields, in the order of Simulation::stateOf.
    template <class Self>
    static auto stateOf(Self& s) {
        return std::tie(s.world, s.ladder, s.stops, s.stepper, s.ledger, s.t, s.impactLoss, s.impactHeldWork,
                        s.nextAction, s.nextDragSample, s.stats, s.stepScale, s.imbalanceBase, s.booksScale);
    }
};

}  // namespace jl
