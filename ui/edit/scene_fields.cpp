#include "ui/edit/scene_fields.h"

#include "jl/scene/ladder_blocks.h"
#include "jl/scene/scene_ranges.h"

#include <QCoreApplication>

#include <algorithm>

namespace jl::ui {

namespace {

QString tr(const char* s) { return QCoreApplication::translate("SceneFields", s); }

// The scene files' range of a number (jl/scene/scene_ranges.h), in the
// form's shown units: the form accepts exactly what a file may hold.
struct Shown {
    double min, max;
};
Shown within(jl::Bound b, double scale) { return {b.lo * scale, b.hi * scale}; }

// A field of the ladder spec, read as 0 when the scene has no ladder.
NumberField ladderNumber(QString key, QString label, QString unit, QString tip, Shown range, double scale, int decimals,
                         std::function<double(const jl::LadderSpec&)> get,
                         std::function<void(jl::LadderSpec&, double)> set) {
    NumberField f;
    f.key = std::move(key), f.label = std::move(label), f.unit = std::move(unit), f.tip = std::move(tip);
    f.min = range.min, f.max = range.max, f.scale = scale, f.decimals = decimals;
    f.change = SceneChange::Ladder;
    f.get = [get](const jl::Scene& s) { return s.ladder ? get(*s.ladder) : 0.0; };
    f.set = [set](jl::Scene& s, double v) {
        if (s.ladder) set(*s.ladder, v);
    };
    return f;
}

// A number whose useful values span decades: kept to `decimals`, shown to `digits`.
NumberField significant(NumberField f, int digits) {
    f.significant = digits;
    return f;
}

NumberField solverNumber(QString key, QString label, QString unit, QString tip, Shown range, double scale, int decimals,
                         bool scientific, double jl::SolverSpec::*member) {
    NumberField f;
    f.key = std::move(key), f.label = std::move(label), f.unit = std::move(unit), f.tip = std::move(tip);
    f.min = range.min, f.max = range.max, f.scale = scale, f.decimals = decimals, f.scientific = scientific;
    f.change = SceneChange::Solver;
    f.get = [member](const jl::Scene& s) { return s.solver.*member; };
    f.set = [member](jl::Scene& s, double v) { s.solver.*member = v; };
    return f;
}

// The mass of every block; at 0 (not set) it follows from the density, and
// the field says what that comes to rather than showing "0 g".
NumberField blockMassField() {
    using L = jl::LadderSpec;
    NumberField f = ladderNumber(
        "mass", tr("Block mass"), "g", tr("Mass of every block; 0 means computed from the density."),
        {0, jl::range::mass.hi * 1000}, 1000, 2, [](const L& l) { return l.block.mass.value_or(0.0); },
        [](L& l, double v) { l.block.mass = v > 0 ? std::optional<double>(v) : std::nullopt; });
    f.unset = [](const jl::Scene& s) {
        if (!s.ladder) return QString();
        jl::BlockSpec b = s.ladder->block;
        b.mass.reset();
        return tr("from density: %1 g").arg(jl::massOf(b) * 1000, 0, 'f', 2);
    };
    return f;
}

// The step: 0 lets the engine choose it (1 ms at most, within the stability
// limit of the ladder's fastest vibration), which the field says in words.
NumberField automaticStepField() {
    NumberField f = solverNumber("step", tr("Time step"), "ms",
                                 tr("Fixed step of the integrator (the first try of the adaptive one); 0: the engine "
                                    "chooses it, at most 1 ms and short enough to stay stable on long ladders."),
                                 {0, jl::range::step.hi * 1000}, 1000, 3, false, &jl::SolverSpec::step);
    f.unset = [](const jl::Scene&) { return tr("automatic"); };
    return f;
}

// The scene's length: where the lesson stops playing and the timeline ends
// (Play at the end goes on). The range's open end at 0 is the form's 1 ms.
NumberField durationField() {
    NumberField f;
    f.key = "duration", f.label = tr("Duration"), f.unit = "s";
    f.tip = tr("How long the scene plays before it pauses; the timeline spans it. Play at the end goes on.");
    f.min = 0.001, f.max = jl::range::duration.hi, f.scale = 1, f.decimals = 3;
    f.change = SceneChange::Duration;
    f.get = [](const jl::Scene& s) { return s.duration; };
    f.set = [](jl::Scene& s, double v) { s.duration = v; };
    return f;
}

}  // namespace

void setBlockCount(jl::LadderSpec& ladder, int n) {
    ladder.blocks = n;
    std::erase_if(ladder.held, [n](int b) { return b >= n; });
    std::erase_if(ladder.overrides, [n](const jl::BlockOverride& o) { return o.index >= n; });
    // Explicit starting poses or fold angles no longer fit: start from the hanging equilibrium.
    if (ladder.initial.kind != jl::InitialState::Kind::Equilibrium) ladder.initial = {};
}

std::vector<NumberField> ladderNumberFields() {
    using L = jl::LadderSpec;
    return {
        ladderNumber(
            "blocks", tr("Blocks"), "", tr("How many blocks hang in the ladder; changing it rebuilds the ladder."),
            {jl::range::kFewestBlocks, jl::range::kMostBlocks}, 1, 0, [](const L& l) { return double(l.blocks); },
            [](L& l, double v) { setBlockCount(l, int(v)); }),
        ladderNumber(
            "length", tr("Block length"), "mm",
            tr("Along the ladder; every block shares it, so the far corners meet when folded."),
            within(jl::range::size, 1000), 1000, 1, [](const L& l) { return l.block.length; },
            [](L& l, double v) { l.block.length = v; }),
        ladderNumber(
            "thickness", tr("Block thickness"), "mm",
            tr("Across the ladder, in its plane; thin blocks carry the ripple further."), within(jl::range::size, 1000),
            1000, 2, [](const L& l) { return l.block.thickness; }, [](L& l, double v) { l.block.thickness = v; }),
        ladderNumber(
            "width", tr("Block width"), "mm", tr("Out of the ladder's plane; changes only the mass and the drawing."),
            within(jl::range::size, 1000), 1000, 1, [](const L& l) { return l.block.width; },
            [](L& l, double v) { l.block.width = v; }),
        ladderNumber(
            "density", tr("Density"), "kg/m³", tr("Of the wood; gives each block's mass unless a mass is set."),
            within(jl::range::density, 1), 1, 0, [](const L& l) { return l.block.density; },
            [](L& l, double v) { l.block.density = v; }),
        blockMassField(),
        ladderNumber(
            "ribbonWidth", tr("Outer ribbon width"), "mm",
            tr("Width of each of the two outer ribbons across the block faces (drawing only)."),
            within(jl::range::ribbonSize, 1000), 1000, 1, [](const L& l) { return l.ribbons.width; },
            [](L& l, double v) { l.ribbons.width = v; }),
        ladderNumber(
            "ribbonCentralWidth", tr("Middle ribbon width"), "mm",
            tr("Width of the middle ribbon, on the faces that do not carry the outer pair (drawing only)."),
            within(jl::range::ribbonSize, 1000), 1000, 1, [](const L& l) { return l.ribbons.centralWidth; },
            [](L& l, double v) { l.ribbons.centralWidth = v; }),
        ladderNumber(
            "ribbonThickness", tr("Ribbon thickness"), "mm",
            tr("How far the ribbons stand off the faces (drawing only)."), within(jl::range::ribbonSize, 1000), 1000, 2,
            [](const L& l) { return l.ribbons.thickness; }, [](L& l, double v) { l.ribbons.thickness = v; }),
        ladderNumber(
            "ribbonInset", tr("Ribbon inset"), "mm", tr("From a block's edge to an outer ribbon (drawing only)."),
            within(jl::range::inset, 1000), 1000, 1, [](const L& l) { return l.ribbons.inset; },
            [](L& l, double v) { l.ribbons.inset = v; }),
        significant(ladderNumber(
                        "damping", tr("Hinge damping"), "N·m·s",
                        tr("Viscous torque in free hinges; above about 1e-5 it stops long ripples."),
                        within(jl::range::angularDamping, 1), 1, 9, [](const L& l) { return l.hinges.damping; },
                        [](L& l, double v) { l.hinges.damping = v; }),
                    3),
        ladderNumber(
            "restitution", tr("Restitution"), "", tr("Bounce at a lock or fold, 0 (plastic) to just under 1."),
            within(jl::range::restitution, 1), 1, 3, [](const L& l) { return l.hinges.restitution; },
            [](L& l, double v) { l.hinges.restitution = v; }),
    };
}

std::vector<NumberField> solverNumberFields() {
    using S = jl::SolverSpec;
    return {
        durationField(),
        automaticStepField(),
        solverNumber("tolerance", tr("Error tolerance"), "",
                     tr("Local error allowed per step by the adaptive integrator."), within(jl::range::tolerance, 1), 1,
                     0, true, &S::tolerance),
        solverNumber("projectionTolerance", tr("Pin tolerance"), "m",
                     tr("Largest gap left in a pin after the constraint projection."),
                     within(jl::range::projectionTolerance, 1), 1, 0, true, &S::projectionTolerance),
        solverNumber("eventTolerance", tr("Event tolerance"), "s",
                     tr("How precisely the time of a lock, fold or flip is located."),
                     within(jl::range::eventTolerance, 1), 1, 0, true, &S::eventTolerance),
        solverNumber("frameInterval", tr("Frame interval"), "ms",
                     tr("Simulated time between recorded frames (the timeline's resolution)."),
                     within(jl::range::frameInterval, 1000), 1000, 2, false, &S::frameInterval),
    };
}

SceneField<jl::LadderSpec> ladderField(const QString& key) {
    return {UndoId::LadderValue, key, SceneChange::Ladder,
            [](const jl::Scene& s) { return s.ladder.value_or(jl::LadderSpec{}); },
            [](jl::Scene& s, const jl::LadderSpec& v) { s.ladder = v; }};
}

SceneField<jl::SolverSpec> solverField(const QString& key) {
    return {UndoId::SolverValue, key, SceneChange::Solver, [](const jl::Scene& s) { return s.solver; },
            [](jl::Scene& s, const jl::SolverSpec& v) { s.solver = v; }};
}

void changeNumber(Document* doc, const NumberField& f, double si) {
    jl::Scene copy = doc->scene();
    f.set(copy, si);
    const QString text = QCoreApplication::translate("SceneFields", "Change %1").arg(f.label.toLower());
    if (f.change == SceneChange::Duration)
        changeScene(doc,
                    SceneField<double>{UndoId::Duration, f.key, SceneChange::Duration,
                                       [](const jl::Scene& s) { return s.duration; },
                                       [](jl::Scene& s, const double& v) { s.duration = v; }},
                    copy.duration, text);
    else if (f.change == SceneChange::Solver)
        changeScene(doc, solverField(f.key), copy.solver, text);
    else if (copy.ladder)
        changeScene(doc, ladderField(f.key), *copy.ladder, text);
}

}  // namespace jl::ui
