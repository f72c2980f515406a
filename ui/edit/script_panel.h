// The Script dock: the scene's timed actions as an editable table.
#pragma once

#include "ui/edit/document.h"

#include <QWidget>

class QTableWidget;

namespace jl::ui {

class ScriptPanel : public QWidget {
    Q_OBJECT
public:
    ScriptPanel(Document* doc, QWidget* parent = nullptr);
    void refresh();
    // A row added from elsewhere (the views' turn and restructuring), in time
    // order, as one step of undo.
    void addAction(const jl::ScriptAction& action, const QString& text);
    void addTurn(int block, double angle, double duration, double at);

private:
    void commitRow(int row);
    void setScript(std::vector<jl::ScriptAction> script, const QString& text);

    Document* doc_;
    QTableWidget* table_;
};

}  // namespace jl::ui
