#include "ui/view3d/strip_entity.h"

#include "ui/view3d/shader_material.h"
#include "ui/view3d/spring_coil.h"

#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DCore/QGeometry>
#include <Qt3DRender/QGeometryRenderer>
#include <Qt3DRender/QMaterial>
#include <Qt3DRender/QParameter>

namespace jl::ui {

StripEntity::StripEntity(Qt3DCore::QNode* parent, bool unlit) : Qt3DCore::QEntity(parent) {
    auto* geometry = new Qt3DCore::QGeometry(this);
    buffer_ = new Qt3DCore::QBuffer(geometry);
    buffer_->setUsage(Qt3DCore::QBuffer::StreamDraw);
    const uint stride = 6 * sizeof(float);
    attributes_ = {new Qt3DCore::QAttribute(buffer_, Qt3DCore::QAttribute::defaultPositionAttributeName(),
                                            Qt3DCore::QAttribute::Float, 3, 0, 0, stride),
                   new Qt3DCore::QAttribute(buffer_, Qt3DCore::QAttribute::defaultNormalAttributeName(),
                                            Qt3DCore::QAttribute::Float, 3, 0, 3 * sizeof(float), stride)};
    for (auto* a : attributes_) geometry->addAttribute(a);
    renderer_ = new Qt3DRender::QGeometryRenderer(this);
    renderer_->setGeometry(geometry);
    renderer_->setPrimitiveType(Qt3DRender::QGeometryRenderer::Triangles);
    renderer_->setVertexCount(0);
    addComponent(renderer_);
    auto* material = shaderMaterial("strip", this, unlit ? ShaderOptions::TwoSided : ShaderOptions::TwoSidedOnAFace);
    color_ = new Qt3DRender::QParameter("stripColor", QColor(Qt::white), material);
    material->addParameter(color_);
    material->addParameter(new Qt3DRender::QParameter("unlit", unlit ? 1.0f : 0.0f, material));
    addComponent(material);
}

void StripEntity::setColor(const QColor& c) { color_->setValue(c); }

void StripEntity::addQuad(const QVector3D& a, const QVector3D& b, const QVector3D& c, const QVector3D& d,
                          const QVector3D& n) {
    for (const QVector3D* p : {&a, &b, &c, &a, &c, &d})
        data_.insert(data_.end(), {p->x(), p->y(), p->z(), n.x(), n.y(), n.z()});
}

void StripEntity::commit() {
    const uint vertices = uint(data_.size() / 6);
    buffer_->setData(QByteArray(reinterpret_cast<const char*>(data_.data()), int(data_.size() * sizeof(float))));
    for (auto* a : attributes_) a->setCount(vertices);
    renderer_->setVertexCount(int(vertices));
}

void buildDragLine(StripEntity& strip, const jl::Frame& frame, float z, float width) {
    // No drag and none drawn: no upload of an empty strip at every frame.
    if (!frame.dragging && strip.empty()) return;
    strip.clear();
    if (frame.dragging) {
        const jl::Vec2 a = frame.dragFrom, b = frame.dragTo;
        jl::Vec2 side = jl::perp(b - a);
        side = side.norm() > 0 ? jl::Vec2(side.normalized() * (width / 2)) : jl::Vec2(width / 2, 0);
        const QVector3D n(0, 0, 1);
        auto v = [z](const jl::Vec2& p) { return QVector3D(float(p.x()), float(p.y()), z); };
        strip.addQuad(v(a - side), v(b - side), v(b + side), v(a + side), n);
        // A small square at each end: where it is held, and where the hand is.
        for (const jl::Vec2& c : {a, b}) {
            const double s = width * 2;
            strip.addQuad(v(c + jl::Vec2(-s, -s)), v(c + jl::Vec2(s, -s)), v(c + jl::Vec2(s, s)),
                          v(c + jl::Vec2(-s, s)), n);
        }
    }
    strip.commit();
}

void buildSprings(StripEntity& strip, const jl::Frame& frame, float z, float width) {
    // A ladder has none: no upload of an empty strip at every frame.
    if (frame.springs.empty() && strip.empty()) return;
    strip.clear();
    const QVector3D n(0, 0, 1);
    auto v = [z](const jl::Vec2& p) { return QVector3D(float(p.x()), float(p.y()), z); };
    for (const auto& [a, b] : frame.springs) {
        const std::vector<jl::Vec2> points = springCoil(a, b);
        for (size_t i = 0; i + 1 < points.size(); ++i) {
            const jl::Vec2 d = points[i + 1] - points[i];
            if (!(d.norm() > 0)) continue;
            const jl::Vec2 side = jl::perp(d.normalized()) * (width / 2);
            strip.addQuad(v(points[i] - side), v(points[i + 1] - side), v(points[i + 1] + side), v(points[i] + side),
                          n);
        }
    }
    strip.commit();
}

}  // namespace jl::ui
