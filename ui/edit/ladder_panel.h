// The Ladder dock: blocks, ribbons and hinges of the open scene, every edit
// undoable; beside the block count, how far the first ripple travels.
#pragma once

#include "ui/edit/document.h"

#include <QWidget>

class QCheckBox;
class QLineEdit;
class QPushButton;

namespace jl::ui {

class BlockOverrides;
class ReachEstimate;
class ValueForm;

class LadderPanel : public QWidget {
    Q_OBJECT
public:
    LadderPanel(Document* doc, QWidget* parent = nullptr);
    void refresh();
    ReachEstimate* reachEstimate() const { return estimate_; }

signals:
    void designMapRequested();

private:
    QPushButton* colorButton(const QString& key, const QString& tip);
    void editLadder(const QString& key, const QString& text, const std::function<void(jl::LadderSpec&)>& edit);

    Document* doc_;
    ValueForm* form_;
    QPushButton* blockColor_;
    QPushButton* ribbonColor_;
    QPushButton* centralRibbonColor_;
    QCheckBox* ribbonsVisible_;
    QLineEdit* held_;
    BlockOverrides* overrides_;
    ReachEstimate* estimate_;
};

}  // namespace jl::ui
