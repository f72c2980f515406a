// Why a scene file could not be opened: the file named once, then every
// problem as "line:column: message", wrapped to the dialog's width.
#pragma once

#include "jl/base/diagnostic.h"

#include <QDialog>

#include <vector>

class QPlainTextEdit;

namespace jl::ui {

class FileErrorsDialog : public QDialog {
    Q_OBJECT
public:
    FileErrorsDialog(const QString& path, const std::vector<jl::Diagnostic>& errors, QWidget* parent);
    int errorCount() const;
    QStringList lines() const;  // as shown, one per problem

private:
    QPlainTextEdit* problems_;
    QStringList lines_;
    QStringList located_;  // "file:line:column: message", what Copy copies (editors jump to it)
};

}  // namespace jl::ui
