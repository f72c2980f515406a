// PinSolver on other graphs (branched, looped, welded, or forced): Eigen's
// sparse LDLT of J W J^T (docs/model.md section 4.6).
#include "jl/engine/world.h"
#include "pin_solver.h"

#include <algorithm>
#include <cmath>

namespace jl {

// Every constraint row r acts on a body b through a 3-vector g (force x,
// force y, moment per unit multiplier); the matrix entry of rows r, s is the
// sum over their shared bodies of g_r^T W_b g_s.
void PinSolver::factorSparse(const World& w) {
    struct Entry {
        int row;
        Eigen::Vector3d g;
    };
    std::vector<std::vector<Entry>> byBody(size_t(w.bodyCount()));
    for (size_t i = 0; i < pins_.size(); ++i) {
        const PinRow& p = pins_[i];
        const int row = 2 * int(i);
        if (p.dynA) {
            byBody[size_t(p.bodyA)].push_back({row, {1, 0, -p.rA.y()}});
            byBody[size_t(p.bodyA)].push_back({row + 1, {0, 1, p.rA.x()}});
        }
        if (p.dynB) {
            byBody[size_t(p.bodyB)].push_back({row, {-1, 0, p.rB.y()}});
            byBody[size_t(p.bodyB)].push_back({row + 1, {0, -1, -p.rB.x()}});
        }
    }
    for (size_t i = 0; i < welds_.size(); ++i) {
        const WeldRow& wr = welds_[i];
        const int row = int(2 * pins_.size() + i);
        if (wr.dynA) byBody[size_t(wr.bodyA)].push_back({row, {0, 0, wr.arm}});
        if (wr.dynB) byBody[size_t(wr.bodyB)].push_back({row, {0, 0, -wr.arm}});
    }
    const int n = rowCount();
    std::vector<Eigen::Triplet<double>> t;
    t.reserve(size_t(n) * 8);
    double scale = 0;
    for (int b = 0; b < w.bodyCount(); ++b) {
        const Eigen::Vector2d& im = inverse_[size_t(b)];
        const Eigen::Vector3d inverse(im[0], im[0], im[1]);
        for (const Entry& r : byBody[size_t(b)])
            for (const Entry& c : byBody[size_t(b)]) {
                const double m = r.g.dot(inverse.cwiseProduct(c.g));
                if (r.row == c.row) scale = std::max(scale, std::abs(m));
                t.emplace_back(r.row, c.row, m);
            }
    }
    for (int i = 0; i < n; ++i) t.emplace_back(i, i, kRegularisation * (scale > 0 ? scale : 1.0));
    matrix_.resize(n, n);
    matrix_.setFromTriplets(t.begin(), t.end());
    if (!analysed_) {
        ldlt_.analyzePattern(matrix_);
        analysed_ = true;
    }
    ldlt_.factorize(matrix_);
}

}  // namespace jl
