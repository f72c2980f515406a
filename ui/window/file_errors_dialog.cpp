#include "ui/window/file_errors_dialog.h"

#include <QClipboard>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QGuiApplication>
#include <QLabel>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QVBoxLayout>

namespace jl::ui {

namespace {
// A problem in the file the dialog names: its place in that file and what
// is wrong. The file's full path in front of every row pushed the message
// past the dialog's edge.
QString row(const QString& path, const jl::Diagnostic& d) {
    const QString file = QString::fromStdString(d.file);
    const QString message = QString::fromStdString(d.message);
    if (QFileInfo(file).absoluteFilePath() != QFileInfo(path).absoluteFilePath())
        return QString::fromStdString(d.format());
    if (d.line <= 0) return message;
    return QString("%1:%2: %3").arg(d.line).arg(d.column).arg(message);
}
}  // namespace

FileErrorsDialog::FileErrorsDialog(const QString& path, const std::vector<jl::Diagnostic>& errors, QWidget* parent)
    : QDialog(parent) {
    setObjectName("fileErrors");
    setWindowTitle(tr("Could not open %1").arg(QFileInfo(path).fileName()));
    setAttribute(Qt::WA_DeleteOnClose);
    auto* box = new QVBoxLayout(this);
    auto* intro = new QLabel(tr("<b>%1</b> was not opened: it has %n problem(s). The scene you had open is unchanged.",
                                nullptr, int(errors.size()))
                                 .arg(path.toHtmlEscaped()),
                             this);
    intro->setWordWrap(true);
    box->addWidget(intro);
    for (const jl::Diagnostic& d : errors) {
        lines_ << row(path, d);
        located_ << QString::fromStdString(d.format());
    }
    problems_ = new QPlainTextEdit(this);
    problems_->setObjectName("problems");
    problems_->setReadOnly(true);
    problems_->setLineWrapMode(QPlainTextEdit::WidgetWidth);
    problems_->setWordWrapMode(QTextOption::WrapAtWordBoundaryOrAnywhere);
    // A blank line apart: a wrapped problem still reads as one.
    problems_->setPlainText(lines_.join("\n\n"));
    box->addWidget(problems_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto* copy = buttons->addButton(tr("Copy"), QDialogButtonBox::ActionRole);
    connect(copy, &QPushButton::clicked, this, [this] { QGuiApplication::clipboard()->setText(located_.join('\n')); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    box->addWidget(buttons);
    resize(720, 320);
}

int FileErrorsDialog::errorCount() const { return int(lines_.size()); }

QStringList FileErrorsDialog::lines() const { return lines_; }

}  // namespace jl::ui
