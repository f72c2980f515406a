#include "ui/edit/block_overrides.h"

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

// Shown value of an optional field: empty when the ladder's value applies.
QString cell(const std::optional<double>& v, double scale) {
    return v ? QString::number(*v * scale, 'g', 6) : QString();
}
std::optional<double> read(const QString& text, double scale) {
    bool ok = false;
    const double v = text.trimmed().toDouble(&ok);
    if (!ok || v <= 0) return std::nullopt;
    return v / scale;
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
    table_->setHorizontalHeaderLabels(
        {tr("Block"), tr("T (mm)"), tr("W (mm)"), tr("ρ (kg/m³)"), tr("m (g)"), tr("Colour")});
    const QStringList tips = {tr("Which block (0 is the top)."),
                              tr("Thickness of this block, across the ladder."),
                              tr("Width of this block, out of the plane."),
                              tr("Density of this block."),
                              tr("Mass of this block; overrides the density."),
                              tr("Colour, as #rrggbb.")};
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
    o.thickness = read(text(Thickness), 1000);
    o.width = read(text(Width), 1000);
    o.density = read(text(Density), 1);
    o.mass = read(text(Mass), 1000);
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
        const QString values[Columns] = {QString::number(o.index), cell(o.thickness, 1000), cell(o.width, 1000),
                                         cell(o.density, 1),       cell(o.mass, 1000),      colour};
        for (int c = 0; c < Columns; ++c) setCellText(table_, r, c, values[c]);
        table_->item(r, Colour)->setBackground(o.color ? QBrush(QColor(o.color->r, o.color->g, o.color->b)) : QBrush());
    }
}

}  // namespace jl::ui
