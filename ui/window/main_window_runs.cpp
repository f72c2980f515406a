// The main window's edits into the simulation: what runs again after an
// edit, and from where.
#include "ui/play/sim_controller.h"
#include "ui/window/main_window.h"

namespace jl::ui {

// An edit shows its effect at the moment on screen: the engine cannot
// change a parameter mid-run, so it runs again from the start up to there.
// A change of the drags alone (Undo or Redo of a push) asks for the run of
// those drags, which the simulation kept if a push replaced it: it comes
// back whole, with nothing computed. The status of the load or recall
// posted (loadsPosted_) is the first whose drags are the document's.
void MainWindow::simulateEdit(SceneChange change) {
    const auto now = sim_->status();
    const double at = (change != SceneChange::Whole && now->frame) ? now->frame->time : 0.0;
    ++loadsPosted_;
    if (change == SceneChange::Drags) return sim_->recall(doc_->scene(), at);
    sim_->load(doc_->scene());
    if (at > 0) sim_->seek(at);
}

}  // namespace jl::ui
