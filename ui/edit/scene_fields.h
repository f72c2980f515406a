// The editable numbers of a scene with their units and one-line descriptions:
// the metadata that drives the generic value forms of the Ladder and Simulation docks.
#pragma once

#include "jl/scene/scene.h"
#include "ui/edit/change_value.h"

#include <QString>

#include <functional>
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
