// A form of labelled number editors built from NumberField metadata: units
// shown, a tooltip on every row, each edit pushed as one (merging) undo step.
#pragma once

#include "ui/edit/scene_fields.h"

#include <QWidget>

#include <vector>

class QFormLayout;

namespace jl::ui {

class ValueForm : public QWidget {
    Q_OBJECT
public:
    ValueForm(Document* doc, std::vector<NumberField> fields, QWidget* parent = nullptr);
    QFormLayout* layout() const { return form_; }
    // Reads every value from the document's scene again.
    void refresh();

protected:
    bool eventFilter(QObject* watched, QEvent* event) override;

private:
    QWidget* makeEditor(const NumberField& f);

    Document* doc_;
    std::vector<NumberField> fields_;
    std::vector<QWidget*> editors_;
    QFormLayout* form_;
};

}  // namespace jl::ui
