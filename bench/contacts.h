// jladder bench: what contact between blocks costs (docs/model.md section
// 17): the broad phase per block and call on ladders of 12 .. 100,000
// blocks, and every example run with block contact off and on.
#pragma once

#include "bench/cases.h"

#include <filesystem>
#include <string>
#include <vector>

namespace jl::bench {

// The broad phase alone (BlockPairs::find), on the classic design with
// `blocks` blocks half a second into its turn: the ripple has started and
// the rest of the ladder is its still tail.
struct BroadPhaseRow {
    int blocks = 0;
    int stillFrom = -1;       // first block of the still tail (-1: none)
    int pairs = 0;            // pairs passed on to the corners
    int calls = 0;            // repetitions timed
    double perBlock = 0;      // CPU s per block per call that searches
    double perBlockKept = 0;  // CPU s per block per call that keeps the pairs it found
    double buildCpu = 0;      // CPU s to build and run the half second (context)
    std::string failure;
};

// One example, run with block contact off (the paper's model) and on.
struct ContactExampleRow {
    std::string scene;
    double asked = 0;              // s
    double cpuOff = 0, cpuOn = 0;  // CPU s, the least of the repetitions
    double ratio = 0;              // the median over the turns of on / off
    int turns = 0;                 // off and on runs taken in turn
    long long stepsOff = 0, stepsOn = 0;
    int eventsOff = 0, eventsOn = 0;  // every event, contact events included
    int touches = 0;                  // "strikes" events with contact on
    bool sameSequence = true;         // the same events (kind, hinge) in the same order, off and on
    double largestShift = 0;          // s, the largest difference of their times, when the same
    double partAt = -1;               // s, where the sequences part, when not
    double balanceOn = 0;             // J, the largest |energy balance| with contact on, every 0.1 s
    std::string failureOff, failureOn;
};

struct ContactsStudy {
    std::vector<BroadPhaseRow> broad;
    std::vector<ContactExampleRow> examples;
    std::string error;  // the examples could not be read
};

// Broad phase on N = 12 .. 100,000 (quick: .. 10,000); every *.yaml of `dir`
// for 3 s (quick: 1 s), off and on, each three times (quick: once).
ContactsStudy contactsStudy(const BenchPlan& plan, const std::filesystem::path& dir);

}  // namespace jl::bench
