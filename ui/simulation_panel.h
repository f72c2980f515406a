// The Simulation dock: integrator, steps, tolerances and the event policy.
#pragma once

#include "ui/document.h"

#include <QWidget>

class QComboBox;
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
    Document* doc_;
    ValueForm* form_;
    QComboBox* integrator_;
    QComboBox* events_;
    QSpinBox* history_;
};

}  // namespace jl::ui
