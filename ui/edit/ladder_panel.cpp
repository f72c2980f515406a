#include "ui/edit/ladder_panel.h"

#include "ui/design/reach_estimate.h"
#include "ui/edit/block_overrides.h"
#include "ui/edit/scene_fields.h"
#include "ui/edit/value_form.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpressionValidator>
#include <QSignalBlocker>
#include <QVBoxLayout>

namespace jl::ui {

namespace {
QColor toQColor(const jl::Color& c) { return QColor(c.r, c.g, c.b); }
jl::Color toColor(const QColor& c) { return {std::uint8_t(c.red()), std::uint8_t(c.green()), std::uint8_t(c.blue())}; }

// The colour a colour button edits.
jl::Color& colorOf(jl::LadderSpec& l, const QString& key) {
    if (key == "blockColor") return l.block.color;
    if (key == "ribbonColor") return l.ribbons.color;
    return l.ribbons.centralColor;
}

void paintSwatch(QPushButton* b, const jl::Color& c) {
    QPixmap pm(28, 14);
    pm.fill(toQColor(c));
    b->setIcon(QIcon(pm));
    b->setText(toQColor(c).name());
}

QString heldText(const std::vector<int>& held) {
    QStringList parts;
    for (int h : held) parts << QString::number(h);
    return parts.join(", ");
}
}  // namespace

LadderPanel::LadderPanel(Document* doc, QWidget* parent) : QWidget(parent), doc_(doc) {
    auto* box = new QVBoxLayout(this);
    form_ = new ValueForm(doc, ladderNumberFields(), this);
    box->addWidget(form_);
    QFormLayout* form = form_->layout();

    blockColor_ = colorButton("blockColor", tr("Colour of every block (a block override may change one)."));
    form->insertRow(6, new QLabel(tr("Block colour")), blockColor_);
    // Under the ribbons' numbers (outer width, middle width, thickness, inset).
    ribbonColor_ = colorButton("ribbonColor", tr("Colour of the two outer ribbons."));
    form->insertRow(11, new QLabel(tr("Outer ribbon colour")), ribbonColor_);
    centralRibbonColor_ = colorButton("centralRibbonColor", tr("Colour of the middle ribbon."));
    form->insertRow(12, new QLabel(tr("Middle ribbon colour")), centralRibbonColor_);
    ribbonsVisible_ = new QCheckBox(tr("Show ribbons"), this);
    ribbonsVisible_->setObjectName("ribbonsVisible");
    ribbonsVisible_->setToolTip(tr("Ribbons are drawn only; hiding them shows the hinges."));
    form->insertRow(13, QString(), ribbonsVisible_);
    connect(ribbonsVisible_, &QCheckBox::toggled, this, [this](bool on) {
        editLadder("ribbonsVisible", on ? tr("Show ribbons") : tr("Hide ribbons"),
                   [on](jl::LadderSpec& l) { l.ribbons.visible = on; });
    });

    held_ = new QLineEdit(this);
    held_->setObjectName("held");
    held_->setPlaceholderText(tr("none"));
    held_->setValidator(new QRegularExpressionValidator(QRegularExpression(R"(^[\d,\s]*$)"), held_));
    const QString heldTip = tr("Blocks held by the hand (0 is the top), separated by commas; they follow the script.");
    held_->setToolTip(heldTip);
    auto* heldLabel = new QLabel(tr("Held blocks"));
    heldLabel->setToolTip(heldTip);
    form->addRow(heldLabel, held_);
    connect(held_, &QLineEdit::editingFinished, this, [this] {
        std::vector<int> held;
        for (const QString& p : held_->text().split(',', Qt::SkipEmptyParts)) {
            bool ok = false;
            const int b = p.trimmed().toInt(&ok);
            const int n = doc_->scene().ladder ? doc_->scene().ladder->blocks : 0;
            if (ok && b >= 0 && b < n && std::find(held.begin(), held.end(), b) == held.end()) held.push_back(b);
        }
        editLadder("held", tr("Change held blocks"), [held](jl::LadderSpec& l) { l.held = held; });
        held_->setText(heldText(doc_->scene().ladder ? doc_->scene().ladder->held : std::vector<int>{}));
    });
    // Under the block count: the live estimate of the first ripple, across
    // the whole form (in the room beside a button it took five lines), and
    // the map of it over two parameters.
    estimate_ = new ReachEstimate(this);
    auto* mapButton = new QPushButton(tr("Design map..."), this);
    mapButton->setObjectName("designMapButton");
    mapButton->setToolTip(
        tr("How far the first ripple travels over two of the design's parameters, one simulation per design."));
    connect(mapButton, &QPushButton::clicked, this, &LadderPanel::designMapRequested);
    form->insertRow(1, estimate_);
    form->insertRow(2, QString(), mapButton);

    overrides_ = new BlockOverrides(doc, this);
    box->addWidget(new QLabel(tr("<b>Blocks that differ</b>"), this));
    box->addWidget(overrides_, 1);
    refresh();
}

QPushButton* LadderPanel::colorButton(const QString& key, const QString& tip) {
    auto* b = new QPushButton(this);
    b->setObjectName(key);
    b->setToolTip(tip);
    connect(b, &QPushButton::clicked, this, [this, key] {
        if (!doc_->scene().ladder) return;
        jl::LadderSpec l = *doc_->scene().ladder;
        jl::Color& color = colorOf(l, key);
        const QColor c = QColorDialog::getColor(toQColor(color), this);
        if (!c.isValid()) return;
        const QString text = key == "blockColor"    ? tr("Change block colour")
                             : key == "ribbonColor" ? tr("Change outer ribbon colour")
                                                    : tr("Change middle ribbon colour");
        editLadder(key, text, [key, c](jl::LadderSpec& spec) { colorOf(spec, key) = toColor(c); });
    });
    return b;
}

void LadderPanel::editLadder(const QString& key, const QString& text,
                             const std::function<void(jl::LadderSpec&)>& edit) {
    if (!doc_->scene().ladder) return;
    jl::LadderSpec l = *doc_->scene().ladder;
    edit(l);
    changeScene(doc_, ladderField(key), l, text);
}

void LadderPanel::refresh() {
    setEnabled(doc_->scene().ladder.has_value());
    form_->refresh();
    estimate_->estimate(doc_->scene());
    if (!doc_->scene().ladder) return;
    const jl::LadderSpec& l = *doc_->scene().ladder;
    paintSwatch(blockColor_, l.block.color);
    paintSwatch(ribbonColor_, l.ribbons.color);
    paintSwatch(centralRibbonColor_, l.ribbons.centralColor);
    const QSignalBlocker b1(ribbonsVisible_), b2(held_);
    ribbonsVisible_->setChecked(l.ribbons.visible);
    held_->setText(heldText(l.held));
    overrides_->refresh();
}

}  // namespace jl::ui
