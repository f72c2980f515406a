#include "ui/edit/simulation_panel.h"

#include "jl/scene/scene_fields.h"
#include "jl/sim/simulation.h"
#include "ui/edit/change_value.h"
#include "ui/edit/scene_fields.h"
#include "ui/edit/value_form.h"

#include <QApplication>
#include <QCheckBox>
#include <QComboBox>
#include <QCoreApplication>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>
#include <QtConcurrent>

#include <cmath>
#include <limits>
#include <utility>

namespace jl::ui {

namespace {

// A choice of the scene files' table (jl/scene/scene_fields.h): its labels,
// each item carrying its value, so no list here depends on the enum's order.
template <class E>
void addWords(QComboBox* box, std::span<const jl::Word<E>> words) {
    for (const jl::Word<E>& w : words)
        box->addItem(QCoreApplication::translate("SceneFields", std::string(w.label).c_str()), int(w.value));
}

// Keyed apart: a table put there and its height typed a moment later are
// two steps of undo; the height's own arrow clicks merge.
SceneField<std::optional<jl::FloorSpec>> floorField(const QString& key) {
    return {UndoId::Floor, key, SceneChange::Floor, [](const jl::Scene& s) { return s.floor; },
            [](jl::Scene& s, const std::optional<jl::FloorSpec>& v) { s.floor = v; }};
}

// Where a new table top goes: 10 mm under the ladder's lowest corner as it
// starts (a whole millimetre), so that it can be lowered or dropped onto it.
double tableUnderTheLadder(const jl::Scene& scene) {
    jl::Scene open = scene;
    open.floor.reset();
    const jl::Simulation::Built built = jl::Simulation::build(open);
    if (!built.simulation || !built.simulation->ladder()) return 0;
    const jl::Ladder& ladder = *built.simulation->ladder();
    double lowest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < ladder.blockCount(); ++i)
        for (int k = 0; k < 4; ++k) lowest = std::min(lowest, ladder.cornerWorld(built.simulation->world(), i, k).y());
    return std::floor(lowest * 1000) / 1000 - 0.01;
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
    addTableTop();
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

// The table top (docs/model.md section 17.8): checked, one is put just
// under the ladder; its height is then a field. Each is one undoable edit.
void SimulationPanel::addTableTop() {
    const jl::NumberField<jl::FloorSpec>& height = jl::rowOf(jl::kFloorNumbers, "height");
    const QString tip = tipOf(height.meaning, tr("Block corners strike it and rest on it, whatever \"Blocks touch\" "
                                                 "says; the box puts one just under the ladder."));
    table_ = new QCheckBox(this);
    table_->setObjectName("floor");
    table_->setToolTip(tip);
    tableHeight_ = new QDoubleSpinBox(this);
    tableHeight_->setObjectName("floor.height");
    // One step under the lowest height a scene may give: the minimum, which
    // reads "none".
    const int decimals = 1;
    const auto [lowest, highest] = shownRange(height.range, 1000, decimals);
    tableHeight_->setRange(lowest - std::pow(10.0, -decimals), highest);
    tableHeight_->setDecimals(decimals);
    tableHeight_->setSuffix(" " + shownUnit(height.unit, 1000));
    tableHeight_->setSpecialValueText(tr("none"));  // shown at the minimum, where no table is
    tableHeight_->setKeyboardTracking(false);
    tableHeight_->setToolTip(tip);
    auto* row = new QHBoxLayout;
    row->addWidget(table_);
    row->addWidget(tableHeight_, 1);
    auto* l = new QLabel(tr("Table top"));
    l->setToolTip(tip);
    form_->layout()->addRow(l, row);
    connect(table_, &QCheckBox::toggled, this, [this](bool on) {
        if (on)
            placeTableTop();
        else
            changeScene(doc_, floorField("floor"), std::optional<jl::FloorSpec>(), tr("Remove table top"));
    });
    // An edit meanwhile: the place is found again for the scene as it is
    // now. Another scene altogether (a file opened): the click is dropped.
    connect(doc_, &Document::changed, this, [this](SceneChange c) {
        if (!placingTable_) return;
        tablePlaceStale_ = true;
        if (c != SceneChange::Whole) return;
        tablePlaced();
        refresh();
    });
    connect(&tablePlace_, &QFutureWatcher<double>::finished, this, [this] {
        if (!placingTable_) return;
        if (tablePlaceStale_) return placeTableTop();
        tablePlaced();
        if (doc_->scene().floor) return refresh();
        changeScene(doc_, floorField("floor"), std::optional<jl::FloorSpec>(jl::FloorSpec{tablePlace_.result()}),
                    tr("Add table top"));
    });
    connect(tableHeight_, &QDoubleSpinBox::valueChanged, this, [this](double mm) {
        if (!doc_->scene().floor || mm == tableHeight_->minimum()) return;
        changeScene(doc_, floorField("floor.height"), std::optional<jl::FloorSpec>(jl::FloorSpec{mm / 1000}),
                    tr("Change table top"));
    });
}

// The box stays checked, and out of reach, until the place is found; the
// table top is then one undoable edit.
void SimulationPanel::placeTableTop() {
    placingTable_ = true;
    tablePlaceStale_ = false;
    // Disabled with the focus on it, the box would hand the keyboard to the
    // next field (History memory), whose arrows then change it.
    if (table_->hasFocus()) {
        tableHadFocus_ = true;
        table_->clearFocus();
    }
    table_->setEnabled(false);
    tablePlace_.setFuture(QtConcurrent::run([scene = doc_->scene()] { return tableUnderTheLadder(scene); }));
}

void SimulationPanel::tablePlaced() {
    placingTable_ = false;
    table_->setEnabled(doc_->scene().ladder.has_value());
    if (std::exchange(tableHadFocus_, false) && !QApplication::focusWidget() && table_->isEnabled())
        table_->setFocus(Qt::OtherFocusReason);
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
    const QSignalBlocker b4(table_), b5(tableHeight_);
    const std::optional<jl::FloorSpec>& floor = doc_->scene().floor;
    table_->setChecked(floor.has_value() || placingTable_);
    table_->setEnabled(doc_->scene().ladder.has_value() && !placingTable_);
    tableHeight_->setEnabled(floor.has_value());
    tableHeight_->setValue(floor ? floor->height * 1000 : tableHeight_->minimum());
}

}  // namespace jl::ui
