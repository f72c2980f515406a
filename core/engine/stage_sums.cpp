#include "stage_sums.h"

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

void StageTerms::add(double coefficient, const Eigen::VectorXd& vector) {
    assert(m < most);
    if (coefficient == 0) return;
    c[m] = coefficient;
    x[m++] = vector.data();
}

void StageTerms::padTo(size_t count, const double* vector) {
    assert(count <= most);
    while (m < count) {
        c[m] = 0;
        x[m++] = vector;
    }
}

namespace {

// A stage's positions and velocities side by side, M terms each, M known
// to the compiler so that it can unroll the terms and vectorize the
// elements.
template <size_t M>
void sumPair(double* q, const double* q0, const StageTerms& tq, double* v, const double* v0, const StageTerms& tv,
             Eigen::Index n) {
    for (Eigen::Index e = 0; e < n; ++e) {
        double sq = q0[e], sv = v0[e];
        for (size_t i = 0; i < M; ++i) {
            sq = sq + tq.c[i] * tq.x[i][e];
            sv = sv + tv.c[i] * tv.x[i][e];
        }
        q[e] = sq;
        v[e] = sv;
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

void combineStages(Eigen::VectorXd& q, const Eigen::VectorXd& q0, const StageTerms& termsQ, Eigen::VectorXd& v,
                   const Eigen::VectorXd& v0, const StageTerms& termsV, Eigen::Index n) {
    // Run side by side, the shorter sum gets zero terms (on its base, which
    // is read anyway).
    StageTerms tq = termsQ, tv = termsV;
    tq.padTo(tv.m, q0.data());
    tv.padTo(tq.m, v0.data());
    q.resize(n);
    v.resize(n);
    switch (tq.m) {
        case 0:
            sumPair<0>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 1:
            sumPair<1>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 2:
            sumPair<2>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 3:
            sumPair<3>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 4:
            sumPair<4>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 5:
            sumPair<5>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 6:
            sumPair<6>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 7:
            sumPair<7>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 8:
            sumPair<8>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        case 9:
            sumPair<9>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
        default:
            sumPair<10>(q.data(), q0.data(), tq, v.data(), v0.data(), tv, n);
            break;
    }
}

double errorNorm(const ErrorNormInputs& in, const StageTerms& termsQ, const StageTerms& termsV) {
    StageTerms tq = termsQ, tv = termsV;
    tq.padTo(tv.m, in.q0);
    tv.padTo(tq.m, in.v0);
    SquaresSum s;
    switch (tq.m) {
        case 0:
            s = errorSquares<0>(in, tq, tv);
            break;
        case 1:
            s = errorSquares<1>(in, tq, tv);
            break;
        case 2:
            s = errorSquares<2>(in, tq, tv);
            break;
        case 3:
            s = errorSquares<3>(in, tq, tv);
            break;
        case 4:
            s = errorSquares<4>(in, tq, tv);
            break;
        case 5:
            s = errorSquares<5>(in, tq, tv);
            break;
        case 6:
            s = errorSquares<6>(in, tq, tv);
            break;
        case 7:
            s = errorSquares<7>(in, tq, tv);
            break;
        case 8:
            s = errorSquares<8>(in, tq, tv);
            break;
        case 9:
            s = errorSquares<9>(in, tq, tv);
            break;
        default:
            s = errorSquares<10>(in, tq, tv);
            break;
    }
    return s.count > 0 ? std::sqrt(s.sum / s.count) : 0.0;
}

}  // namespace jl
