#include "turns.h"

#include <cmath>
#include <vector>

#if defined(JL_HAVE_LIBMVEC) && defined(__x86_64__)
#include <immintrin.h>

// libmvec's entry points, named by the x86-64 vector function ABI (glibc
// declares them only under -ffast-math, which this project does not use).
// 'b': two lanes in SSE registers (any x86-64); 'd': four lanes in AVX2
// registers (glibc picks its AVX2 + FMA code, or two 'b' calls).
extern "C" __m128d _ZGVbN2v_cos(__m128d);
extern "C" __m128d _ZGVbN2v_sin(__m128d);
#pragma GCC push_options
#pragma GCC target("avx2")
extern "C" __m256d _ZGVdN4v_cos(__m256d);
extern "C" __m256d _ZGVdN4v_sin(__m256d);
#pragma GCC pop_options
#endif

namespace jl {

namespace {

#if defined(JL_HAVE_LIBMVEC) && defined(__x86_64__)

// Angle i of the list; past its end the last one again, so that the tail
// goes through the same routine as the rest.
inline double angleAt(const double* angle, std::ptrdiff_t stride, std::size_t i, std::size_t n) {
    return angle[std::ptrdiff_t(i < n ? i : n - 1) * stride];
}

// Four angles straight into a register. Not copied through memory first:
// four 8-byte stores read back as one 32-byte load cannot be forwarded,
// and that wait made the routine take 6 ns an angle where libmvec's own
// work is 2.6 ns (2.0 ns now; a probe on this project's machine).
__attribute__((target("avx2"))) inline __m256d loadFour(const double* angle, std::ptrdiff_t stride, std::size_t i,
                                                        std::size_t n) {
    if (stride == 1 && i + 4 <= n) return _mm256_loadu_pd(angle + i);
    return _mm256_set_pd(angleAt(angle, stride, i + 3, n), angleAt(angle, stride, i + 2, n),
                         angleAt(angle, stride, i + 1, n), angleAt(angle, stride, i, n));
}

__attribute__((target("avx2"))) void cosSinFour(const double* angle, std::ptrdiff_t stride, std::size_t n,
                                                Eigen::Vector2d* out) {
    alignas(32) double pairs[8];
    for (std::size_t i = 0; i < n; i += 4) {
        const __m256d a = loadFour(angle, stride, i, n);
        const __m256d c = _ZGVdN4v_cos(a), s = _ZGVdN4v_sin(a);
        // (c0 s0 c2 s2), (c1 s1 c3 s3) -> (c0 s0 c1 s1), (c2 s2 c3 s3)
        const __m256d even = _mm256_unpacklo_pd(c, s), odd = _mm256_unpackhi_pd(c, s);
        double* to = i + 4 <= n ? out[i].data() : pairs;
        _mm256_storeu_pd(to, _mm256_permute2f128_pd(even, odd, 0x20));
        _mm256_storeu_pd(to + 4, _mm256_permute2f128_pd(even, odd, 0x31));
        if (to == pairs)
            for (std::size_t k = 0; i + k < n; ++k) out[i + k] = {pairs[2 * k], pairs[2 * k + 1]};
    }
}

void cosSinTwo(const double* angle, std::ptrdiff_t stride, std::size_t n, Eigen::Vector2d* out) {
    alignas(32) double c[4], s[4];
    for (std::size_t i = 0; i < n; i += 4) {
        for (std::size_t k = 0; k < 4; k += 2) {
            const __m128d a = _mm_set_pd(angleAt(angle, stride, i + k + 1, n), angleAt(angle, stride, i + k, n));
            _mm_store_pd(c + k, _ZGVbN2v_cos(a));
            _mm_store_pd(s + k, _ZGVbN2v_sin(a));
        }
        for (std::size_t k = 0; k < 4 && i + k < n; ++k) out[i + k] = {c[k], s[k]};
    }
}

#endif

// std::cos and std::sin: where there is no libmvec (or no x86-64), and in
// tests, the answer the others are held to.
void cosSinScalar(const double* angle, std::ptrdiff_t stride, std::size_t n, Eigen::Vector2d* out) {
    for (std::size_t i = 0; i < n; ++i) {
        const double a = angle[std::ptrdiff_t(i) * stride];
        out[i] = {std::cos(a), std::sin(a)};
    }
}

// The fastest this processor can run first (listed at first use, not in a
// static initialiser, which could run before the processor has been asked).
const std::vector<TurnRoutine>& routines() {
    static const std::vector<TurnRoutine> list = [] {
        std::vector<TurnRoutine> r;
#if defined(JL_HAVE_LIBMVEC) && defined(__x86_64__)
        __builtin_cpu_init();
        if (__builtin_cpu_supports("avx2")) r.push_back({"libmvec avx2", cosSinFour});
        r.push_back({"libmvec sse2", cosSinTwo});
#endif
        r.push_back({"scalar", cosSinScalar});
        return r;
    }();
    return list;
}

}  // namespace

const std::vector<TurnRoutine>& turnRoutines() { return routines(); }

void cosSinOf(const double* angle, std::ptrdiff_t stride, std::size_t n, Eigen::Vector2d* out) {
    static const TurnRoutine::Run run = routines().front().run;
    if (n > 0) run(angle, stride, n, out);
}

}  // namespace jl
