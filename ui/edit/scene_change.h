// Which part of the scene an edit touched: one typed change signal for every
// edit, and the merge ids of undo commands, kept in one enum each.
#pragma once

namespace jl::ui {

enum class SceneChange { Whole, Ladder, Solver, Script, Drags, Text, Duration, Floor };

// Commands with the same id and the same field key merge (a spin-box drag is
// one undo step). Apart (-1, QUndoStack's "no merging") never does: a row
// added by a gesture of the hand is a step of its own, however soon the next.
enum class UndoId { Apart = -1, LadderValue = 1, SolverValue, ScriptTable, RecordDrag, Description, Duration, Floor };

}  // namespace jl::ui
