#include "ui/edit/script_panel.h"

#include "jl/scene/scene_fields.h"
#include "ui/edit/change_value.h"
#include "ui/edit/scene_fields.h"
#include "ui/edit/table_cells.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <numbers>

namespace jl::ui {

namespace {
using Kind = jl::ScriptAction::Kind;
enum Column { At, Action, Block, Amount, Duration, Columns };
const QStringList kKinds = {"turn", "move", "hold", "release", "push", "cut", "join"};  // order of Kind

SceneField<std::vector<jl::ScriptAction>> scriptField(UndoId id = UndoId::ScriptTable) {
    return {id, "script", SceneChange::Script, [](const jl::Scene& s) { return s.script; },
            [](jl::Scene& s, const std::vector<jl::ScriptAction>& v) { s.script = v; }};
}

// A typed time brought into its row's (closed) range, as a file may hold it.
double within(double v, const jl::Bound& range) { return std::clamp(v, range.lo, range.hi); }

QString pair(const jl::Point2& p, double scale) {
    return QString("%1, %2").arg(p[0] * scale, 0, 'g', 6).arg(p[1] * scale, 0, 'g', 6);
}
jl::Point2 readPair(const QString& s, double scale) {
    const QStringList p = s.split(',');
    return {p.value(0).trimmed().toDouble() / scale, p.value(1).trimmed().toDouble() / scale};
}

// What the "amount" column means for each kind of action, in the units shown.
QString amountText(const jl::ScriptAction& a) {
    switch (a.kind) {
        case Kind::Turn:
            return QString::number(a.angle * 180 / std::numbers::pi, 'g', 6) + "°";
        case Kind::Move:
            return pair(a.offset, 1000) + " " + shownUnit(jl::kMoveBy.unit, 1000);
        case Kind::Push:
            return pair(a.impulse, 1) + " " + shownUnit(jl::kPushImpulse.unit, 1);
        case Kind::Cut:
            return QObject::tr("hinge %1").arg(a.hinge);
        case Kind::Join:
            return QObject::tr("block %1, corners %2/%3").arg(a.otherBlock).arg(a.corner).arg(a.otherCorner);
        default:
            return {};
    }
}
void readAmount(jl::ScriptAction& a, QString s) {
    s.remove(QRegularExpression("[^0-9eE+\\-.,/ ]"));
    switch (a.kind) {
        case Kind::Turn:
            a.angle = s.trimmed().toDouble() * std::numbers::pi / 180;
            break;
        case Kind::Move:
            a.offset = readPair(s, 1000);
            break;
        case Kind::Push:
            a.impulse = readPair(s, 1);
            break;
        case Kind::Cut:
            a.hinge = s.trimmed().toInt();
            break;
        case Kind::Join: {
            const QStringList p = s.split(QRegularExpression("[,/ ]+"), Qt::SkipEmptyParts);
            a.otherBlock = p.value(0).toInt();
            a.corner = p.value(1).toInt();
            a.otherCorner = p.value(2).toInt();
            break;
        }
        default:
            break;
    }
}
}  // namespace

ScriptPanel::ScriptPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* box = new QVBoxLayout(this);
    table_ = new QTableWidget(0, Columns, this);
    table_->setObjectName("script");
    // The times are rows of the scene's table: their units and meanings.
    auto timed = [](const QString& label, const jl::NumberField<jl::ScriptAction>& row) {
        return QString("%1 (%2)").arg(label, shownUnit(row.unit, 1));
    };
    table_->setHorizontalHeaderLabels({timed(tr("At"), jl::kActionAt), tr("Action"), tr("Block"), tr("Amount"),
                                       timed(tr("Duration"), jl::kActionDuration)});
    table_->horizontalHeaderItem(At)->setToolTip(tipOf(jl::kActionAt.meaning));
    table_->horizontalHeaderItem(Action)->setToolTip(
        tr("Turn or move a held block, hold or release one, push, cut a hinge, join two blocks."));
    table_->horizontalHeaderItem(Block)->setToolTip(tr("The block acted on (0 is the top)."));
    table_->horizontalHeaderItem(Amount)->setToolTip(
        tr("Turn: degrees, counter-clockwise. Move: mm. Push: N·s. Cut: hinge. Join: block, corners."));
    table_->horizontalHeaderItem(Duration)->setToolTip(tipOf(jl::kActionDuration.meaning));
    table_->horizontalHeader()->setStretchLastSection(true);
    table_->verticalHeader()->hide();
    box->addWidget(table_);
    connect(table_, &QTableWidget::cellChanged, this, [this](int row, int) { commitRow(row); });

    auto [add, remove] =
        addRowButtons(this, box, tr("Add turn"), tr("Adds a half turn of the top block after the last action."),
                      tr("Removes the selected action."));
    connect(add, &QPushButton::clicked, this, [this] {
        auto script = doc_->scene().script;
        jl::ScriptAction a;
        a.at = script.empty() ? 0.2 : script.back().at + script.back().duration + 0.5;
        a.angle = -std::numbers::pi;
        script.push_back(a);
        setScript(std::move(script), tr("Add script action"));
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int row = table_->currentRow();
        auto script = doc_->scene().script;
        if (row < 0 || row >= int(script.size())) return;
        script.erase(script.begin() + row);
        setScript(std::move(script), tr("Remove script action"));
    });
    refresh();
}

void ScriptPanel::setScript(std::vector<jl::ScriptAction> script, const QString& text) {
    changeScene(doc_, scriptField(), std::move(script), text);
}

void ScriptPanel::addTurn(int block, double angle, double duration, double at) {
    jl::ScriptAction turn;
    turn.kind = Kind::Turn;
    turn.at = at;
    turn.block = block;
    turn.angle = angle;
    turn.duration = duration;
    addAction(turn, tr("Turn block %1").arg(block));
}

void ScriptPanel::addAction(const jl::ScriptAction& action, const QString& text) {
    auto script = doc_->scene().script;
    const auto later = std::upper_bound(script.begin(), script.end(), action.at,
                                        [](double at, const jl::ScriptAction& a) { return at < a.at; });
    script.insert(later, action);
    changeScene(doc_, scriptField(UndoId::Apart), std::move(script), text);
}

void ScriptPanel::commitRow(int row) {
    auto script = doc_->scene().script;
    if (row < 0 || row >= int(script.size())) return;
    jl::ScriptAction& a = script[size_t(row)];
    auto text = [&](int col) { return table_->item(row, col) ? table_->item(row, col)->text() : QString(); };
    a.at = within(text(At).toDouble(), jl::kActionAt.range);
    a.block = std::max(0, text(Block).toInt());
    if (auto* combo = qobject_cast<QComboBox*>(table_->cellWidget(row, Action))) a.kind = Kind(combo->currentIndex());
    readAmount(a, text(Amount));
    a.duration = within(text(Duration).toDouble(), jl::kActionDuration.range);
    setScript(std::move(script), tr("Edit script action"));
}

void ScriptPanel::refresh() {
    const QSignalBlocker block(table_);
    const auto& script = doc_->scene().script;
    table_->setRowCount(int(script.size()));
    for (int r = 0; r < int(script.size()); ++r) {
        const jl::ScriptAction& a = script[size_t(r)];
        setCellText(table_, r, At, QString::number(a.at, 'g', 6));
        auto* combo = qobject_cast<QComboBox*>(table_->cellWidget(r, Action));
        if (!combo) {
            combo = new QComboBox;
            combo->addItems(kKinds);
            connect(combo, &QComboBox::activated, this, [this, r] { commitRow(r); });
            table_->setCellWidget(r, Action, combo);
        }
        const QSignalBlocker blockCombo(combo);
        combo->setCurrentIndex(int(a.kind));
        setCellText(table_, r, Block, QString::number(a.block));
        setCellText(table_, r, Amount, amountText(a));
        setCellText(table_, r, Duration, QString::number(a.duration, 'g', 6));
    }
    table_->resizeColumnsToContents();
}

}  // namespace jl::ui
