// Asks what to export as pictures or a video: the time range, pictures per
// second, the picture size and where to put them.
#pragma once

#include "ui/teaching/exporter.h"

#include <QDialog>

class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QSpinBox;

namespace jl::ui {

class SequenceDialog : public QDialog {
    Q_OBJECT
public:
    enum class Kind { Pictures, Video };
    // `duration`: the recorded run, the largest sensible end.
    SequenceDialog(Kind kind, double from, double to, double duration, QWidget* parent = nullptr);

    // The request (without a painter) and, for a video, its file.
    SequenceRequest request() const;
    QString target() const;

private:
    void browse();
    void updateCount();

    Kind kind_;
    QDoubleSpinBox* from_;
    QDoubleSpinBox* to_;
    QDoubleSpinBox* fps_;
    QSpinBox* width_;
    QSpinBox* height_;
    QLineEdit* target_;
    QLabel* count_;
};

}  // namespace jl::ui
