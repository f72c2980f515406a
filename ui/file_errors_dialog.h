// Why a scene file could not be opened: every problem with file, line and column.
#pragma once

#include "jl/base/diagnostic.h"

#include <QDialog>

#include <vector>

class QListWidget;

namespace jl::ui {

class FileErrorsDialog : public QDialog {
    Q_OBJECT
public:
    FileErrorsDialog(const QString& path, const std::vector<jl::Diagnostic>& errors, QWidget* parent);
    int errorCount() const;
    QStringList lines() const;

private:
    QListWidget* list_;
};

}  // namespace jl::ui
