#include "ui/view3d/room.h"

#include "ui/view3d/shader_material.h"

#include <QColor>
#include <QVector3D>
#include <Qt3DCore/QTransform>
#include <Qt3DExtras/QCuboidMesh>
#include <Qt3DRender/QMaterial>
#include <Qt3DRender/QParameter>

namespace jl::ui {

namespace {
// Dimensions for a ladder reaching 0.5 m below the hand; larger ladders scale the room.
constexpr float kTableTopBelowLadder = 0.12f;  // m between the bottom block and the table
constexpr float kTableHeight = 0.74f, kTableWidth = 1.4f, kTableDepth = 0.7f, kTop = 0.035f;
constexpr float kRoomWidth = 6.0f, kRoomDepth = 5.0f, kRoomHeight = 3.0f;

void box(Qt3DCore::QNode* parent, QVector3D centre, QVector3D size, QColor color) {
    auto* e = new Qt3DCore::QEntity(parent);
    auto* mesh = new Qt3DExtras::QCuboidMesh(e);
    mesh->setXExtent(size.x());
    mesh->setYExtent(size.y());
    mesh->setZExtent(size.z());
    auto* t = new Qt3DCore::QTransform(e);
    t->setTranslation(centre);
    auto* m = shaderMaterial("room", e);
    m->addParameter(new Qt3DRender::QParameter("surfaceColor", color, m));
    e->addComponent(mesh);
    e->addComponent(t);
    e->addComponent(m);
}
}  // namespace

Room::Room(Qt3DCore::QNode* parent) : Qt3DCore::QEntity(parent) {
    transform_ = new Qt3DCore::QTransform(this);
    addComponent(transform_);
    // Built for a unit room whose table top is at y = 0, centred under the ladder.
    const float floorY = -kTableHeight;
    // A slate bench top: the wood stands out.
    box(this, {0, -kTop / 2, 0}, {kTableWidth, kTop, kTableDepth}, QColor(118, 126, 138));
    for (float sx : {-1.f, 1.f})
        for (float sz : {-1.f, 1.f})
            box(this, {sx * (kTableWidth / 2 - 0.06f), floorY / 2 - kTop / 2, sz * (kTableDepth / 2 - 0.06f)},
                {0.05f, kTableHeight - kTop, 0.05f}, QColor(60, 64, 72));
    box(this, {0, floorY - 0.02f, 0}, {kRoomWidth, 0.04f, kRoomDepth}, QColor(178, 172, 160));
    box(this, {0, floorY + kRoomHeight / 2, -kRoomDepth / 2}, {kRoomWidth, kRoomHeight, 0.05f}, QColor(196, 200, 208));
    box(this, {-kRoomWidth / 2, floorY + kRoomHeight / 2, 0}, {0.05f, kRoomHeight, kRoomDepth}, QColor(186, 190, 199));
    box(this, {kRoomWidth / 2, floorY + kRoomHeight / 2, 0}, {0.05f, kRoomHeight, kRoomDepth}, QColor(186, 190, 199));
    // A skirting board where wall meets floor, so the room reads as a room.
    box(this, {0, floorY + 0.05f, -kRoomDepth / 2 + 0.03f}, {kRoomWidth, 0.1f, 0.02f}, QColor(245, 245, 245));

    fitTo(0.36);
}

void Room::fitTo(double extent, std::optional<double> tableTop) {
    const float scale = std::max(1.0f, float(extent) / 1.2f);
    transform_->setScale(scale);
    transform_->setTranslation({0, tableTop ? float(*tableTop) : -float(extent) - kTableTopBelowLadder * scale, 0});
}

}  // namespace jl::ui
