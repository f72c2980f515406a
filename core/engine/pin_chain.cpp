// PinSolver along chains: the pins in path order, the O(N) block
// elimination (docs/model.md section 4.5), its substitutions, and the
// solves and evaluations that run in its sweeps.
#include "jl/engine/world.h"
#include "pin_solver.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>

namespace jl {

void PinSolver::order(const World& w) {
    const std::vector<Pin>& pins = w.pins();
    const int n = int(pins.size());
    pins_.resize(size_t(n));
    // The first two pins on each dynamic body, and how many it has: more
    // than two anywhere means a branch. Flat buffers kept from call to call,
    // as the ladder re-orders at every lock and unlock.
    pinsOfBody_.assign(size_t(w.bodyCount()), {-1, -1});
    pinCountOfBody_.assign(size_t(w.bodyCount()), 0);
    for (int i = 0; i < n; ++i) {
        for (int b : {pins[size_t(i)].bodyA, pins[size_t(i)].bodyB}) {
            if (w.body(b).kinematic) continue;
            int& count = pinCountOfBody_[size_t(b)];
            if (count < 2) pinsOfBody_[size_t(b)][size_t(count)] = i;
            ++count;
        }
    }
    unpinned_.clear();
    for (int b = 0; b < w.bodyCount(); ++b)
        if (!w.body(b).kinematic && pinCountOfBody_[size_t(b)] == 0) unpinned_.push_back(b);
    welds_.resize(w.welds().size());
    chain_ = w.welds().empty() && !forceSparse_;
    for (int count : pinCountOfBody_)
        if (count > 2) chain_ = false;
    sequence_.clear();
    pathStart_.clear();
    links_.clear();
    if (chain_) {
        auto neighbour = [&](int pin, int body) {
            for (int k = 0; k < pinCountOfBody_[size_t(body)]; ++k)
                if (const int other = pinsOfBody_[size_t(body)][size_t(k)]; other != pin) return other;
            return -1;
        };
        visited_.assign(size_t(n), 0);
        auto degree = [&](int i) {
            int d = 0;
            for (int b : {pins[size_t(i)].bodyA, pins[size_t(i)].bodyB})
                if (!w.body(b).kinematic && neighbour(i, b) >= 0) ++d;
            return d;
        };
        for (int start = 0; start < n; ++start) {
            if (visited_[size_t(start)] || degree(start) > 1) continue;
            pathStart_.push_back(int(sequence_.size()));
            int pin = start, from = -1;
            while (pin >= 0) {
                visited_[size_t(pin)] = 1;
                sequence_.push_back(pin);
                int next = -1;
                for (int b : {pins[size_t(pin)].bodyA, pins[size_t(pin)].bodyB}) {
                    if (w.body(b).kinematic) continue;
                    const int o = neighbour(pin, b);
                    if (o >= 0 && o != from && !visited_[size_t(o)]) {
                        next = o;
                        links_.push_back(
                            {b, pins[size_t(pin)].bodyA == b ? 1.0 : -1.0, pins[size_t(o)].bodyA == b ? 1.0 : -1.0});
                        break;
                    }
                }
                if (next < 0) links_.push_back({-1, 0, 0});
                from = pin;
                pin = next;
            }
        }
        if (int(sequence_.size()) != n) chain_ = false;  // a loop of bodies
        pathStart_.push_back(int(sequence_.size()));
    }
    analysed_ = false;
    version_ = w.structureVersion();
}

void PinSolver::assemble(const World& w, const std::vector<Eigen::Vector2d>* inverseMass) {
    if (!prepare(w, inverseMass)) return;
    if (chain_)
        factorChain([](int) { return Vec2(); }, nullptr);
    else
        factorSparse(w);
    assembledPlain_ = !inverseMass;
    assembledRevision_ = w.revision();
}

void PinSolver::factorAndSolve(const World& w, const Eigen::VectorXd& r, Eigen::VectorXd& x) {
    if (chain_) {
        x.resize(r.size());
        factorChain([&r](int pin) { return Vec2(r.segment<2>(2 * pin)); }, &x);
        backSubstitute(x, [](size_t) {});
    } else {
        factorSparse(w);
        x = ldlt_.solve(r);
    }
    assembledPlain_ = true;
    assembledRevision_ = w.revision();
}

// The dynamics' accelerations. The pins' acceleration equations are
// J a + sum(sigma * -omega^2 r) = 0, where a = u + W J^T lambda and u is the
// unconstrained acceleration: a kinematic body's prescribed one, a dynamic
// one's W f. Each row's right-hand side is formed from the forces as it is
// needed (at 100,000 blocks a pass that wrote W f for every body and one
// more that read it back were two more streams through memory).
void PinSolver::accelerations(World& w, const Eigen::VectorXd& force, Eigen::VectorXd& lambda) {
    const bool stale = prepare(w);
    const std::vector<unsigned char>& kinematic = w.kinematicFlags();
    const Eigen::VectorXd& v = w.v;
    Eigen::VectorXd& a = w.a;
    const Eigen::VectorXd& im = w.invMassDiag;
    const auto unconstrained = [&](int b) -> Eigen::Vector3d {
        return kinematic[size_t(b)] ? Eigen::Vector3d(a.segment<3>(3 * b))
                                    : Eigen::Vector3d(im.segment<3>(3 * b).cwiseProduct(force.segment<3>(3 * b)));
    };
    const auto rhs = [&](int pin) -> Vec2 {
        const PinRow& p = pins_[size_t(pin)];
        const Eigen::Vector3d aA = unconstrained(p.bodyA), aB = unconstrained(p.bodyB);
        const Vec2 ua = aA.head<2>() + aA[2] * perp(p.rA);
        const Vec2 ub = aB.head<2>() + aB[2] * perp(p.rB);
        const double wa = v[3 * p.bodyA + 2], wb = v[3 * p.bodyB + 2];
        return wa * wa * p.rA - wb * wb * p.rB - (ua - ub);
    };
    if (!stale || !chain_) {
        // One pass for the right-hand side (welds fix a relative angle, a
        // linear constraint: no velocity term), the solve, then J^T lambda.
        rhs_.resize(rowCount());
        for (size_t i = 0; i < pins_.size(); ++i) rhs_.segment<2>(2 * Eigen::Index(i)) = rhs(int(i));
        for (size_t i = 0; i < welds_.size(); ++i)
            rhs_[Eigen::Index(2 * pins_.size() + i)] =
                -(welds_[i].arm * (unconstrained(welds_[i].bodyA)[2] - unconstrained(welds_[i].bodyB)[2]));
        solvePrepared(w, stale, rhs_, lambda);
        jv_ = force;
        addJTranspose(lambda, jv_);
        for (int b = 0; b < w.bodyCount(); ++b)
            if (!kinematic[size_t(b)]) a.segment<3>(3 * b) = im.segment<3>(3 * b).cwiseProduct(jv_.segment<3>(3 * b));
        return;
    }
    // Along chains, in the solve's two sweeps: each pin's right-hand side as
    // the elimination reaches it, each body's acceleration as the back
    // substitution has both of its pins' forces. Three passes over the pins
    // and two over the bodies fewer, with the same arithmetic in the same
    // order: at 100,000 blocks every pass streams from memory.
    lambda.resize(rowCount());
    factorChain(rhs, &lambda);
    assembledPlain_ = true;
    assembledRevision_ = w.revision();

    // a = W (f + J^T lambda), the pins' forces added to f in the order of
    // their index (as addJTranspose adds them).
    backSubstituteApplying(
        lambda, kinematic, [&](int body) -> Eigen::Vector3d { return force.segment<3>(3 * body); },
        [&](int body, const Eigen::Vector3d& f) { a.segment<3>(3 * body) = im.segment<3>(3 * body).cwiseProduct(f); });
}

void PinSolver::removeVelocityDrift(World& w, Eigen::VectorXd& impulses) {
    const bool stale = prepare(w);
    Eigen::VectorXd& v = w.v;
    const Eigen::VectorXd& im = w.invMassDiag;
    if (!chain_) {
        multiplyJ(v, jv_);
        jv_ = -jv_;
        solvePrepared(w, stale, jv_, impulses);
        rhs_.setZero(v.size());
        addJTranspose(impulses, rhs_);
        v.array() += rhs_.array() * im.array();
        return;
    }
    // -J v, pin by pin, as multiplyJ forms it.
    const auto drift = [&](int pin) -> Vec2 {
        const PinRow& p = pins_[size_t(pin)];
        const Vec2 ua = v.segment<2>(3 * p.bodyA) + v[3 * p.bodyA + 2] * perp(p.rA);
        const Vec2 ub = v.segment<2>(3 * p.bodyB) + v[3 * p.bodyB + 2] * perp(p.rB);
        return -(ua - ub);
    };
    impulses.resize(rowCount());
    if (stale) {
        factorChain(drift, &impulses);
        assembledPlain_ = true;
        assembledRevision_ = w.revision();
    } else {
        forwardSubstitute(drift, impulses);
    }
    // A body's correction from zero, its pins' impulses added in the order
    // of their index (as addJTranspose adds them), then scaled by W.
    backSubstituteApplying(
        impulses, w.kinematicFlags(), [](int) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); },
        [&](int body, const Eigen::Vector3d& f) { v.segment<3>(3 * body) += f.cwiseProduct(im.segment<3>(3 * body)); });
}

// Along chains, the back substitution of x (the forward one done), calling
// apply(b, f) for every dynamic body b once, with f = start(b) plus the
// forces J^T x of its pins added in the order of their index: a link's body
// once the substitution has passed it, a path's two end bodies (the first
// pin's and the last pin's other body) and the bodies with no pin at the
// end.
template <class Start, class Apply>
void PinSolver::backSubstituteApplying(Eigen::VectorXd& x, const std::vector<unsigned char>& kinematic,
                                       const Start& start, const Apply& apply) const {
    const auto finish = [&](int body, int first, int second) {
        if (kinematic[size_t(body)]) return;
        Eigen::Vector3d f = start(body);
        for (int pin : {std::min(first, second), std::max(first, second)}) {
            if (pin < 0) continue;
            const PinRow& p = pins_[size_t(pin)];
            const Vec2 l = x.segment<2>(2 * pin);
            if (p.bodyA == body) {
                f.head<2>() += l;
                f[2] += cross(p.rA, l);
            } else {
                f.head<2>() -= l;
                f[2] -= cross(p.rB, l);
            }
        }
        apply(body, f);
    };
    backSubstitute(x, [&](size_t i) { finish(links_[i].body, sequence_[i], sequence_[i + 1]); });
    for (size_t path = 0; path + 1 < pathStart_.size(); ++path) {
        const size_t begin = size_t(pathStart_[path]), end = size_t(pathStart_[path + 1]);
        if (begin == end) continue;
        const PinRow& first = pins_[size_t(sequence_[begin])];
        const PinRow& last = pins_[size_t(sequence_[end - 1])];
        const int inner1 = end - begin > 1 ? links_[begin].body : -1;
        const int inner2 = end - begin > 1 ? links_[end - 2].body : -1;
        finish(first.bodyA == inner1 ? first.bodyB : first.bodyA, sequence_[begin], -1);
        if (end - begin == 1)
            finish(first.bodyB, sequence_[begin], -1);
        else
            finish(last.bodyA == inner2 ? last.bodyB : last.bodyA, sequence_[end - 1], -1);
    }
    for (int b : unpinned_)
        if (!kinematic[size_t(b)]) apply(b, start(b));
}

// x = (J W J^T)^{-1} J u and jtx = J^T x with the factorisation in hand.
// Along chains J u is formed row by row in the forward substitution and
// J^T x body by body in the back substitution: no vector of rows, and no
// pass that zeroes jtx and one more that adds into it.
void PinSolver::solveApplying(const World& w, const Eigen::VectorXd& u, Eigen::VectorXd& x, Eigen::VectorXd& jtx) {
    if (!chain_) {
        multiplyJ(u, rhs_);
        solve(rhs_, x);
        jtx.setZero(u.size());
        addJTranspose(x, jtx);
        for (int b : w.kinematicBodies()) jtx.segment<3>(3 * b).setZero();
        return;
    }
    x.resize(rowCount());
    forwardSubstitute(
        [&](int pin) -> Vec2 {
            const PinRow& p = pins_[size_t(pin)];
            const Vec2 ua = u.segment<2>(3 * p.bodyA) + u[3 * p.bodyA + 2] * perp(p.rA);
            const Vec2 ub = u.segment<2>(3 * p.bodyB) + u[3 * p.bodyB + 2] * perp(p.rB);
            return ua - ub;
        },
        x);
    jtx.resize(u.size());
    backSubstituteApplying(
        x, w.kinematicFlags(), [](int) -> Eigen::Vector3d { return Eigen::Vector3d::Zero(); },
        [&](int body, const Eigen::Vector3d& f) { jtx.segment<3>(3 * body) = f; });
    for (int b : w.kinematicBodies()) jtx.segment<3>(3 * b).setZero();
    for (Eigen::Index e = 3 * Eigen::Index(w.bodyCount()); e < jtx.size(); ++e) jtx[e] = 0;
}

// Block LDL^T along each path. The pivots S_i = D_i - B^T S_{i-1}^{-1} B are
// symmetric (J W J^T is), so only three of their entries are formed. Each
// link waits on the one before, so what counts is the chain of dependent
// operations, not their number: S_i is formed as D_i - (B^T adj(S_{i-1}) B)
// / det(S_{i-1}), where the product with the adjugate runs while the
// division does, rather than after it (as B^T S_{i-1}^{-1} B would); the
// multipliers L_i = B^T S_{i-1}^{-1} and the inverse pivots, which no later
// link waits on, are formed beside the chain. The previous link's numbers
// are carried in locals, and the arrays are reached through plain pointers.
// Given x, the forward substitution y_i = r_i - L_i y_{i-1} runs alongside
// (r_i = rhs(pin), formed as the sweep reaches it), leaving S_i^{-1} y_i in
// x for backSubstitute.
template <class RowRhs>
void PinSolver::factorChain(const RowRhs& rhs, Eigen::VectorXd* x) {
    const size_t n = sequence_.size();
    invPivot_.resize(n);
    lower_.resize(n);
    const int* sequence = sequence_.data();
    const PinRow* pins = pins_.data();
    const Eigen::Vector2d* inverse = inverse_.data();
    const Link* links = links_.data();
    Eigen::Matrix2d* invPivot = invPivot_.data();
    Eigen::Matrix2d* lower = lower_.data();
    for (size_t path = 0; path + 1 < pathStart_.size(); ++path) {
        const size_t begin = size_t(pathStart_[path]), end = size_t(pathStart_[path + 1]);
        double b00 = 0, b01 = 0, b10 = 0, b11 = 0;  // the previous link's coupling B
        double p00 = 0, p01 = 0, p11 = 0, inv = 0;  // the previous pivot S and 1 / det S
        Vec2 y;                                     // the previous link's forward substitution
        for (size_t i = begin; i < end; ++i) {
            const PinRow& p = pins[sequence[i]];
            double d00 = 0, d01 = 0, d11 = 0;  // D_i, each body's im 1 + ii perp(r) perp(r)^T
            const auto add = [&](int body, const Vec2& r) {
                const Eigen::Vector2d& im = inverse[body];
                d00 += im[0] + im[1] * r.y() * r.y();
                d01 -= im[1] * r.x() * r.y();
                d11 += im[0] + im[1] * r.x() * r.x();
            };
            if (p.dynA) add(p.bodyA, p.rA);
            if (p.dynB) add(p.bodyB, p.rB);
            if (i > begin) {
                // Eliminate the previous pin. t = adj(S) B; B^T t is symmetric.
                const double t00 = p11 * b00 - p01 * b10, t01 = p11 * b01 - p01 * b11;
                const double t10 = p00 * b10 - p01 * b00, t11 = p00 * b11 - p01 * b01;
                d00 -= (b00 * t00 + b10 * t10) * inv;
                d01 -= (b00 * t01 + b10 * t11) * inv;
                d11 -= (b01 * t01 + b11 * t11) * inv;
                // L = B^T S^{-1} = t^T / det S.
                lower[i] << t00 * inv, t10 * inv, t01 * inv, t11 * inv;
                if (x) y = rhs(sequence[i]) - lower[i] * y;
            } else if (x) {
                y = rhs(sequence[i]);
            }
            // The pivot and its inverse; a singular one (redundant pins) gets
            // the tiny diagonal shift first.
            const double scale = std::max({std::abs(d00), std::abs(d01), std::abs(d11)});
            double det = d00 * d11 - d01 * d01;
            if (!(std::abs(det) > 1e-13 * scale * scale)) {
                const double shift = kRegularisation * (scale > 0 ? scale : 1.0);
                d00 += shift;
                d11 += shift;
                det = d00 * d11 - d01 * d01;
            }
            p00 = d00;
            p01 = d01;
            p11 = d11;
            inv = 1.0 / det;
            Eigen::Matrix2d& s = invPivot[i];
            s << d11 * inv, -d01 * inv, -d01 * inv, d00 * inv;
            if (x) x->segment<2>(2 * sequence[i]) = s * y;
            if (i + 1 < end) {
                const Link& l = links[i];
                const PinRow& next = pins[sequence[i + 1]];
                const Vec2& r1 = p.bodyA == l.body ? p.rA : p.rB;
                const Vec2& r2 = next.bodyA == l.body ? next.rA : next.rB;
                const Eigen::Vector2d& im = inverse[l.body];
                const double sign = l.signPrev * l.signNext;
                const double ii = im[1];
                b00 = sign * (im[0] + ii * r1.y() * r2.y());
                b01 = sign * (-ii * r1.y() * r2.x());
                b10 = sign * (-ii * r1.x() * r2.y());
                b11 = sign * (im[0] + ii * r1.x() * r2.x());
            }
        }
    }
}

void PinSolver::solve(const Eigen::VectorXd& r, Eigen::VectorXd& x) const {
    x.resize(r.size());
    if (!chain_) {
        x = ldlt_.solve(r);
        return;
    }
    forwardSubstitute([&r](int pin) -> Vec2 { return r.segment<2>(2 * pin); }, x);
    backSubstitute(x, [](size_t) {});
}

// Forward: y_i = r_i - L_i y_{i-1} (r_i = rhs(pin)); x keeps S_i^{-1} y_i.
// Each substitution carries the previous link's value in locals: read back
// from the vector just written, every link waited on a store.
template <class RowRhs>
void PinSolver::forwardSubstitute(const RowRhs& rhs, Eigen::VectorXd& x) const {
    const int* sequence = sequence_.data();
    const Eigen::Matrix2d* lower = lower_.data();
    const Eigen::Matrix2d* invPivot = invPivot_.data();
    for (size_t path = 0; path + 1 < pathStart_.size(); ++path) {
        const size_t begin = size_t(pathStart_[path]), end = size_t(pathStart_[path + 1]);
        if (begin == end) continue;
        Vec2 y = rhs(sequence[begin]);
        x.segment<2>(2 * sequence[begin]) = invPivot[begin] * y;
        for (size_t i = begin + 1; i < end; ++i) {
            y = rhs(sequence[i]) - lower[i] * y;
            x.segment<2>(2 * sequence[i]) = invPivot[i] * y;
        }
    }
}

// Back: x_i = S_i^{-1} y_i - S_i^{-1} B_i x_{i+1}, where S_i^{-1} B_i is
// L_{i+1}^T (S is symmetric): the forward pass left S_i^{-1} y_i in x, so
// each link waits on one 2 x 2 product and a subtraction, not two products.
// passed(i) runs once x_i and x_{i+1} are final, for every link i.
template <class Passed>
void PinSolver::backSubstitute(Eigen::VectorXd& x, const Passed& passed) const {
    const int* sequence = sequence_.data();
    const Eigen::Matrix2d* lower = lower_.data();
    for (size_t path = 0; path + 1 < pathStart_.size(); ++path) {
        const size_t begin = size_t(pathStart_[path]), end = size_t(pathStart_[path + 1]);
        if (end - begin < 2) continue;
        Vec2 next = x.segment<2>(2 * sequence[end - 1]);
        for (size_t i = end - 1; i-- > begin;) {
            next = x.segment<2>(2 * sequence[i]) - lower[i + 1].transpose() * next;
            x.segment<2>(2 * sequence[i]) = next;
            passed(i);
        }
    }
}

}  // namespace jl
