#include "ui/simulation_panel.h"

#include "ui/scene_fields.h"
#include "ui/value_form.h"

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace jlui {

SimulationPanel::SimulationPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* box = new QVBoxLayout(this);
    form_ = new ValueForm(doc, solverNumberFields(), this);
    box->addWidget(form_);

    integrator_ = new QComboBox(this);
    integrator_->setObjectName("integrator");
    // Same order as jl::Integrator.
    integrator_->addItems({tr("Explicit Euler (the paper's)"), tr("Symplectic Euler"), tr("Runge-Kutta 4"),
                           tr("Dormand-Prince 5(4), adaptive")});
    const QString integratorTip = tr("How the motion is integrated between events; the adaptive one follows the tolerance.");
    integrator_->setToolTip(integratorTip);
    auto* il = new QLabel(tr("Integrator"));
    il->setToolTip(integratorTip);
    form_->layout()->insertRow(0, il, integrator_);
    connect(integrator_, &QComboBox::activated, this, [this](int i) {
        jl::SolverSpec s = doc_->scene().solver;
        s.integrator = jl::Integrator(i);
        changeScene(doc_, solverField("integrator"), s, tr("Change integrator"));
    });

    events_ = new QComboBox(this);
    events_->setObjectName("eventPolicy");
    events_->addItems({tr("Located inside the step"), tr("At the end of the step (the paper's)")});
    const QString eventsTip = tr("Where locks, folds and flips happen: at their exact time, or after the step that crossed them.");
    events_->setToolTip(eventsTip);
    auto* el = new QLabel(tr("Events"));
    el->setToolTip(eventsTip);
    form_->layout()->addRow(el, events_);
    connect(events_, &QComboBox::activated, this, [this](int i) {
        jl::SolverSpec s = doc_->scene().solver;
        s.events = jl::EventPolicy(i);
        changeScene(doc_, solverField("events"), s, tr("Change event policy"));
    });
    box->addStretch(1);
    refresh();
}

void SimulationPanel::refresh() {
    form_->refresh();
    const QSignalBlocker b1(integrator_), b2(events_);
    integrator_->setCurrentIndex(int(doc_->scene().solver.integrator));
    events_->setCurrentIndex(int(doc_->scene().solver.events));
}

}  // namespace jlui
