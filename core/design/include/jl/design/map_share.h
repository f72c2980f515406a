// A design map split among machines: share K of N holds only its cells (an
// equal part of them, in the map's order) and is written as CSV that also
// names its map (the axes exactly, and the base scene by a digest of its
// file text); the shares, joined, give the very map one machine computes,
// byte for byte, whatever machine computed each share.
#pragma once

#include "jl/design/ripple_map.h"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace jl {

// The cells of share `index` of `count` (1-based) of a map of `total`
// cells: [first, last), every share as large as another to within one.
std::pair<std::size_t, std::size_t> shareCells(std::size_t total, int index, int count);

// The map's name, as each share carries it: "blocks=4:8:2;thickness=
// 0.006:0.012:0.006;scene=<digest>", its numbers as they read back exactly,
// and ";whole-runs" when every cell runs its whole time (other counts).
std::string mapName(const Scene& base, const DesignAxis& x, const DesignAxis& y,
                    RippleStop stop = RippleStop::WhenSettled);

// Share `index` of `count` of `m` (whose cells of that share are computed):
// "map,share,cell," then the columns of rippleMapCsv, one row per cell.
std::string rippleShareCsv(const RippleMap& m, const std::string& name, int index, int count);

// The map the shares make, or why they do not make one: a share of another
// map, a share missing or given twice, a cell missing or not its share's.
// `shares` holds each share's file name (for messages) and text.
struct JoinedMap {
    std::optional<RippleMap> map;
    std::string error;
};
JoinedMap joinRippleShares(const std::vector<std::pair<std::string, std::string>>& shares);

}  // namespace jl
