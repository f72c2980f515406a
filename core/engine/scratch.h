// The work space of one world (World::scratch): the buffers its operations
// fill afresh at every call and keep from call to call, so that a step
// allocates nothing once the sizes have settled, where they had been
// thread_local. Each world owns its own, so worlds run on different threads
// (a worker, the design map's pool) share nothing; a copy of a world starts
// with an empty one (Fresh). Nothing here outlives the call that fills it.
#pragma once

#include "jl/engine/contact.h"
#include "jl/engine/world.h"
#include "pin_solver.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace jl {

struct Scratch {
    // World::rigidGroups: a ladder regroups two bodies at every lock, fold
    // and trial, and fresh vectors were most of what that cost.
    std::vector<std::pair<PartId, int>> partIndex;      // (part, its index), sorted
    std::vector<int> root;                              // union-find over the indices
    std::vector<ParticleId> seen;                       // the live particles on the parts
    std::vector<std::pair<std::uint64_t, int>> shared;  // particles shared per pair, few parts
    std::vector<int> members;                           // the parts one particle is on
    std::vector<std::pair<int, PartId>> byRoot;         // the parts by group
    // World::rebuildPins: the bodies a particle already joins.
    std::vector<int> joined;
    // fastestVibration: each body's sum of |F| |r|.
    std::vector<double> pull;
    // The resting contacts' response in a projection, or with a trial
    // contact added (contactMatrixWith, with its list of contacts).
    ContactResponse contacts;
    std::vector<Contact> trialContacts;
    // A pin solver that is reset before each use: the trial contact's.
    PinSolver pins;
};

}  // namespace jl
