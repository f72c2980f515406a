// The Script dock: the scene's timed actions as an editable table.
#pragma once

#include "ui/document.h"

#include <QWidget>

class QTableWidget;

namespace jl::ui {

class ScriptPanel : public QWidget {
    Q_OBJECT
public:
    ScriptPanel(Document* doc, QWidget* parent = nullptr);
    void refresh();

private:
    void commitRow(int row);
    void setScript(std::vector<jl::ScriptAction> script, const QString& text);

    Document* doc_;
    QTableWidget* table_;
};

}  // namespace jl::ui
