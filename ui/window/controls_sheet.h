// Help > Controls: the mouse and the keys of the window in one page.
#pragma once

class QWidget;

namespace jl::ui {

// Shows (or brings back) the sheet, a window that does not block `window`;
// the keys are read from `window`'s actions, so the page cannot drift from
// what the program does.
void showControlsSheet(QWidget* window);

}  // namespace jl::ui
