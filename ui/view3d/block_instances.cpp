#include "ui/view3d/block_instances.h"

#include "ui/view3d/instance_upload.h"
#include "ui/view3d/shader_material.h"

#include <QVector4D>
#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DCore/QGeometry>
#include <Qt3DRender/QGeometryRenderer>
#include <Qt3DRender/QMaterial>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

namespace jl::ui {

namespace {
// Per instance: pose (x, y, angle, z), size (across, along, out, highlight), colour (rgba).
constexpr int kInstanceFloats = 12;

// 36 vertices of a unit cube, position and outward normal interleaved.
QByteArray unitCube() {
    const std::array<std::array<float, 3>, 6> normals = {
        {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}}};
    QByteArray data;
    data.reserve(36 * 6 * sizeof(float));
    auto push = [&data](float x) { data.append(reinterpret_cast<const char*>(&x), sizeof x); };
    for (const auto& n : normals) {
        // Two axes spanning the face, ordered so the triangles wind counter-clockwise
        // seen from outside (Qt3D culls back faces by default).
        std::array<float, 3> u{n[2], n[0], n[1]}, v{n[1], n[2], n[0]};
        const std::array<float, 3> uxv{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
        if (uxv[0] * n[0] + uxv[1] * n[1] + uxv[2] * n[2] < 0) std::swap(u, v);
        const float corners[6][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, -1}, {1, 1}, {-1, 1}};
        for (const auto& c : corners) {
            for (int k = 0; k < 3; ++k) push(0.5f * (n[size_t(k)] + c[0] * u[size_t(k)] + c[1] * v[size_t(k)]));
            for (int k = 0; k < 3; ++k) push(n[size_t(k)]);
        }
    }
    return data;
}
}  // namespace

BlockInstances::BlockInstances(Qt3DCore::QNode* parent) : Qt3DCore::QEntity(parent) {
    auto* geometry = new Qt3DCore::QGeometry(this);
    auto* vertices = new Qt3DCore::QBuffer(geometry);
    vertices->setData(unitCube());
    const uint stride = 6 * sizeof(float);
    geometry->addAttribute(new Qt3DCore::QAttribute(vertices, Qt3DCore::QAttribute::defaultPositionAttributeName(),
                                                    Qt3DCore::QAttribute::Float, 3, 36, 0, stride));
    geometry->addAttribute(new Qt3DCore::QAttribute(vertices, Qt3DCore::QAttribute::defaultNormalAttributeName(),
                                                    Qt3DCore::QAttribute::Float, 3, 36, 3 * sizeof(float), stride));

    instances_ = new Qt3DCore::QBuffer(geometry);
    instances_->setUsage(Qt3DCore::QBuffer::StreamDraw);
    const char* names[] = {"blockPose", "blockSize", "blockColor"};
    for (int i = 0; i < 3; ++i) {
        auto* a = new Qt3DCore::QAttribute(instances_, names[i], Qt3DCore::QAttribute::Float, 4, 0,
                                           uint(4 * i * sizeof(float)), kInstanceFloats * sizeof(float));
        a->setDivisor(1);
        geometry->addAttribute(a);
        instanceAttributes_.push_back(a);
    }

    renderer_ = new Qt3DRender::QGeometryRenderer(this);
    renderer_->setGeometry(geometry);
    renderer_->setPrimitiveType(Qt3DRender::QGeometryRenderer::Triangles);
    renderer_->setVertexCount(36);
    renderer_->setInstanceCount(0);
    addComponent(renderer_);
    addComponent(shaderMaterial("blocks", this));
}

void BlockInstances::setShapes(std::vector<BlockShape> shapes) { shapes_ = std::move(shapes); }

void BlockInstances::showFrame(const jl::Frame& frame, int grabbed, const std::vector<int>& pointedAt) {
    const size_t n = std::min(frame.poses.size(), shapes_.size());
    all_.resize(n * kInstanceFloats);
    marked_.assign(n, false);
    float* f = all_.data();
    for (size_t i = 0; i < n; ++i, f += kInstanceFloats) {
        const jl::Pose& p = frame.poses[i];
        const BlockShape& s = shapes_[i];
        const bool held = i < frame.held.size() && frame.held[i];
        // Held blocks are a shade darker: the hand has them.
        const float shade = held ? 0.8f : 1.0f;
        const bool pointed = std::find(pointedAt.begin(), pointedAt.end(), int(i)) != pointedAt.end();
        const float hi = int(i) == grabbed ? 1.0f : pointed ? 0.85f : 0.0f;
        marked_[i] = held || hi > 0;
        const float values[kInstanceFloats] = {float(p.position.x()),
                                               float(p.position.y()),
                                               float(p.angle),
                                               0.0f,
                                               s.across,
                                               s.along,
                                               s.out,
                                               hi,
                                               float(s.color.redF()) * shade,
                                               float(s.color.greenF()) * shade,
                                               float(s.color.blueF()) * shade,
                                               1.0f};
        std::copy(std::begin(values), std::end(values), f);
    }
    upload();
}

void BlockInstances::setView(const QMatrix4x4& viewProjection, QSize pixels) {
    if (viewProjection == viewProjection_ && pixels == pixels_) return;
    viewProjection_ = viewProjection;
    pixels_ = pixels;
    if (!all_.empty()) upload();
}

// The instances to draw: a block is left out when its centre is within a
// pixel of the last block drawn and each of its sides spans under a pixel
// (the shader draws a block at least 1.5 pixels across, so the one drawn
// covers it). Nothing is left out before the view's size is known.
void BlockInstances::upload() {
    const size_t n = marked_.size();
    drawnData_.clear();
    const QPointF half(pixels_.width() / 2.0, pixels_.height() / 2.0);
    // Where a point of the world is drawn, in pixels from the view's centre; none at or behind the eye.
    const auto pixel = [&](float x, float y, float z) -> std::optional<QPointF> {
        const QVector4D c = viewProjection_ * QVector4D(x, y, z, 1);
        if (c.w() <= 0) return std::nullopt;
        return QPointF(c.x() / c.w() * half.x(), c.y() / c.w() * half.y());
    };
    const auto apart = [](QPointF a, QPointF b) { return QPointF::dotProduct(a - b, a - b) >= 1.0; };
    std::optional<QPointF> last;
    for (size_t i = 0; i < n; ++i) {
        const float* f = all_.data() + i * kInstanceFloats;
        const std::optional<QPointF> at = pixels_.isEmpty() ? std::nullopt : pixel(f[0], f[1], f[3]);
        bool draw = marked_[i] || i + 1 == n || !at || !last || apart(*at, *last);
        const float side = std::max({f[4], f[5], f[6]});
        for (int axis = 0; axis < 3 && !draw; ++axis) {
            const auto reach =
                pixel(f[0] + (axis == 0 ? side : 0), f[1] + (axis == 1 ? side : 0), f[3] + (axis == 2 ? side : 0));
            draw = !reach || apart(*reach, *at);
        }
        if (!draw) continue;
        if (at) last = at;
        drawnData_.insert(drawnData_.end(), f, f + kInstanceFloats);
    }
    drawn_ = uploadInstances(instances_, instanceAttributes_, renderer_, drawnData_, kInstanceFloats);
}

}  // namespace jl::ui
