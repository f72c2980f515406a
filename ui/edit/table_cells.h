// Editable tables of the docks: writing a cell in place (a table refreshed
// from inside its own change signal must not delete the item that sent it),
// and the add/remove buttons under a table.
#pragma once

#include <QBoxLayout>
#include <QPushButton>
#include <QTableWidget>

#include <utility>

namespace jl::ui {

inline void setCellText(QTableWidget* table, int row, int column, const QString& text) {
    if (QTableWidgetItem* item = table->item(row, column))
        item->setText(text);
    else
        table->setItem(row, column, new QTableWidgetItem(text));
}

inline std::pair<QPushButton*, QPushButton*> addRowButtons(QWidget* parent, QBoxLayout* box, const QString& addText,
                                                           const QString& addTip, const QString& removeTip) {
    auto* buttons = new QHBoxLayout;
    auto* add = new QPushButton(addText, parent);
    add->setToolTip(addTip);
    auto* remove = new QPushButton(QObject::tr("Remove"), parent);
    remove->setToolTip(removeTip);
    buttons->addWidget(add);
    buttons->addWidget(remove);
    buttons->addStretch(1);
    box->addLayout(buttons);
    return {add, remove};
}

}  // namespace jl::ui
