#include "ui/edit/block_overrides.h"

#include "jl/scene/scene_fields.h"
#include "ui/edit/scene_fields.h"
#include "ui/edit/table_cells.h"

#include <QHBoxLayout>
#include <QHeaderView>
#include <QPushButton>
#include <QSignalBlocker>
#include <QTableWidget>
#include <QVBoxLayout>

#include <algorithm>

namespace jl::ui {

namespace {
enum Column { Index, Thickness, Width, Density, Mass, Colour, Columns };

// The columns of numbers: each a row of the scene's table (its unit, range
// and meaning), with the form's short header and shown scale.
struct NumberColumn {
    Column column;
    const char* header;
    double scale;
    const jl::NumberField<jl::BlockOverride>& row;
    // Every number of an override may be left out.
    template <class Override>  // const or not
    auto& of(Override& o) const {
        return o.*std::get<std::optional<double> jl::BlockOverride::*>(row.member);
    }
};
const NumberColumn kNumbers[] = {
    {Thickness, QT_TR_NOOP("T"), 1000, jl::rowOf(jl::kOverrideNumbers, "thickness")},
    {Width, QT_TR_NOOP("W"), 1000, jl::rowOf(jl::kOverrideNumbers, "width")},
    {Density, QT_TR_NOOP("ρ"), 1, jl::rowOf(jl::kOverrideNumbers, "density")},
    {Mass, QT_TR_NOOP("m"), 1000, jl::rowOf(jl::kOverrideNumbers, "mass")},
};

// Shown value of an optional field: empty when the ladder's value applies.
QString cell(const std::optional<double>& v, double scale) {
    return v ? QString::number(*v * scale, 'g', 6) : QString();
}
// A typed value, kept when the scene file would take it: empty or out of
// the row's range, the ladder's value applies.
std::optional<double> read(const QString& text, const NumberColumn& c) {
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok) / c.scale;
    if (!ok || !c.row.range.contains(v)) return std::nullopt;
    return v;
}
std::optional<jl::Color> readColor(const QString& text) {
    const QColor c(text.trimmed());
    if (text.trimmed().isEmpty() || !c.isValid()) return std::nullopt;
    return jl::Color{std::uint8_t(c.red()), std::uint8_t(c.green()), std::uint8_t(c.blue())};
}
}  // namespace

BlockOverrides::BlockOverrides(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* box = new QVBoxLayout(this);
    box->setContentsMargins(0, 0, 0, 0);
    table_ = new QTableWidget(0, Columns, this);
    table_->setObjectName("blockOverrides");
    QStringList headers(Columns), tips(Columns);
    headers[Index] = tr("Block"), tips[Index] = tr("Which block (0 is the top).");
    headers[Colour] = tr("Colour"), tips[Colour] = tr("Colour, as #rrggbb.");
    for (const NumberColumn& c : kNumbers) {
        headers[c.column] = QString("%1 (%2)").arg(tr(c.header), shownUnit(c.row.unit, c.scale));
        tips[c.column] = tipOf(c.row.meaning);
    }
    table_->setHorizontalHeaderLabels(headers);
    for (int c = 0; c < Columns; ++c) table_->horizontalHeaderItem(c)->setToolTip(tips[c]);
    table_->setToolTip(tr("Blocks that differ from the rest; an empty cell keeps the ladder's value."));
    table_->verticalHeader()->hide();
    table_->horizontalHeader()->setSectionResizeMode(QHeaderView::Stretch);
    table_->setMinimumHeight(90);
    box->addWidget(table_);
    connect(table_, &QTableWidget::cellChanged, this, [this](int row, int) { commitRow(row); });

    auto [add, remove] = addRowButtons(this, box, tr("Override a block"),
                                       tr("Adds the first block without an override, to make it different."),
                                       tr("The selected block goes back to the ladder's values."));
    connect(add, &QPushButton::clicked, this, [this] {
        if (!doc_->scene().ladder) return;
        auto overrides = doc_->scene().ladder->overrides;
        int index = 0;
        while (std::any_of(overrides.begin(), overrides.end(), [index](const auto& o) { return o.index == index; }))
            ++index;
        if (index >= doc_->scene().ladder->blocks) return;
        jl::BlockOverride o;
        o.index = index;
        o.color = jl::Color{170, 110, 70};  // a darker wood, so the block is seen at once
        overrides.push_back(o);
        setOverrides(std::move(overrides), tr("Override block %1").arg(index));
    });
    connect(remove, &QPushButton::clicked, this, [this] {
        const int row = table_->currentRow();
        if (!doc_->scene().ladder || row < 0 || row >= int(doc_->scene().ladder->overrides.size())) return;
        auto overrides = doc_->scene().ladder->overrides;
        overrides.erase(overrides.begin() + row);
        setOverrides(std::move(overrides), tr("Remove block override"));
    });
    refresh();
}

void BlockOverrides::setOverrides(std::vector<jl::BlockOverride> overrides, const QString& text) {
    jl::LadderSpec l = *doc_->scene().ladder;
    l.overrides = std::move(overrides);
    changeScene(doc_, ladderField("overrides"), l, text);
}

void BlockOverrides::commitRow(int row) {
    if (!doc_->scene().ladder) return;
    auto overrides = doc_->scene().ladder->overrides;
    if (row < 0 || row >= int(overrides.size())) return;
    auto text = [&](int col) { return table_->item(row, col) ? table_->item(row, col)->text() : QString(); };
    jl::BlockOverride& o = overrides[size_t(row)];
    bool ok = false;
    const int index = text(Index).toInt(&ok);
    const bool taken =
        std::any_of(overrides.begin(), overrides.end(), [&](const auto& x) { return &x != &o && x.index == index; });
    if (ok && index >= 0 && index < doc_->scene().ladder->blocks && !taken) o.index = index;
    for (const NumberColumn& c : kNumbers) c.of(o) = read(text(c.column), c);
    o.color = readColor(text(Colour));
    setOverrides(std::move(overrides), tr("Change block %1").arg(o.index));
    refresh();  // shows what was kept of the typing (unchanged scene: no change signal)
}

void BlockOverrides::refresh() {
    const QSignalBlocker block(table_);
    const auto overrides = doc_->scene().ladder ? doc_->scene().ladder->overrides : std::vector<jl::BlockOverride>{};
    table_->setRowCount(int(overrides.size()));
    for (int r = 0; r < int(overrides.size()); ++r) {
        const jl::BlockOverride& o = overrides[size_t(r)];
        const QString colour = o.color ? QColor(o.color->r, o.color->g, o.color->b).name() : QString();
        setCellText(table_, r, Index, QString::number(o.index));
        for (const NumberColumn& c : kNumbers) setCellText(table_, r, c.column, cell(c.of(o), c.scale));
        setCellText(table_, r, Colour, colour);
        table_->item(r, Colour)->setBackground(o.color ? QBrush(QColor(o.color->r, o.color->g, o.color->b)) : QBrush());
    }
}

}  // namespace jl::ui
