#include "ui/edit/simulation_panel.h"

#include "jl/scene/scene_fields.h"
#include "ui/edit/scene_fields.h"
#include "ui/edit/value_form.h"

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

    integrator_ = addChoice<jl::Integrator>(
        jl::kIntegrators, &jl::SolverSpec::integrator, "integrator", tr("Integrator"),
        tr("How the motion is integrated between events; the adaptive one follows the tolerance."),
        tr("Change integrator"), true);
    events_ = addChoice<jl::EventPolicy>(
        jl::kEventPolicies, &jl::SolverSpec::events, "events", tr("Events"),
        tr("Where locks, folds and flips happen: at their exact time, or after the step that crossed "
           "them."),
        tr("Change event policy"));
    blockContact_ = addChoice<jl::BlockContact>(
        jl::kBlockContacts, &jl::SolverSpec::blockContact, "block_contact", tr("Blocks touch"),
        tr("Whether blocks that are not neighbours push each other apart (a corner strikes "
           "and rests on a face) or pass through one another, as in the paper's model."),
        tr("Change block contact"));
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

// A choice of the solver's (a row of the scene files' table), as a box in
// the form, named by its key in the scene file: each change one undoable
// edit of the scene.
template <class E>
QComboBox* SimulationPanel::addChoice(std::span<const jl::Word<E>> words, E jl::SolverSpec::*member, const char* key,
                                      const QString& label, const QString& tip, const QString& undo, bool first) {
    auto* box = new QComboBox(this);
    box->setObjectName(key);
    addWords<E>(box, words);
    box->setToolTip(tip);
    auto* l = new QLabel(label);
    l->setToolTip(tip);
    if (first)
        form_->layout()->insertRow(0, l, box);
    else
        form_->layout()->addRow(l, box);
    connect(box, &QComboBox::activated, this, [this, box, member, key, undo](int i) {
        jl::SolverSpec s = doc_->scene().solver;
        s.*member = E(box->itemData(i).toInt());
        changeScene(doc_, solverField(key), s, undo);
    });
    return box;
}

void SimulationPanel::setHistoryMegabytes(int mb) {
    const QSignalBlocker block(history_);
    history_->setValue(mb);
}

void SimulationPanel::refresh() {
    form_->refresh();
    const QSignalBlocker b1(integrator_), b2(events_), b3(blockContact_);
    const jl::SolverSpec& s = doc_->scene().solver;
    integrator_->setCurrentIndex(integrator_->findData(int(s.integrator)));
    events_->setCurrentIndex(events_->findData(int(s.events)));
    blockContact_->setCurrentIndex(blockContact_->findData(int(s.blockContact)));
}

}  // namespace jl::ui
