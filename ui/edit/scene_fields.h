// The editable numbers of a scene as the Ladder and Simulation docks show
// them: each built from its row of the scene's table (jl/scene/scene_fields.h:
// unit, range, meaning) and the form's own choices (label, shown scale,
// decimals, what a sentinel 0 means).
#pragma once

#include "jl/scene/bound.h"
#include "jl/scene/scene.h"
#include "ui/edit/change_value.h"

#include <QString>

#include <functional>
#include <string_view>
#include <utility>
#include <vector>

namespace jl::ui {

struct NumberField {
    QString key;  // stable name, also the undo merge key
    QString label;
    QString unit;             // as shown, after the scale is applied
    QString tip;              // one line: what it means and its effect
    double min = 0, max = 1;  // in shown units
    double scale = 1;         // shown = SI * scale (mm for lengths)
    int decimals = 3;         // 0: an integer field
    bool scientific = false;  // tolerances: typed as 1e-8
    int significant = 0;      // > 0: shown to this many significant digits (damping: 2e-05, not 0.0000200)
    SceneChange change = SceneChange::Ladder;
    std::function<double(const jl::Scene&)> get;  // SI
    std::function<void(jl::Scene&, double)> set;  // SI
    // Shown instead of the minimum when that means "not set" (e.g. a mass
    // that follows from the density): says what the engine will use.
    std::function<QString(const jl::Scene&)> unset;
};

std::vector<NumberField> ladderNumberFields();
// The unit a form shows for a row's SI unit at a scale (shown = SI * scale):
// "mm" for "m" at 1000, "N·m·s" for "N m s" at 1.
QString shownUnit(std::string_view si, double scale);
// A row's meaning as a tooltip: a sentence, without the page's backticks,
// and what the form adds (`note`).
QString tipOf(std::string_view meaning, const QString& note = {});
// The range a form allows for a row's at a scale and number of decimals:
// rounded inward to the decimals, an open end moved in by one step.
std::pair<double, double> shownRange(const jl::Bound& range, double scale, int decimals);
std::vector<NumberField> solverNumberFields();  // the Simulation panel's: the scene's duration, then the solver's

// The whole sub-spec is what an edit stores, so side effects (dropping
// overrides past a new block count) undo exactly.
SceneField<jl::LadderSpec> ladderField(const QString& key);
SceneField<jl::SolverSpec> solverField(const QString& key);

// Applies a number to a copy of the scene and pushes it as one undo step.
void changeNumber(Document* doc, const NumberField& f, double si);

// A ladder of n blocks: per-block data past the end dropped, explicit start poses reset.
void setBlockCount(jl::LadderSpec& ladder, int n);

}  // namespace jl::ui
