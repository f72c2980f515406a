// labels: ui
// Every number the editing panels show is a row of the scene's table
// (jl/scene/scene_fields.h): its editor carries the row's unit (as the form
// scales it), its range and its meaning, so a form cannot drift from the
// reader, the writer and docs/scene-format.md. A number editor that is no
// row must be named here as the form's own.
#include "jl/scene/scene_fields.h"
#include "jl/scene/scene_io.h"
#include "ui/edit/document.h"
#include "ui/edit/ladder_panel.h"
#include "ui/edit/scene_fields.h"
#include "ui/edit/script_panel.h"
#include "ui/edit/simulation_panel.h"
#include "ui_test_support.h"

#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QHeaderView>
#include <QLabel>
#include <QLineEdit>
#include <QSpinBox>
#include <QTableWidget>
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

using namespace jl::ui;

namespace {

// What a row says, wherever it is.
struct Row {
    std::string_view unit;
    jl::Bound range;
    std::string_view meaning;
};
template <class Section>
Row said(const jl::NumberField<Section>& n) {
    return {n.unit, n.range, n.meaning};
}
template <class Section, std::size_t N>
Row said(const jl::NumberField<Section> (&numbers)[N], std::string_view key) {
    return said(jl::rowOf(numbers, key));
}

// Each editor of a number, by object name, and its row.
std::map<QString, Row> expectedRows() {
    return {
        {"length", said(jl::kBlockNumbers, "length")},
        {"thickness", said(jl::kBlockNumbers, "thickness")},
        {"width", said(jl::kBlockNumbers, "width")},
        {"density", said(jl::kBlockNumbers, "density")},
        {"mass", said(jl::kBlockNumbers, "mass")},
        {"ribbonWidth", said(jl::kRibbonNumbers, "width")},
        {"ribbonCentralWidth", said(jl::kRibbonNumbers, "central_width")},
        {"ribbonThickness", said(jl::kRibbonNumbers, "thickness")},
        {"ribbonInset", said(jl::kRibbonNumbers, "inset")},
        {"damping", said(jl::kHingeNumbers, "damping")},
        {"restitution", said(jl::kHingeNumbers, "restitution")},
        {"duration", said(jl::kDurationField)},
        {"step", said(jl::kSolverNumbers, "step")},
        {"tolerance", said(jl::kSolverNumbers, "tolerance")},
        {"projectionTolerance", said(jl::kSolverNumbers, "projection_tolerance")},
        {"eventTolerance", said(jl::kSolverNumbers, "event_tolerance")},
        {"frameInterval", said(jl::kSolverNumbers, "frame_interval")},
        {"floor.height", said(jl::kFloorNumbers, "height")},
    };
}
// Numbers of the forms' own: a whole number whose range is the ladder's
// size, a list of blocks, this computer's memory.
const QStringList kFormsOwn = {"blocks", "held", "historyMegabytes"};

// The scale at which `shown` is the row's unit (1, or 1000 for mm, ms, g).
std::optional<double> scaleOf(const QString& shown, const Row& row) {
    for (double scale : {1.0, 1000.0})
        if (shown == shownUnit(row.unit, scale)) return scale;
    return std::nullopt;
}

// A spin box: its suffix is the row's unit, its tip the row's meaning, and
// its range the row's, to the precision it shows: nothing the file would
// refuse, nothing it takes cut off by more than the box's last digit (a
// value below the range that reads as words stands for "left out").
void checkSpin(QAbstractSpinBox* box, double min, double max, int decimals, const Row& row) {
    const QString name = box->objectName();
    QVERIFY2(box->toolTip().startsWith(tipOf(row.meaning)), qPrintable(name + ": " + box->toolTip()));
    const QString suffix = qobject_cast<QSpinBox*>(box) ? qobject_cast<QSpinBox*>(box)->suffix()
                                                        : qobject_cast<QDoubleSpinBox*>(box)->suffix();
    const auto scale = scaleOf(suffix.trimmed(), row);
    QVERIFY2(scale, qPrintable(name + ": unit " + suffix));
    const double lo = row.range.lo * *scale, hi = row.range.hi * *scale;
    const double digit = std::pow(10.0, -decimals), slack = 1e-9 * std::max({1.0, std::abs(lo), std::abs(hi)});
    const QString says = QString("%1: shows %2 .. %3, the row %4 .. %5").arg(name).arg(min).arg(max).arg(lo).arg(hi);
    QVERIFY2(max <= hi + slack && hi - max <= digit + slack && (!row.range.hiOpen || max < hi), qPrintable(says));
    const bool leftOut = !box->specialValueText().isEmpty() && min < lo;
    QVERIFY2(leftOut || (min >= lo - slack && min - lo <= digit + slack && (!row.range.loOpen || min > lo)),
             qPrintable(says));
}

// A number typed as 1e-8: the validator holds the row's range, the label its unit.
void checkTyped(QLineEdit* edit, const Row& row, QWidget* panel) {
    const QString name = edit->objectName();
    QVERIFY2(edit->toolTip().startsWith(tipOf(row.meaning)), qPrintable(name));
    const auto* v = qobject_cast<const QDoubleValidator*>(edit->validator());
    QVERIFY2(v && v->bottom() == row.range.lo && v->top() == row.range.hi, qPrintable(name));
    for (QLabel* label : panel->findChildren<QLabel*>())
        if (label->buddy() == edit && !row.unit.empty())
            QVERIFY2(label->text().endsWith("(" + shownUnit(row.unit, 1) + ")"), qPrintable(label->text()));
}

// Every number editor of a panel: a row's, or one of the forms' own.
void checkPanel(QWidget* panel, std::set<QString>& seen) {
    const std::map<QString, Row> rows = expectedRows();
    for (QWidget* w : panel->findChildren<QWidget*>()) {
        auto* spin = qobject_cast<QAbstractSpinBox*>(w);
        auto* edit = qobject_cast<QLineEdit*>(w);
        if ((!spin && !edit) || qobject_cast<QAbstractSpinBox*>(w->parentWidget())) continue;  // a box's own line
        const QString name = w->objectName();
        if (kFormsOwn.contains(name)) continue;
        const auto row = rows.find(name);
        QVERIFY2(row != rows.end(), qPrintable("a number of no row: " + name));
        seen.insert(name);
        if (auto* d = qobject_cast<QDoubleSpinBox*>(w))
            checkSpin(d, d->minimum(), d->maximum(), d->decimals(), row->second);
        else if (auto* i = qobject_cast<QSpinBox*>(w))
            checkSpin(i, i->minimum(), i->maximum(), 0, row->second);
        else
            checkTyped(edit, row->second, panel);
    }
}

// A table's column of a row: its header has the row's unit, its tip the row's meaning.
void checkColumn(QTableWidget* table, int column, const Row& row) {
    QTableWidgetItem* header = table->horizontalHeaderItem(column);
    QVERIFY(header);
    QCOMPARE(header->toolTip(), tipOf(row.meaning));
    const QString text = header->text();
    const qsizetype open = text.lastIndexOf('(');
    QVERIFY2(open > 0 && scaleOf(text.mid(open + 1).chopped(1), row), qPrintable(text));
}

}  // namespace

class FormFieldsTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { jl::test::isolateSettings(); }

    void everyNumberOfTheFormsIsARowOfTheTable() {
        Document doc;
        const jl::SceneLoad load = jl::loadScene(JL_SOURCE_DIR "/examples/classic.yaml");
        QVERIFY(load.scene);
        doc.reset(*load.scene, QString());
        LadderPanel ladder(&doc);
        SimulationPanel simulation(&doc);
        std::set<QString> seen;
        checkPanel(&ladder, seen);
        checkPanel(&simulation, seen);
        // Every row expected is shown somewhere.
        for (const auto& [name, row] : expectedRows()) QVERIFY2(seen.count(name), qPrintable("not shown: " + name));

        auto* overrides = ladder.findChild<QTableWidget*>("blockOverrides");
        QVERIFY(overrides);
        const char* overrideKeys[] = {"thickness", "width", "density", "mass"};
        for (int c = 1; c <= 4; ++c) checkColumn(overrides, c, said(jl::kOverrideNumbers, overrideKeys[c - 1]));

        ScriptPanel script(&doc);
        auto* actions = script.findChild<QTableWidget*>("script");
        QVERIFY(actions);
        checkColumn(actions, 0, said(jl::kActionAt));
        checkColumn(actions, 4, said(jl::kActionDuration));
    }
};

QTEST_MAIN(FormFieldsTest)
#include "test_form_fields.moc"
