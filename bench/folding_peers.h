// The folding chain (bench/folding_chain.h) in the engines people would
// otherwise use: MuJoCo, Box2D and Bullet's Featherstone multibody, each with
// its own joint limits as the stops. Built when JL_BENCH_PEERS is on.
#pragma once

#include "bench/folding_chain.h"

#include <string>
#include <vector>

namespace jl::bench {

// Every peer's runs of the folding chain of n blocks, each at several fixed
// steps (a run repeated until it has taken minSeconds of CPU time); empty
// when the peers are not built in (foldingPeerNote says why).
std::vector<FoldingRun> runFoldingPeers(int n, double minSeconds);

// The peers' versions and how their runs were chosen, or why there are none.
std::string foldingPeerNote();

}  // namespace jl::bench
