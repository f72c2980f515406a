#include "ui/view3d/scale_mark.h"

#include "ui/view3d/round_length.h"
#include "ui/view3d/strip_entity.h"
#include "ui/view3d/view_camera.h"

#include <QFont>
#include <QQuaternion>
#include <Qt3DCore/QTransform>
#include <Qt3DExtras/QText2DEntity>

#include <cmath>
#include <numbers>

namespace jl::ui {

namespace {
constexpr double kLeastPixels = 90;  // the bar is the shortest round length at least this long
constexpr float kFontPoints = 10;    // the label's glyphs, in its own units (scaled to the view)
constexpr float kPixelsWide = 3;     // the bar's width
constexpr float kToRight = 0.72f;    // of the view's half width, right of the point looked at
}  // namespace

ScaleMark::ScaleMark(Qt3DCore::QNode* parent) : Qt3DCore::QEntity(parent) {
    bar_ = new StripEntity(this, true);
    bar_->setColor(QColor(40, 40, 48));
    label_ = new Qt3DExtras::QText2DEntity(this);
    QFont font;
    font.setPointSizeF(kFontPoints);
    label_->setFont(font);
    label_->setColor(QColor(30, 30, 36));
    label_->setWidth(8 * kFontPoints);
    label_->setHeight(2 * kFontPoints);
    labelAt_ = new Qt3DCore::QTransform(label_);
    label_->addComponent(labelAt_);
}

void ScaleMark::place(const ViewCamera& camera, int pixelsHigh, float aspect) {
    if (pixelsHigh <= 0) return;
    // Metres per pixel at the depth of the point looked at.
    const float halfHeight = camera.distance() * std::tan(float(std::numbers::pi / 180) * ViewCamera::kFieldOfView / 2);
    const double perPixel = 2.0 * halfHeight / pixelsHigh;
    length_ = gridCell(1 / perPixel, kLeastPixels);
    // The screen's right and up, at the target, facing the eye.
    const QVector3D back = (camera.eye() - camera.target()).normalized();
    const QVector3D right = QVector3D::crossProduct({0, 1, 0}, back).normalized();
    const QVector3D up = QVector3D::crossProduct(back, right);
    const float len = float(length_), half = float(perPixel) * kPixelsWide / 2;
    top_ = camera.target() + right * (kToRight * halfHeight * aspect) + up * (len / 2);
    bottom_ = top_ - up * len;
    const QVector3D bottom = bottom_;
    bar_->clear();
    bar_->addQuad(top_ - right * half, bottom - right * half, bottom + right * half, top_ + right * half, back);
    // Ticks across both ends, three times as wide: where the length starts and stops.
    for (const QVector3D& end : {top_, bottom})
        bar_->addQuad(end - right * 3 * half - up * half, end + right * 3 * half - up * half,
                      end + right * 3 * half + up * half, end - right * 3 * half + up * half, back);
    bar_->commit();
    // The label under the bar, its glyphs about 14 pixels tall.
    const float scale = float(perPixel) * 14 / kFontPoints;
    label_->setText(lengthText(length_));
    labelAt_->setRotation(QQuaternion::fromAxes(right, up, back));
    labelAt_->setScale(scale);
    labelAt_->setTranslation(bottom - right * (2 * kFontPoints * scale) - up * (2.2f * kFontPoints * scale));
}

}  // namespace jl::ui
