#include "ui/simulation_panel.h"

#include "jl/scene/scene_fields.h"
#include "ui/scene_fields.h"
#include "ui/value_form.h"

#include <QComboBox>
#include <QCoreApplication>
#include <QFormLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

namespace jl::ui {

namespace {

// A choice of the scene files' table (jl/scene/scene_fields.h): its labels,
// each item carrying its value, so no list here depends on the enum's order.
template <class E>
void addWords(QComboBox* box, std::span<const jl::Word<E>> words) {
    for (const jl::Word<E>& w : words)
        box->addItem(QCoreApplication::translate("SceneFields", std::string(w.label).c_str()), int(w.value));
}

}  // namespace

SimulationPanel::SimulationPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* box = new QVBoxLayout(this);
    form_ = new ValueForm(doc, solverNumberFields(), this);
    box->addWidget(form_);

    integrator_ = new QComboBox(this);
    integrator_->setObjectName("integrator");
    addWords<jl::Integrator>(integrator_, jl::kIntegrators);
    const QString integratorTip =
        tr("How the motion is integrated between events; the adaptive one follows the tolerance.");
    integrator_->setToolTip(integratorTip);
    auto* il = new QLabel(tr("Integrator"));
    il->setToolTip(integratorTip);
    form_->layout()->insertRow(0, il, integrator_);
    connect(integrator_, &QComboBox::activated, this, [this](int i) {
        jl::SolverSpec s = doc_->scene().solver;
        s.integrator = jl::Integrator(integrator_->itemData(i).toInt());
        changeScene(doc_, solverField("integrator"), s, tr("Change integrator"));
    });

    events_ = new QComboBox(this);
    events_->setObjectName("eventPolicy");
    addWords<jl::EventPolicy>(events_, jl::kEventPolicies);
    const QString eventsTip =
        tr("Where locks, folds and flips happen: at their exact time, or after the step that crossed them.");
    events_->setToolTip(eventsTip);
    auto* el = new QLabel(tr("Events"));
    el->setToolTip(eventsTip);
    form_->layout()->addRow(el, events_);
    connect(events_, &QComboBox::activated, this, [this](int i) {
        jl::SolverSpec s = doc_->scene().solver;
        s.events = jl::EventPolicy(events_->itemData(i).toInt());
        changeScene(doc_, solverField("events"), s, tr("Change event policy"));
    });
    // Not part of the scene: how much of this computer's memory the timeline may use.
    history_ = new QSpinBox(this);
    history_->setObjectName("historyMegabytes");
    history_->setRange(16, 65536);
    history_->setSingleStep(64);
    history_->setSuffix(" MB");
    history_->setKeyboardTracking(false);
    const QString historyTip =
        tr("Memory for recorded frames (a setting of this computer, not of the scene); "
           "older frames beyond it are re-simulated when you scrub back.");
    history_->setToolTip(historyTip);
    auto* hl = new QLabel(tr("History memory"));
    hl->setToolTip(historyTip);
    form_->layout()->addRow(hl, history_);
    connect(history_, &QSpinBox::valueChanged, this, &SimulationPanel::historyMegabytesChanged);
    box->addStretch(1);
    refresh();
}

void SimulationPanel::setHistoryMegabytes(int mb) {
    const QSignalBlocker block(history_);
    history_->setValue(mb);
}

void SimulationPanel::refresh() {
    form_->refresh();
    const QSignalBlocker b1(integrator_), b2(events_);
    integrator_->setCurrentIndex(integrator_->findData(int(doc_->scene().solver.integrator)));
    events_->setCurrentIndex(events_->findData(int(doc_->scene().solver.events)));
}

}  // namespace jl::ui
