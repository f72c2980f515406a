#include "ui/view3d/view_capture.h"

#include "ui/view3d/ladder_view.h"

#include <QEventLoop>
#include <QTimer>
#include <Qt3DRender/QRenderCapture>

#include <memory>

namespace jl::ui {

QImage captureView(LadderView* view, int timeoutMs) {
    QImage image;
    // A capture may come back with a frame drawn just before the latest
    // changes reached the renderer; the second one in a row is drawn after them.
    for (int i = 0; i < 2; ++i) {
        std::unique_ptr<Qt3DRender::QRenderCaptureReply> reply(view->capture()->requestCapture());
        QEventLoop wait;
        QTimer::singleShot(timeoutMs, &wait, &QEventLoop::quit);
        QObject::connect(reply.get(), &Qt3DRender::QRenderCaptureReply::completed, &wait, &QEventLoop::quit);
        if (!reply->isComplete()) wait.exec();
        if (!reply->isComplete()) return {};
        image = reply->image();
    }
    // Opaque: the clear colour's alpha would make a see-through picture on a slide.
    return image.convertToFormat(QImage::Format_RGB32);
}

FramePainter viewPainter(LadderView* view) {
    return [view](const jl::Frame& frame) {
        view->showFrame(frame);
        return captureView(view);
    };
}

}  // namespace jl::ui
