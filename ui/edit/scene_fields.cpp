#include "ui/edit/scene_fields.h"

#include "jl/scene/ladder_blocks.h"
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_ranges.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <variant>

namespace jl::ui {

namespace {

QString tr(const char* s) { return QCoreApplication::translate("SceneFields", s); }

// The form's own choices for a row: its stable name (the editor's object
// name and the undo merge key), label, shown scale and decimals, and what
// it adds to the row's meaning.
struct Look {
    QString key, label;
    double scale = 1;
    int decimals = 3;
    QString note = {};
    bool scientific = false;  // typed as 1e-8, to any precision
};

double siOf(double v) { return v; }
double siOf(const std::optional<double>& v) { return v.value_or(0.0); }  // 0: left out
void setSi(double& out, double v) { out = v; }
void setSi(std::optional<double>& out, double v) { out = v > 0 ? std::optional<double>(v) : std::nullopt; }

// A number of the scene's table in a form. `where` finds its section in a
// scene (nullptr when the scene has none: a scene without a ladder).
template <class Section, class Where>
NumberField fieldOf(const jl::NumberField<Section>& row, const Look& look, SceneChange change, Where where) {
    NumberField f;
    f.key = look.key, f.label = look.label, f.scale = look.scale, f.decimals = look.decimals;
    f.unit = shownUnit(row.unit, look.scale);
    f.tip = tipOf(row.meaning, look.note);
    f.scientific = look.scientific;
    if (look.scientific)
        f.min = row.range.lo * look.scale, f.max = row.range.hi * look.scale;
    else
        std::tie(f.min, f.max) = shownRange(row.range, look.scale, look.decimals);
    f.change = change;
    // No form edits a point as one number: only plain and optional numbers.
    using Plain = double Section::*;
    using Optional = std::optional<double> Section::*;
    const auto member = row.member;
    f.get = [where, member](const jl::Scene& s) {
        const Section* at = where(s);
        if (!at) return 0.0;
        return std::holds_alternative<Plain>(member) ? siOf(at->*std::get<Plain>(member))
                                                     : siOf(at->*std::get<Optional>(member));
    };
    f.set = [where, member](jl::Scene& s, double v) {
        Section* at = where(s);
        if (!at) return;
        if (std::holds_alternative<Plain>(member))
            setSi(at->*std::get<Plain>(member), v);
        else
            setSi(at->*std::get<Optional>(member), v);
    };
    return f;
}

// Where the ladder's sections and the solver are in a scene.
template <class Section, Section jl::LadderSpec::*part>
NumberField ladderNumber(const jl::NumberField<Section>& row, const Look& look) {
    return fieldOf(row, look, SceneChange::Ladder, [](auto& s) { return s.ladder ? &((*s.ladder).*part) : nullptr; });
}
NumberField solverNumber(std::string_view key, const Look& look) {
    return fieldOf(jl::rowOf(jl::kSolverNumbers, key), look, SceneChange::Solver, [](auto& s) { return &s.solver; });
}

// A number whose useful values span decades: kept to `decimals`, shown to `digits`.
NumberField significant(NumberField f, int digits) {
    f.significant = digits;
    return f;
}

// The block count is a whole number, whose range is the loader's (not a
// row of the table: jl/scene/scene_fields.h).
NumberField blockCountField() {
    NumberField f;
    f.key = "blocks", f.label = tr("Blocks"), f.decimals = 0;
    f.tip = tr("How many blocks hang in the ladder; changing it rebuilds the ladder.");
    f.min = jl::range::kFewestBlocks, f.max = jl::range::kMostBlocks;
    f.get = [](const jl::Scene& s) { return s.ladder ? double(s.ladder->blocks) : 0.0; };
    f.set = [](jl::Scene& s, double v) {
        if (s.ladder) setBlockCount(*s.ladder, int(v));
    };
    return f;
}

// The mass of every block; at 0 (left out) it follows from the density, and
// the field says what that comes to rather than showing "0 g".
NumberField blockMassField() {
    NumberField f = ladderNumber<jl::BlockSpec, &jl::LadderSpec::block>(
        jl::rowOf(jl::kBlockNumbers, "mass"), {"mass", tr("Block mass"), 1000, 2, tr("0 leaves it out.")});
    f.min = 0;
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
    NumberField f = solverNumber("step", {"step", tr("Time step"), 1000, 3, tr("0: the engine chooses it.")});
    f.min = 0;
    f.unset = [](const jl::Scene&) { return tr("automatic"); };
    return f;
}

}  // namespace

QString shownUnit(std::string_view si, double scale) {
    QString unit = QString::fromUtf8(si.data(), qsizetype(si.size()));
    if (scale == 1000 && (unit == "m" || unit == "s")) return "m" + unit;
    if (scale == 1000 && unit == "kg") return "g";
    return unit.replace(' ', QChar(0x00B7));  // N·m·s
}

QString tipOf(std::string_view meaning, const QString& note) {
    QString tip = QString::fromUtf8(meaning.data(), qsizetype(meaning.size())).remove('`');
    if (!tip.isEmpty()) tip = tip.front().toUpper() + tip.mid(1) + ".";
    if (!note.isEmpty()) tip += (tip.isEmpty() ? "" : " ") + note;
    return tip;
}

std::pair<double, double> shownRange(const jl::Bound& range, double scale, int decimals) {
    // Rounded inward to what the form shows: a spin box rounds its limits
    // to its decimals, and 0.001 mm shown to one decimal would allow 0.
    const double per = std::pow(10.0, decimals), slack = 1e-9;
    double lo = std::ceil(range.lo * scale * per - slack) / per;
    double hi = std::floor(range.hi * scale * per + slack) / per;
    if (range.loOpen && lo <= range.lo * scale) lo += 1 / per;
    if (range.hiOpen && hi >= range.hi * scale) hi -= 1 / per;
    return {lo, hi};
}

void setBlockCount(jl::LadderSpec& ladder, int n) {
    ladder.blocks = n;
    std::erase_if(ladder.held, [n](int b) { return b >= n; });
    std::erase_if(ladder.overrides, [n](const jl::BlockOverride& o) { return o.index >= n; });
    // Explicit starting poses or fold angles no longer fit: start from the hanging equilibrium.
    if (ladder.initial.kind != jl::InitialState::Kind::Equilibrium) ladder.initial = {};
}

std::vector<NumberField> ladderNumberFields() {
    using L = jl::LadderSpec;
    auto block = [](std::string_view key, const Look& look) {
        return ladderNumber<jl::BlockSpec, &L::block>(jl::rowOf(jl::kBlockNumbers, key), look);
    };
    auto ribbon = [](std::string_view key, const Look& look) {
        return ladderNumber<jl::RibbonSpec, &L::ribbons>(jl::rowOf(jl::kRibbonNumbers, key), look);
    };
    auto hinge = [](std::string_view key, const Look& look) {
        return ladderNumber<jl::HingeOptions, &L::hinges>(jl::rowOf(jl::kHingeNumbers, key), look);
    };
    return {
        blockCountField(),
        block("length", {"length", tr("Block length"), 1000, 1}),
        block("thickness", {"thickness", tr("Block thickness"), 1000, 2}),
        block("width", {"width", tr("Block width"), 1000, 1}),
        block("density", {"density", tr("Density"), 1, 0}),
        blockMassField(),
        ribbon("width", {"ribbonWidth", tr("Outer ribbon width"), 1000, 1}),
        ribbon("central_width", {"ribbonCentralWidth", tr("Middle ribbon width"), 1000, 1}),
        ribbon("thickness", {"ribbonThickness", tr("Ribbon thickness"), 1000, 2}),
        ribbon("inset", {"ribbonInset", tr("Ribbon inset"), 1000, 1}),
        significant(hinge("damping", {"damping", tr("Hinge damping"), 1, 9}), 3),
        hinge("restitution", {"restitution", tr("Restitution"), 1, 3}),
    };
}

std::vector<NumberField> solverNumberFields() {
    // The scene's length: where the lesson stops playing and the timeline
    // ends (Play at the end goes on).
    NumberField duration =
        fieldOf(jl::kDurationField, {"duration", tr("Duration"), 1, 3, tr("Play at the end goes on.")},
                SceneChange::Duration, [](auto& s) { return &s; });
    return {
        duration,
        automaticStepField(),
        solverNumber("tolerance", {"tolerance", tr("Error tolerance"), 1, 0, {}, true}),
        solverNumber("projection_tolerance", {"projectionTolerance", tr("Pin tolerance"), 1, 0, {}, true}),
        solverNumber("event_tolerance", {"eventTolerance", tr("Event tolerance"), 1, 0, {}, true}),
        solverNumber("frame_interval", {"frameInterval", tr("Frame interval"), 1000, 2}),
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
