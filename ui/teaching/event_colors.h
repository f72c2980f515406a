// One colour per kind of event, shared by every view that marks events in time.
#pragma once

#include "jl/sim/frame.h"

#include <QColor>

namespace jl::ui {

// Flip-flops orange, folds blue, locks green, releases grey, the rest purple:
// the colours of the timeline's marks, so a mark means the same everywhere.
inline QColor eventColor(jl::EventKind k) {
    switch (k) {
        case jl::EventKind::FlipFlop:
            return {214, 96, 40};
        case jl::EventKind::Fold:
            return {60, 120, 200};
        case jl::EventKind::Lock:
            return {90, 150, 70};
        case jl::EventKind::Unlock:
        case jl::EventKind::Unfold:
            return {130, 130, 130};
        default:
            return {150, 90, 170};
    }
}

}  // namespace jl::ui
