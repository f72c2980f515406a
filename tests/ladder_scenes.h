// Test support: two- and three-block ladder scenes worked by hand
// (docs/model.md section 14.5), shared by the suites of ladder events.
#pragma once

#include "jl/ladder/hinge_event.h"

#include <QString>
#include <QtTest>

#include <string>
#include <vector>

namespace jl::test {

// Block 0 held lying flat (-90 degrees): its hinge face (corner 0's side) is
// on top, hinge 1 at its left end. Block 1 starts at fold angle `phi`; past
// pi/2 + atan(T/L) it topples onto block 0, below that it falls off the end.
// At t = 1 s the hand turns block 0 by `turn` over 0.5 s.
// `pairs` is the model of a locked or folded pair: "merge" (one body) or
// "weld" (two bodies, a pin and a weld): the hand answers hold for both.
inline std::string flatHeldBlock(double phi, const char* turn, const QString& pairs = "merge") {
    return "format: jacobs-ladder/1\n"
           "solver: {rigid_pairs: " +
           pairs.toStdString() +
           "}\n"
           "ladder:\n"
           "  blocks: 2\n"
           "  held: [0]\n"
           "  initial: {fold_angles: [" +
           std::to_string(phi) +
           "], poses: [{block: 0, position: [0, 0], angle: -90deg}]}\n"
           "script:\n"
           "  - {at: 1.0, turn: {block: 0, by: " +
           turn + ", duration: 0.5}}\n";
}

inline void bothModelsOfRigidPairs() {
    QTest::addColumn<QString>("pairs");
    QTest::newRow("merged") << QString("merge");
    QTest::newRow("welded") << QString("weld");
}

// The first event of `kind` at hinge j at or after `from` (nullptr if none).
inline const Event* firstEvent(const std::vector<Event>& events, int j, EventKind kind, double from) {
    for (const Event& e : events)
        if (e.hinge == j && e.kind == kind && e.time >= from) return &e;
    return nullptr;
}

}  // namespace jl::test
