// The hybrid study (`jladder bench --only folding`): the folding chain
// (bench/folding_chain.h) at N = 10 and 100 in this engine, Siconos, MuJoCo,
// Bullet and Box2D, against this engine's tightest run checked against
// Siconos's event-driven one; the section and its charts.
#pragma once

#include "bench/cases.h"

#include <filesystem>

namespace jl::bench {

bool runFoldingStudy(const BenchPlan& plan, const std::filesystem::path& out, const std::filesystem::path& report);

}  // namespace jl::bench
