#include "jl/ladder/hinge_event.h"

namespace jl {

const char* toString(HingeMode m) {
    switch (m) {
        case HingeMode::Free:
            return "free";
        case HingeMode::OpenLocked:
            return "open-locked";
        case HingeMode::Folded:
            return "folded";
        case HingeMode::Cut:
            return "cut";
    }
    return "?";
}

// The names used in event files (jladder run --events).
const char* toString(EventKind k) {
    switch (k) {
        case EventKind::Lock:
            return "lock";
        case EventKind::Unlock:
            return "unlock";
        case EventKind::Fold:
            return "fold";
        case EventKind::Unfold:
            return "unfold";
        case EventKind::FlipFlop:
            return "flip";
        case EventKind::Bounce:
            return "bounce";
        case EventKind::Cut:
            return "cut";
        case EventKind::Join:
            return "join";
        case EventKind::Script:
            return "script";
        case EventKind::Touch:
            return "touch";
        case EventKind::Part:
            return "part";
    }
    return "?";
}

}  // namespace jl
