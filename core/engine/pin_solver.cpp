// PinSolver: each pin's row and each body's turn and masses at the
// world's positions, whether the factorisation in hand still holds, and the
// products with J and J^T; the factorisations are in pin_chain.cpp and
// pin_sparse.cpp.
#include "pin_solver.h"

#include "jl/engine/world.h"
#include "turns.h"

#include <algorithm>
#include <bit>
#include <cmath>

namespace jl {

// One pass over the bodies: each one's turn and its inverse mass and
// inertia, side by side in flat arrays for the passes over the pins (read
// from the world's flat inverse masses: a Body, with its list of parts, is
// a long stride to read two numbers from).
// The world's own inverse masses change only with its revision: copied
// again only then (at 100,000 blocks each copy streams two arrays).
void PinSolver::updateBodies(const World& w, const std::vector<Eigen::Vector2d>* inverseMass) {
    const size_t n = size_t(w.bodyCount());
    turns(w);
    angle_ = rotated_;
    if (inverseMass) {
        inverse_ = *inverseMass;
        inverseRevision_ = 0;  // no world's
    } else if (inverseRevision_ != w.revision() || inverse_.size() != n) {
        inverse_.resize(n);
        for (size_t b = 0; b < n; ++b)
            inverse_[b] = Eigen::Vector2d(w.invMassDiag[3 * Eigen::Index(b)], w.invMassDiag[3 * Eigen::Index(b) + 2]);
        inverseRevision_ = w.revision();
    }
}

const std::vector<Eigen::Vector2d>& PinSolver::turns(const World& w) {
    const size_t n = size_t(w.bodyCount());
    const auto bits = [](double x) { return std::bit_cast<std::uint64_t>(x); };
    bool same = rotated_.size() == n;
    for (size_t b = 0; same && b < n; ++b) same = bits(rotated_[b]) == bits(w.q[3 * Eigen::Index(b) + 2]);
    if (!same) {
        rotated_.resize(n);
        for (size_t b = 0; b < n; ++b) rotated_[b] = w.q[3 * Eigen::Index(b) + 2];
        rotation_.resize(n);
        cosSinOf(rotated_.data(), 1, n, rotation_.data());
    }
    return rotation_;
}

void PinSolver::assemble(const World& w) { assemble(w, nullptr); }

void PinSolver::assemble(const World& w, const std::vector<Eigen::Vector2d>& inverseMass) { assemble(w, &inverseMass); }

bool PinSolver::prepare(const World& w) { return prepare(w, nullptr); }

bool PinSolver::prepare(const World& w, const std::vector<Eigen::Vector2d>* inverseMass) {
    if (!inverseMass && assembledPlain_ && version_ == w.structureVersion() && assembledRevision_ == w.revision() &&
        sameTurns(w))
        return false;
    assembledPlain_ = false;
    if (version_ != w.structureVersion()) order(w);
    updateBodies(w, inverseMass);
    auto turn = [&](int body, const Vec2& r) {
        const Eigen::Vector2d& cs = rotation_[size_t(body)];
        return Vec2(cs[0] * r.x() - cs[1] * r.y(), cs[1] * r.x() + cs[0] * r.y());
    };
    const std::vector<Pin>& pins = w.pins();
    // The flat flags, not the bodies: a Body is a long stride to read one
    // flag from, and at 100,000 blocks this pass streams from memory.
    const std::vector<unsigned char>& kinematic = w.kinematicFlags();
    for (size_t i = 0; i < pins.size(); ++i) {
        const Pin& p = pins[i];
        PinRow& row = pins_[i];
        row.bodyA = p.bodyA;
        row.bodyB = p.bodyB;
        row.dynA = !kinematic[size_t(p.bodyA)];
        row.dynB = !kinematic[size_t(p.bodyB)];
        row.rA = turn(p.bodyA, p.localA);
        row.rB = turn(p.bodyB, p.localB);
    }
    const std::vector<Weld>& welds = w.welds();
    for (size_t i = 0; i < welds.size(); ++i) {
        const PinRow& p = pins_[size_t(welds[i].pin)];
        welds_[i] = {p.bodyA, p.bodyB, p.dynA, p.dynB, welds[i].arm};
    }
    return true;
}

bool PinSolver::holdsFactorisationFor(const World& w) const {
    return assembledPlain_ && version_ == w.structureVersion() && assembledRevision_ == w.revision();
}

// The matrix depends on the bodies' turns alone (and on what the revision
// stands for): the same turns bit for bit, the same factorisation.
bool PinSolver::sameTurns(const World& w) const {
    if (angle_.size() != size_t(w.bodyCount())) return false;
    for (int b = 0; b < w.bodyCount(); ++b)
        if (w.q[3 * b + 2] != angle_[size_t(b)]) return false;
    return true;
}

void PinSolver::multiplyJ(const Eigen::VectorXd& u, Eigen::VectorXd& out) const {
    out.resize(rowCount());
    for (size_t i = 0; i < pins_.size(); ++i) {
        const PinRow& p = pins_[i];
        const Vec2 ua = u.segment<2>(3 * p.bodyA) + u[3 * p.bodyA + 2] * perp(p.rA);
        const Vec2 ub = u.segment<2>(3 * p.bodyB) + u[3 * p.bodyB + 2] * perp(p.rB);
        out.segment<2>(2 * Eigen::Index(i)) = ua - ub;
    }
    for (size_t i = 0; i < welds_.size(); ++i) {
        const WeldRow& wr = welds_[i];
        out[Eigen::Index(2 * pins_.size() + i)] = wr.arm * (u[3 * wr.bodyA + 2] - u[3 * wr.bodyB + 2]);
    }
}

void PinSolver::addJTranspose(const Eigen::VectorXd& x, Eigen::VectorXd& f) const {
    for (size_t i = 0; i < pins_.size(); ++i) {
        const PinRow& p = pins_[i];
        const Vec2 l = x.segment<2>(2 * Eigen::Index(i));
        f.segment<2>(3 * p.bodyA) += l;
        f[3 * p.bodyA + 2] += cross(p.rA, l);
        f.segment<2>(3 * p.bodyB) -= l;
        f[3 * p.bodyB + 2] -= cross(p.rB, l);
    }
    for (size_t i = 0; i < welds_.size(); ++i) {
        const WeldRow& wr = welds_[i];
        const double moment = wr.arm * x[Eigen::Index(2 * pins_.size() + i)];
        f[3 * wr.bodyA + 2] += moment;
        f[3 * wr.bodyB + 2] -= moment;
    }
}

}  // namespace jl
