// The cosine and sine of many bodies' turns at once.
//
// Every evaluation of a ladder turns each body's points by its angle, so
// each evaluation needs one cosine and one sine per body: on a turned
// 1,000-block ladder glibc's scalar sincos of angles near pi was a seventh
// of all instructions (20 ns an angle on this project's benchmark machine). glibc's
// vector maths library (libmvec) computes four at a time, within 4 units in
// the last place, in about 2 ns an angle (a cosine and a sine) where the
// processor has AVX2.
#pragma once

#include <Eigen/Core>

#include <cstddef>
#include <vector>

namespace jl {

// out[i] = (cos a_i, sin a_i) for a_i = angle[i * stride], i < n. Every
// angle goes through the same routine wherever it sits in the list, so a
// turn gets the same bits whatever the number of bodies.
void cosSinOf(const double* angle, std::ptrdiff_t stride, std::size_t n, Eigen::Vector2d* out);

// Every routine this build and processor can run, the one cosSinOf uses
// first: libmvec's AVX2 one where the processor has AVX2, its SSE2 one on
// any x86-64, then std::cos and std::sin. Tests check each, not only the
// one their machine happens to choose.
struct TurnRoutine {
    using Run = void (*)(const double* angle, std::ptrdiff_t stride, std::size_t n, Eigen::Vector2d* out);
    const char* name;
    Run run;
};
const std::vector<TurnRoutine>& turnRoutines();

}  // namespace jl
