// The Simulation dock: integrator, steps, tolerances and the event policy.
#pragma once

#include "ui/document.h"

#include <QWidget>

class QComboBox;

namespace jlui {

class ValueForm;

class SimulationPanel : public QWidget {
    Q_OBJECT
public:
    SimulationPanel(Document* doc, QWidget* parent = nullptr);
    void refresh();

private:
    Document* doc_;
    ValueForm* form_;
    QComboBox* integrator_;
    QComboBox* events_;
};

}  // namespace jlui
