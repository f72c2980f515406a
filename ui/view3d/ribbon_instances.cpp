#include "ui/view3d/ribbon_instances.h"

#include "ui/view3d/instance_upload.h"
#include "ui/view3d/shader_material.h"

#include <QVector4D>
#include <Qt3DCore/QAttribute>
#include <Qt3DCore/QBuffer>
#include <Qt3DCore/QGeometry>
#include <Qt3DRender/QGeometryRenderer>
#include <Qt3DRender/QMaterial>
#include <Qt3DRender/QParameter>

#include <algorithm>
#include <array>

namespace jl::ui {

namespace {
constexpr int kPathPoints = 5;  // a ribbon as the engine lays it (docs/model.md section 8.8)
constexpr int kSegments = kPathPoints - 1;
constexpr int kInstanceFloats = 2 * kPathPoints;

// A quad per segment and lane, each vertex as (segment, end, edge, lane):
// the corners (p, -w), (q, -w), (q, +w), (p, +w) of the strip over the
// segment from p to q, in two triangles.
QByteArray ribbonMesh(const std::vector<float>& lanes) {
    QByteArray data;
    auto push = [&data](float x) { data.append(reinterpret_cast<const char*>(&x), sizeof x); };
    const float corners[6][2] = {{0, -1}, {1, -1}, {1, 1}, {0, -1}, {1, 1}, {0, 1}};
    for (int k = 0; k < kSegments; ++k)
        for (const float lane : lanes)
            for (const auto& c : corners)
                for (const float x : {float(k), c[0], c[1], lane}) push(x);
    return data;
}
}  // namespace

RibbonInstances::RibbonInstances(Qt3DCore::QNode* parent, bool central) : Qt3DCore::QEntity(parent), central_(central) {
    auto* geometry = new Qt3DCore::QGeometry(this);
    auto* mesh = new Qt3DCore::QBuffer(geometry);
    const std::vector<float> lanes = central ? std::vector<float>{0} : std::vector<float>{-1, 1};
    mesh->setData(ribbonMesh(lanes));
    const uint vertices = uint(kSegments * lanes.size() * 6);
    auto* corners =
        new Qt3DCore::QAttribute(mesh, "ribbonCorner", Qt3DCore::QAttribute::Float, 4, vertices, 0, 4 * sizeof(float));
    geometry->addAttribute(corners);
    // Qt3D computes bounds from a position attribute and warns at every frame
    // if there is none. Where the strips lie is the shader's to say; the view
    // does not cull by bounds, so those of the corners' numbers do.
    geometry->setBoundingVolumePositionAttribute(corners);

    instances_ = new Qt3DCore::QBuffer(geometry);
    instances_->setUsage(Qt3DCore::QBuffer::StreamDraw);
    const std::pair<const char*, uint> attributes[] = {{"ribbonFrom", 4}, {"ribbonOn", 4}, {"ribbonTo", 2}};
    uint offset = 0;
    for (const auto& [name, size] : attributes) {
        auto* a = new Qt3DCore::QAttribute(instances_, name, Qt3DCore::QAttribute::Float, size, 0,
                                           uint(offset * sizeof(float)), kInstanceFloats * sizeof(float));
        a->setDivisor(1);
        geometry->addAttribute(a);
        instanceAttributes_.push_back(a);
        offset += size;
    }

    renderer_ = new Qt3DRender::QGeometryRenderer(this);
    renderer_->setGeometry(geometry);
    renderer_->setPrimitiveType(Qt3DRender::QGeometryRenderer::Triangles);
    renderer_->setVertexCount(int(vertices));
    renderer_->setInstanceCount(0);
    addComponent(renderer_);
    auto* material = shaderMaterial("ribbons", this, ShaderOptions::TwoSidedOnAFace, "strip");
    color_ = new Qt3DRender::QParameter("stripColor", QColor(Qt::white), material);
    halfWidth_ = new Qt3DRender::QParameter("halfWidth", 0.0f, material);
    laneOffset_ = new Qt3DRender::QParameter("laneOffset", 0.0f, material);
    for (auto* p : {color_, halfWidth_, laneOffset_}) material->addParameter(p);
    material->addParameter(new Qt3DRender::QParameter("unlit", 0.0f, material));
    addComponent(material);
}

// The outer pair is drawn at |z| = half width - inset - half ribbon width,
// the middle ribbon at z = 0.
void RibbonInstances::setSpec(const jl::RibbonSpec& spec, double blockWidth) {
    const jl::Color c = central_ ? spec.centralColor : spec.color;
    color_->setValue(QColor(c.r, c.g, c.b));
    const double width = central_ ? spec.centralWidth : spec.width;
    halfWidth_->setValue(float(width / 2));
    laneOffset_->setValue(central_ ? 0.0f : float(std::max(blockWidth / 2 - spec.inset - width / 2, width / 2)));
}

void RibbonInstances::showRibbons(const std::vector<jl::RibbonFrame>& ribbons) {
    data_.clear();
    for (const jl::RibbonFrame& r : ribbons) {
        if (!r.visible || r.central != central_) continue;
        const size_t n = r.points.size();
        // A longer path goes as several instances, each from the last point
        // of the one before; a shorter one repeats its last point.
        for (size_t start = 0; start + 1 < n; start += kSegments)
            for (size_t i = 0; i < size_t(kPathPoints); ++i) {
                const jl::Vec2& p = r.points[std::min(start + i, n - 1)];
                data_.insert(data_.end(), {float(p.x()), float(p.y())});
            }
    }
    drawn_ = uploadInstances(instances_, instanceAttributes_, renderer_, data_, kInstanceFloats);
}

// A point is in the view when clip space's -w <= x, y <= w and z >= -w:
// the planes w + x, w - x, w + y, w - y and w + z (rows of the matrix),
// each scaled to give metres from it.
BlockSpan blocksNearView(const QMatrix4x4& viewProjection, std::span<const jl::Pose> poses, float reach) {
    const QVector4D w = viewProjection.row(3);
    std::array<QVector4D, 5> planes = {w + viewProjection.row(0), w - viewProjection.row(0), w + viewProjection.row(1),
                                       w - viewProjection.row(1), w + viewProjection.row(2)};
    for (QVector4D& p : planes) p /= std::max(p.toVector3D().length(), 1e-12f);
    BlockSpan span;
    span.first = int(poses.size());
    for (size_t i = 0; i < poses.size(); ++i) {
        const QVector4D c(float(poses[i].position.x()), float(poses[i].position.y()), 0, 1);
        const bool near = std::all_of(planes.begin(), planes.end(),
                                      [&](const QVector4D& p) { return QVector4D::dotProduct(p, c) >= -reach; });
        if (!near) continue;
        span.first = std::min(span.first, int(i));
        span.last = int(i);
    }
    if (span.last < 0) span.first = 0;
    return span;
}

}  // namespace jl::ui
