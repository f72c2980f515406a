#include "jl/engine/stage_sums.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace jl {

StageTerms::StageTerms(double scale, const double* coefficients, const Eigen::VectorXd* const* k, size_t count) {
    assert(count <= most);
    for (size_t j = 0; j < count; ++j) {
        if (coefficients[j] == 0) continue;
        c[m] = scale * coefficients[j];
        x[m++] = k[j]->data();
    }
}

namespace {

// The sum of M terms, M known to the compiler so that it can unroll the
// terms and vectorize the elements.
template <size_t M>
void sumTerms(double* out, const double* base, const StageTerms& t, Eigen::Index n) {
    if (base) {
        for (Eigen::Index e = 0; e < n; ++e) {
            double sum = base[e];
            for (size_t i = 0; i < M; ++i) sum = sum + t.c[i] * t.x[i][e];
            out[e] = sum;
        }
    } else {
        for (Eigen::Index e = 0; e < n; ++e) {
            double sum = 0.0;
            for (size_t i = 0; i < M; ++i) sum = sum + t.c[i] * t.x[i][e];
            out[e] = sum;
        }
    }
}

struct SquaresSum {
    double sum = 0, count = 0;
};

// In blocks of coordinates: the terms of a block side by side (the
// compiler vectorizes them), then added one after another in the order of
// the coordinates, so that the sum is the same bit for bit whatever the
// block. A coordinate without parts adds nothing (its term is not read:
// a held body's entries may be anything).
template <size_t M>
SquaresSum errorSquares(const ErrorNormInputs& in, const StageTerms& tq, const StageTerms& tv) {
    constexpr Eigen::Index block = 64;
    double term[block];
    SquaresSum s;
    for (Eigen::Index start = 0; start < in.n; start += block) {
        const Eigen::Index end = std::min(in.n, start + block);
        for (Eigen::Index i = start; i < end; ++i) {
            double eq = 0.0, ev = 0.0;
            for (size_t j = 0; j < M; ++j) {
                eq = eq + tq.c[j] * tq.x[j][i];
                ev = ev + tv.c[j] * tv.x[j][i];
            }
            const double sq = in.tolerance * (1 + std::max(std::abs(in.q0[i]), std::abs(in.q1[i])));
            const double sv = in.tolerance * (1 + std::max(std::abs(in.v0[i]), std::abs(in.v1[i])));
            term[i - start] = in.parts[i] * ((eq / sq) * (eq / sq) + (ev / sv) * (ev / sv));
        }
        for (Eigen::Index i = start; i < end; ++i) {
            if (in.parts[i] == 0) continue;
            s.sum += term[i - start];
            s.count += 2 * in.parts[i];
        }
    }
    return s;
}

}  // namespace

void combineStages(Eigen::VectorXd& out, const Eigen::VectorXd* base, const StageTerms& t, Eigen::Index n) {
    out.resize(n);
    const double* b = base ? base->data() : nullptr;
    switch (t.m) {
    case 0: sumTerms<0>(out.data(), b, t, n); break;
    case 1: sumTerms<1>(out.data(), b, t, n); break;
    case 2: sumTerms<2>(out.data(), b, t, n); break;
    case 3: sumTerms<3>(out.data(), b, t, n); break;
    case 4: sumTerms<4>(out.data(), b, t, n); break;
    case 5: sumTerms<5>(out.data(), b, t, n); break;
    case 6: sumTerms<6>(out.data(), b, t, n); break;
    case 7: sumTerms<7>(out.data(), b, t, n); break;
    case 8: sumTerms<8>(out.data(), b, t, n); break;
    default: sumTerms<9>(out.data(), b, t, n); break;
    }
}

double errorNorm(const ErrorNormInputs& in, const StageTerms& tq, const StageTerms& tv) {
    assert(tq.m == tv.m);
    SquaresSum s;
    switch (tq.m) {
    case 0: s = errorSquares<0>(in, tq, tv); break;
    case 1: s = errorSquares<1>(in, tq, tv); break;
    case 2: s = errorSquares<2>(in, tq, tv); break;
    case 3: s = errorSquares<3>(in, tq, tv); break;
    case 4: s = errorSquares<4>(in, tq, tv); break;
    case 5: s = errorSquares<5>(in, tq, tv); break;
    case 6: s = errorSquares<6>(in, tq, tv); break;
    case 7: s = errorSquares<7>(in, tq, tv); break;
    case 8: s = errorSquares<8>(in, tq, tv); break;
    default: s = errorSquares<9>(in, tq, tv); break;
    }
    return s.count > 0 ? std::sqrt(s.sum / s.count) : 0.0;
}

}  // namespace jl
