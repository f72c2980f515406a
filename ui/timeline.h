// The timeline: the recorded span, the frame on screen and the events as
// marks; pressing or dragging on it scrubs.
#pragma once

#include "jl/sim/frame.h"

#include <QWidget>

#include <memory>
#include <vector>

namespace jl::ui {

class Timeline : public QWidget {
    Q_OBJECT
public:
    explicit Timeline(QWidget* parent = nullptr);
    void setDuration(double seconds);  // the scene's suggested length
    void setState(double cursor, double recorded, std::shared_ptr<const std::vector<jl::Event>> events);
    QSize sizeHint() const override { return {600, 44}; }

signals:
    void seekRequested(double time);

protected:
    void paintEvent(QPaintEvent*) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;

private:
    double span() const;
    double xOf(double t) const;
    double timeAt(int x) const;
    QRectF track() const;

    double duration_ = 5, cursor_ = 0, recorded_ = 0;
    std::shared_ptr<const std::vector<jl::Event>> events_;
};

}  // namespace jl::ui
