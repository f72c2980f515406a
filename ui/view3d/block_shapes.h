// How each drawn thing of a frame looks: box size and colour per entry of
// Frame::poses, read once from the scene (frames carry only poses).
#pragma once

#include "jl/scene/scene.h"

#include <QColor>

#include <vector>

namespace jl::ui {

struct BlockShape {
    float across = 0, along = 0, out = 0;  // m: local x, local y, z
    QColor color;
};

// Ladder blocks, then general bodies, then particles: the order of
// Frame::poses. Boxes of both kinds have local x across (thickness) and
// local y along (length), as the engine builds them.
std::vector<BlockShape> blockShapes(const jl::Scene& scene);

// The height the ladder hangs over when built, for framing the camera and the room (m).
double ladderExtent(const jl::Scene& scene);

}  // namespace jl::ui
