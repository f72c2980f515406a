// The falling chain in the engines people would otherwise use (MuJoCo,
// Box2D, Bullet's Featherstone multibody), built when JL_BENCH_PEERS is on.
#pragma once

#include "jl/base/geometry.h"

#include <string>
#include <vector>

namespace jl::bench {

struct PeerRun {
    std::string engine;  // "mujoco 2.2.2 rk4", ...
    int blocks = 0;
    double step = 0;       // s
    double cost = 0;       // CPU s per simulated s
    double error = 0;      // m, largest block-centre error at the end
    bool finished = true;  // false: it blew up or produced NaN
};

// Falling chain of n blocks (docs/model.md section 16.1) run to `duration`
// at each step; errors against `reference` (block centres at `duration`).
std::vector<PeerRun> measurePeers(int n, const std::vector<double>& steps, double duration,
                                  const std::vector<Vec2>& reference, double minSeconds);

// "MuJoCo 2.2.2, Box2D 2.4.1, ..." or why there are none.
std::string peerVersions();

}  // namespace jl::bench
