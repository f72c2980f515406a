// Reading what happens over time: the script's timed actions and recorded drags.
#include "jl/scene/scene_ranges.h"
#include "scene_read_parts.h"

#include <yaml-cpp/yaml.h>

#include <array>

namespace jl {

void readBlockIndex(Fields& f, std::string_view key, int& out, int blocks) {
    if (!f.has(key)) return;
    if (blocks == 0)
        f.errorAt(key, "refers to a ladder block but the scene has no ladder");
    else
        f.integer(key, out, 0, blocks - 1);
}

namespace {

using Kind = ScriptAction::Kind;

constexpr std::array<std::pair<std::string_view, Kind>, 7> kActions{{{"turn", Kind::Turn},
                                                                     {"move", Kind::Move},
                                                                     {"hold", Kind::Hold},
                                                                     {"release", Kind::Release},
                                                                     {"push", Kind::Push},
                                                                     {"cut", Kind::Cut},
                                                                     {"join", Kind::Join}}};

// The keys of each action's mapping, in the order they are written.
std::vector<std::string_view> actionKeys(Kind kind) {
    switch (kind) {
        case Kind::Turn:
        case Kind::Move:
            return {"block", "by", "duration"};
        case Kind::Hold:
        case Kind::Release:
            return {"block"};
        case Kind::Push:
            return {"block", "impulse", "point"};
        case Kind::Cut:
            return {"hinge"};
        case Kind::Join:
            return {"block", "corner", "other", "other_corner"};
    }
    return {};
}

void readActionBody(Fields& f, ScriptAction& action, int blocks) {
    const bool needsBlock = action.kind != Kind::Cut;
    if (needsBlock && f.require("block")) readBlockIndex(f, "block", action.block, blocks);
    switch (action.kind) {
        case Kind::Turn:
            f.read(kTurnBy, action);
            f.read(kActionDuration, action);
            break;
        case Kind::Move:
            f.read(kMoveBy, action);
            f.read(kActionDuration, action);
            break;
        case Kind::Push:
            f.read(kPushImpulse, action);
            f.read(kPushPoint, action);
            break;
        case Kind::Cut:
            if (!f.require("hinge")) break;
            if (blocks < 2)
                f.errorAt("hinge", "refers to a hinge but the scene has no ladder of 2 or more blocks");
            else
                f.integer("hinge", action.hinge, 1, blocks - 1);
            break;
        case Kind::Join:
            if (f.require("other")) readBlockIndex(f, "other", action.otherBlock, blocks);
            f.integer("corner", action.corner, 0, 3);
            f.integer("other_corner", action.otherCorner, 0, 3);
            break;
        case Kind::Hold:
        case Kind::Release:
            break;
    }
}

// What a teacher might write for an action, and the action it is.
const KeyHelp kActionHelp{{{"rotate", "turn"},
                           {"spin", "turn"},
                           {"flip", "turn"},
                           {"translate", "move"},
                           {"shift", "move"},
                           {"grab", "hold"},
                           {"grip", "hold"},
                           {"catch", "hold"},
                           {"let_go", "release"},
                           {"drop", "release"},
                           {"kick", "push"},
                           {"hit", "push"},
                           {"impulse", "push"},
                           {"split", "cut"},
                           {"break", "cut"},
                           {"connect", "join"},
                           {"attach", "join"},
                           {"pin", "join"}},
                          "an entry is 'at' and one action: turn, move, hold, release, push, cut or join"};

void readAction(const Located& item, Problems& problems, int blocks, std::vector<ScriptAction>& script) {
    Fields f(problems, item, {"at", "turn", "move", "hold", "release", "push", "cut", "join"}, kActionHelp);
    if (!f.isMap()) return;
    ScriptAction action;
    f.read(kActionAt, action);
    int found = 0;
    for (const auto& [word, kind] : kActions) {
        if (!f.has(word)) continue;
        if (++found > 1) {
            f.errorAt(word, "a script entry holds one action; put this one in an entry of its own");
            continue;
        }
        action.kind = kind;
        Fields body(problems, f.value(word), actionKeys(kind));
        if (body.isMap()) readActionBody(body, action, blocks);
    }
    // An unknown key has said what it should be already.
    if (found == 0 && !f.hadUnknownKeys())
        report(problems, item.mark, item.path + ": expected an action: turn, move, hold, release, push, cut or join");
    script.push_back(action);
}

}  // namespace

void readScript(const Located& at, Problems& problems, int blocks, std::vector<ScriptAction>& script) {
    forEachItem(problems, at, [&](const Located& item) { readAction(item, problems, blocks, script); });
}

namespace {

// A sample is [t, x, y]: recorded drags are long, so the form is compact.
void readSamples(Fields& f, DragRecord& drag) {
    Problems& problems = f.problems();
    forEachItem(problems, f.value("samples"), [&](const Located& item) {
        if (!item.node.IsSequence() || item.node.size() != 3) {
            fail(problems, item, "a sample [t, x, y]");
            return;
        }
        const auto t = readNumber(problems, locate(item.node[0], item.path + "[0]"), kDragEnd.range);
        const auto x = readNumber(problems, locate(item.node[1], item.path + "[1]"), kDragPoint.range);
        const auto y = readNumber(problems, locate(item.node[2], item.path + "[2]"), kDragPoint.range);
        if (!t || !x || !y) return;
        if (!drag.samples.empty() && *t < drag.samples.back().t)
            report(problems, item.mark, item.path + ": samples must be in time order");
        drag.samples.push_back({*t, {*x, *y}});
    });
}

}  // namespace

void readDrags(const Located& at, Problems& problems, int blocks, std::vector<DragRecord>& drags) {
    forEachItem(problems, at, [&](const Located& item) {
        Fields f(problems, item, {"block", "point", "samples", "end"});
        if (!f.isMap()) return;
        DragRecord drag;
        if (f.require("block")) readBlockIndex(f, "block", drag.block, blocks);
        f.read(kDragPoint, drag);
        if (f.require("samples")) readSamples(f, drag);
        f.read(kDragEnd, drag);
        if (!drag.samples.empty() && drag.end < drag.samples.back().t)
            f.errorAt("end", "the release comes before the last sample");
        drags.push_back(drag);
    });
}

}  // namespace jl
