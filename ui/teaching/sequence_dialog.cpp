#include "ui/teaching/sequence_dialog.h"

#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QSpinBox>

namespace jl::ui {

SequenceDialog::SequenceDialog(Kind kind, double from, double to, double duration, QWidget* parent)
    : QDialog(parent), kind_(kind) {
    setWindowTitle(kind == Kind::Video ? tr("Export a video") : tr("Export pictures"));
    auto* form = new QFormLayout(this);
    auto seconds = [this, duration](double value) {
        auto* s = new QDoubleSpinBox(this);
        s->setRange(0, std::max(duration, 0.01) * 4);
        s->setDecimals(3);
        s->setSingleStep(0.1);
        s->setSuffix(" s");
        s->setValue(value);
        return s;
    };
    from_ = seconds(from);
    to_ = seconds(to);
    fps_ = new QDoubleSpinBox(this);
    fps_->setRange(1, 1000);
    fps_->setValue(30);
    fps_->setToolTip(
        tr("Pictures per simulated second. A video plays them at this rate too: "
           "more pictures per second than 30 make a slow-motion video."));
    width_ = new QSpinBox(this);
    height_ = new QSpinBox(this);
    for (QSpinBox* s : {width_, height_}) {
        s->setRange(64, 7680);
        s->setSuffix(" px");
    }
    width_->setValue(1280);
    height_->setValue(720);
    target_ = new QLineEdit(
        kind == Kind::Video ? QDir::home().filePath("ladder.mp4") : QDir::home().filePath("ladder-frames"), this);
    auto* browse = new QPushButton(tr("Browse..."), this);
    auto* where = new QHBoxLayout;
    where->addWidget(target_, 1);
    where->addWidget(browse);
    auto* size = new QHBoxLayout;
    size->addWidget(width_);
    size->addWidget(new QLabel(QStringLiteral("×"), this));
    size->addWidget(height_);
    count_ = new QLabel(this);
    form->addRow(tr("From"), from_);
    form->addRow(tr("To"), to_);
    form->addRow(tr("Pictures per second"), fps_);
    form->addRow(tr("Size"), size);
    form->addRow(kind == Kind::Video ? tr("Video file") : tr("Folder"), where);
    form->addRow(count_);
    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    form->addRow(buttons);
    connect(buttons, &QDialogButtonBox::accepted, this, &QDialog::accept);
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    connect(browse, &QPushButton::clicked, this, &SequenceDialog::browse);
    for (QDoubleSpinBox* s : {from_, to_, fps_})
        connect(s, &QDoubleSpinBox::valueChanged, this, &SequenceDialog::updateCount);
    updateCount();
}

void SequenceDialog::updateCount() {
    count_->setText(tr("%n picture(s)", nullptr, Exporter::frameCount(from_->value(), to_->value(), fps_->value())));
}

void SequenceDialog::browse() {
    const QString chosen =
        kind_ == Kind::Video
            ? QFileDialog::getSaveFileName(this, tr("Video file"), target_->text(), tr("MP4 video (*.mp4);;Any (*)"))
            : QFileDialog::getExistingDirectory(this, tr("Folder for the pictures"), target_->text());
    if (!chosen.isEmpty()) target_->setText(chosen);
}

SequenceRequest SequenceDialog::request() const {
    SequenceRequest r;
    r.from = from_->value();
    r.to = to_->value();
    r.fps = fps_->value();
    r.size = QSize(width_->value(), height_->value());
    if (kind_ == Kind::Pictures) r.directory = target_->text();
    return r;
}

QString SequenceDialog::target() const { return target_->text(); }

}  // namespace jl::ui
