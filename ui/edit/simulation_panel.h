// The Simulation dock: integrator, steps, tolerances, the event policy,
// whether blocks touch, and the table top.
#pragma once

#include "jl/scene/scene_fields.h"
#include "ui/edit/document.h"

#include <QFutureWatcher>
#include <QWidget>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;

namespace jl::ui {

class ValueForm;

class SimulationPanel : public QWidget {
    Q_OBJECT
public:
    SimulationPanel(Document* doc, QWidget* parent = nullptr);
    void refresh();
    // The program's own setting (not the scene's): memory for the recorded frames.
    void setHistoryMegabytes(int mb);

signals:
    void historyMegabytesChanged(int mb);

private:
    template <class E>
    QComboBox* addChoice(std::span<const jl::Word<E>> words, E jl::SolverSpec::*member, const char* key,
                         const QString& label, const QString& tip, const QString& undo, bool first = false);

    void addTableTop();
    void placeTableTop();
    void tablePlaced();

    Document* doc_;
    ValueForm* form_;
    QComboBox* integrator_;
    QComboBox* events_;
    QComboBox* blockContact_;
    QCheckBox* table_;             // a table top under the ladder, or none
    QDoubleSpinBox* tableHeight_;  // mm
    // Where a new table top goes, found off the UI thread (the ladder is
    // built to find its lowest corner: 0.8 s at 100,000 blocks); stale when
    // the scene changed meanwhile, and then found again.
    QFutureWatcher<double> tablePlace_;
    bool placingTable_ = false;
    bool tablePlaceStale_ = false;
    // The box had the keyboard when it was clicked: it gets it back when it
    // is enabled again, unless the user has put the focus somewhere since.
    bool tableHadFocus_ = false;
    QSpinBox* history_;
};

}  // namespace jl::ui
