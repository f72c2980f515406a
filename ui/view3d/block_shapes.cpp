#include "ui/view3d/block_shapes.h"

#include "jl/scene/ladder_blocks.h"

#include <algorithm>
#include <cmath>

namespace jl::ui {

namespace {
QColor toQColor(const jl::Color& c) { return QColor(c.r, c.g, c.b); }
constexpr float kParticleSize = 0.008f;  // m, drawn as a small cube
}  // namespace

std::vector<BlockShape> blockShapes(const jl::Scene& scene) {
    std::vector<BlockShape> out;
    if (scene.ladder) {
        for (const jl::BlockSpec& b : jl::ladderBlocks(*scene.ladder))
            out.push_back({float(b.thickness), float(b.length), float(b.width), toQColor(b.color)});
    }
    for (const jl::BodySpec& b : scene.bodies)
        out.push_back({float(b.thickness), float(b.length), float(b.width), toQColor(b.color)});
    for (size_t i = 0; i < scene.particles.size(); ++i)
        out.push_back({kParticleSize, kParticleSize, kParticleSize, QColor(70, 70, 80)});
    return out;
}

double ladderExtent(const jl::Scene& scene) {
    double h = 0;
    if (scene.ladder) h = scene.ladder->blocks * scene.ladder->block.length;
    for (const jl::BodySpec& b : scene.bodies) h = std::max(h, std::abs(b.position[1]) + b.length);
    for (const jl::ParticleSpec& p : scene.particles) h = std::max(h, std::abs(p.position[1]));
    // Bodies pinned to the world can hang from it as far as they reach end to
    // end: the falling chain, laid out level, swings down 0.6 m through where
    // a table under its start would stand.
    const auto onWorld = [](const jl::PointRef& r) { return r.on == "world"; };
    if (std::any_of(scene.pins.begin(), scene.pins.end(),
                    [&](const jl::PinSpec& p) { return onWorld(p.a) || onWorld(p.b); })) {
        double reach = 0;
        for (const jl::BodySpec& b : scene.bodies) reach += std::hypot(b.length, b.thickness);
        h = std::max(h, reach);
    }
    return std::max(h, 0.1);
}

}  // namespace jl::ui
