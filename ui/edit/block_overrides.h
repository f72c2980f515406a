// The block list of the Ladder dock: per-block thickness, width, density,
// mass and colour that differ from the ladder's; an empty cell keeps the ladder's value.
#pragma once

#include "ui/edit/document.h"

#include <QWidget>

class QTableWidget;

namespace jl::ui {

class BlockOverrides : public QWidget {
    Q_OBJECT
public:
    BlockOverrides(Document* doc, QWidget* parent = nullptr);
    void refresh();

private:
    void commitRow(int row);
    void setOverrides(std::vector<jl::BlockOverride> overrides, const QString& text);

    Document* doc_;
    QTableWidget* table_;
};

}  // namespace jl::ui
