#include "ui/edit/value_form.h"

#include <QDoubleSpinBox>
#include <QDoubleValidator>
#include <QFormLayout>
#include <QKeyEvent>
#include <QLabel>
#include <QLineEdit>
#include <QSignalBlocker>
#include <QSpinBox>

#include <cmath>

namespace jl::ui {

namespace {
// A spin box that shows its value to a few significant digits ("2e-05",
// "0.0003", "0"): with the decimals a small damping needs, every value read
// "0.0000000".
class SignificantSpinBox : public QDoubleSpinBox {
public:
    SignificantSpinBox(int digits, QWidget* parent) : QDoubleSpinBox(parent), digits_(digits) {}
    QString textFromValue(double v) const override { return locale().toString(v, 'g', digits_); }
    double valueFromText(const QString& text) const override { return locale().toDouble(number(text)); }
    QValidator::State validate(QString& text, int&) const override {
        bool ok = false;
        const double v = locale().toDouble(number(text), &ok);
        return ok && v >= minimum() && v <= maximum() ? QValidator::Acceptable : QValidator::Intermediate;
    }

private:
    QString number(QString text) const {
        if (text.endsWith(suffix())) text.chop(suffix().size());
        return text.trimmed();
    }
    int digits_;
};
}  // namespace

ValueForm::ValueForm(Document* doc, std::vector<NumberField> fields, QWidget* parent)
    : QWidget(parent), doc_(doc), fields_(std::move(fields)), form_(new QFormLayout(this)) {
    form_->setFieldGrowthPolicy(QFormLayout::AllNonFixedFieldsGrow);
    for (const auto& f : fields_) {
        QWidget* editor = makeEditor(f);
        editor->setObjectName(f.key);
        editor->setToolTip(f.tip);
        editor->installEventFilter(this);
        // A number typed as 1e-8 has no suffix: its label says the unit.
        const bool unitInLabel = f.scientific && !f.unit.isEmpty();
        auto* label = new QLabel(unitInLabel ? QString("%1 (%2)").arg(f.label, f.unit) : f.label, this);
        label->setToolTip(f.tip);
        label->setBuddy(editor);
        form_->addRow(label, editor);
        editors_.push_back(editor);
    }
    refresh();
}

QWidget* ValueForm::makeEditor(const NumberField& f) {
    const QString suffix = f.unit.isEmpty() ? QString() : " " + f.unit;
    if (f.scientific) {
        auto* edit = new QLineEdit(this);
        auto* v = new QDoubleValidator(f.min, f.max, 20, edit);
        v->setNotation(QDoubleValidator::ScientificNotation);
        v->setLocale(QLocale::c());
        edit->setValidator(v);
        connect(edit, &QLineEdit::editingFinished, this, [this, f, edit] {
            bool ok = false;
            const double v = edit->text().toDouble(&ok);
            if (ok) changeNumber(doc_, f, v / f.scale);
        });
        return edit;
    }
    if (f.decimals == 0) {
        auto* spin = new QSpinBox(this);
        spin->setRange(int(f.min), int(f.max));
        spin->setSuffix(suffix);
        // Typed numbers commit on Enter: a count of 1000 must not build 1, 10 and 100 on the way.
        spin->setKeyboardTracking(false);
        connect(spin, &QSpinBox::valueChanged, this, [this, f](int v) { changeNumber(doc_, f, v / f.scale); });
        return spin;
    }
    auto* spin = f.significant > 0 ? new SignificantSpinBox(f.significant, this) : new QDoubleSpinBox(this);
    spin->setRange(f.min, f.max);
    spin->setDecimals(f.decimals);
    spin->setSingleStep(std::pow(10.0, -std::min(f.decimals, 2)));
    spin->setSuffix(suffix);
    spin->setKeyboardTracking(false);
    connect(spin, &QDoubleSpinBox::valueChanged, this, [this, f](double v) { changeNumber(doc_, f, v / f.scale); });
    return spin;
}

// Ctrl+Z in a number field undoes the document's last edit, as it does
// anywhere else in the window: a field's own text undo would claim the key
// first (and, with its value committed already, do nothing).
bool ValueForm::eventFilter(QObject* watched, QEvent* event) {
    if (event->type() == QEvent::ShortcutOverride) {
        const auto* key = static_cast<QKeyEvent*>(event);
        if (key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
            event->ignore();
            return true;
        }
    }
    return QWidget::eventFilter(watched, event);
}

void ValueForm::refresh() {
    for (size_t i = 0; i < fields_.size(); ++i) {
        const NumberField& f = fields_[i];
        const double shown = f.get(doc_->scene()) * f.scale;
        QWidget* w = editors_[i];
        const QSignalBlocker block(w);
        if (auto* s = qobject_cast<QSpinBox*>(w))
            s->setValue(int(std::lround(shown)));
        else if (auto* d = qobject_cast<QDoubleSpinBox*>(w)) {
            if (f.unset) d->setSpecialValueText(f.unset(doc_->scene()));
            d->setValue(shown);
        } else if (auto* e = qobject_cast<QLineEdit*>(w))
            e->setText(QString::number(shown, 'g', 6));
    }
}

}  // namespace jl::ui
