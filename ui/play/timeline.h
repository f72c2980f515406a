// The timeline: the recorded span, the frame on screen and the events as
// marks; pressing or dragging on it scrubs, pressing on a mark shows that
// event's instant, and hovering one says what it was.
#pragma once

#include "jl/sim/frame.h"

#include <QColor>
#include <QRectF>
#include <QString>
#include <QWidget>

#include <memory>
#include <optional>
#include <utility>
#include <vector>

namespace jl::ui {

class Timeline : public QWidget {
    Q_OBJECT
public:
    explicit Timeline(QWidget* parent = nullptr);
    void setDuration(double seconds);  // the scene's suggested length
    void setState(double cursor, double recorded, std::shared_ptr<const std::vector<jl::Event>> events);
    // The stretch being looped (L ... L), drawn as a bar along the track's top; none: no loop.
    void setLoop(std::optional<std::pair<double, double>> loop);
    static inline const QColor kLoopColor{230, 150, 0};
    QSize sizeHint() const override;
    // The time labels under the track: their tick's x, their text and where
    // they are drawn (always inside the widget, whatever the type's size).
    struct Label {
        double tick = 0;
        QString text;
        QRectF box;
    };
    std::vector<Label> labels() const;
    // The event whose mark is nearest the window x, within a few pixels.
    const jl::Event* eventNear(double x) const;
    double xOf(double t) const;

signals:
    void seekRequested(double time);
    void instantRequested(double time);  // a press on an event's mark

protected:
    void paintEvent(QPaintEvent*) override;
    void changeEvent(QEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    bool event(QEvent* e) override;

private:
    double span() const;
    double timeAt(int x) const;
    QRectF track() const;
    QFont labelFont() const;

    double duration_ = 5, cursor_ = 0, recorded_ = 0;
    std::shared_ptr<const std::vector<jl::Event>> events_;
    std::optional<std::pair<double, double>> loop_;
};

}  // namespace jl::ui
