#include "ui/file_errors_dialog.h"

#include <QClipboard>
#include <QDialogButtonBox>
#include <QFileInfo>
#include <QFontDatabase>
#include <QGuiApplication>
#include <QLabel>
#include <QListWidget>
#include <QPushButton>
#include <QVBoxLayout>

namespace jl::ui {

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
    list_ = new QListWidget(this);
    list_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
    for (const jl::Diagnostic& d : errors) list_->addItem(QString::fromStdString(d.format()));
    box->addWidget(list_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    auto* copy = buttons->addButton(tr("Copy"), QDialogButtonBox::ActionRole);
    connect(copy, &QPushButton::clicked, this, [this] { QGuiApplication::clipboard()->setText(lines().join('\n')); });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    box->addWidget(buttons);
    resize(720, 320);
}

int FileErrorsDialog::errorCount() const { return list_->count(); }

QStringList FileErrorsDialog::lines() const {
    QStringList out;
    for (int i = 0; i < list_->count(); ++i) out << list_->item(i)->text();
    return out;
}

}  // namespace jl::ui
