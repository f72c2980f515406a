// A chain of nested bodies as a MuJoCo model, for the peer runs
// (bench/peers.cpp, bench/folding_peers.cpp). Only with JL_BENCH_PEERS.
#pragma once

#include <mujoco/mujoco.h>
#include <string>
#include <vector>

namespace jl::bench {

// The model whose <mujoco> element holds `head` (compiler, options,
// defaults) and a world body holding bodies[0], which holds bodies[1], and
// so on; each entry is a body's opening tag and what it holds before its
// child. Null, said on stderr, if MuJoCo rejects it.
mjModel* loadNestedChain(const std::string& head, const std::vector<std::string>& bodies);

}  // namespace jl::bench
