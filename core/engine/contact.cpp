#include "jl/engine/contact.h"

#include "jl/engine/world.h"
#include "scratch.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>

namespace jl {

namespace {

// The face's normal in the world, and a point of the face's plane.
Vec2 worldNormal(const World& w, const Contact& c) { return rotate(w.partPose(c.facePart).angle, c.normal); }

}  // namespace

ContactRow contactRow(const World& w, const Contact& c) {
    ContactRow r;
    r.bodyA = w.part(c.cornerPart).body;
    r.bodyB = w.part(c.facePart).body;
    r.normal = worldNormal(w, c);
    const Vec2 p = w.pointPosition(c.cornerPart, c.corner);
    r.armA = p - w.q.segment<2>(3 * r.bodyA);
    r.armB = p - w.q.segment<2>(3 * r.bodyB);
    return r;
}

double contactGap(const World& w, const Contact& c) {
    const Pose face = w.partPose(c.facePart);
    const Vec2 p = w.pointPosition(c.cornerPart, c.corner);
    return rotate(face.angle, c.normal).dot(p - face.position) - c.offset;
}

double contactSlide(const World& w, const Contact& c) {
    const Pose face = w.partPose(c.facePart);
    const Vec2 p = w.pointPosition(c.cornerPart, c.corner);
    return perp(rotate(face.angle, c.normal)).dot(p - face.position);
}

double rowTimes(const ContactRow& r, const Eigen::VectorXd& u) {
    const Vec2 ua = u.segment<2>(3 * r.bodyA) + u[3 * r.bodyA + 2] * perp(r.armA);
    const Vec2 ub = u.segment<2>(3 * r.bodyB) + u[3 * r.bodyB + 2] * perp(r.armB);
    return r.normal.dot(ua - ub);
}

void addRowTranspose(const ContactRow& r, double s, Eigen::VectorXd& f) {
    f.segment<2>(3 * r.bodyA) += s * r.normal;
    f[3 * r.bodyA + 2] += s * cross(r.armA, r.normal);
    f.segment<2>(3 * r.bodyB) -= s * r.normal;
    f[3 * r.bodyB + 2] -= s * cross(r.armB, r.normal);
}

// d/dt of n . (vA + wA perp(rA) - vB - wB perp(rB)) with n turning with B
// (dn/dt = wB perp(n)) and the corner moving with A (d rB/dt = the
// corner's velocity less B's origin's): what is left after G a is
// wB perp(n) . (u + d rB/dt) - wA^2 n . rA, u the gap's rate.
double rowBias(const World& w, const ContactRow& r) {
    const double wa = w.v[3 * r.bodyA + 2], wb = w.v[3 * r.bodyB + 2];
    const Vec2 cornerVelocity = w.v.segment<2>(3 * r.bodyA) + wa * perp(r.armA);
    const Vec2 armBRate = cornerVelocity - w.v.segment<2>(3 * r.bodyB);
    const Vec2 u = armBRate - wb * perp(r.armB);
    return wb * perp(r.normal).dot(u + armBRate) - wa * wa * r.normal.dot(r.armA);
}

void ContactResponse::build(const World& w, PinSolver& solver, bool stale) { build(w, w.contacts(), solver, stale); }

void ContactResponse::build(const World& w, const std::vector<Contact>& contacts, PinSolver& solver, bool stale) {
    const size_t k = contacts.size();
    rows.resize(k);
    response.resize(k);
    pinForces.resize(k);
    Eigen::VectorXd jy, rhs;
    for (size_t i = 0; i < k; ++i) {
        rows[i] = contactRow(w, contacts[i]);
        Eigen::VectorXd& u = response[i];
        u.setZero(w.q.size());
        addRowTranspose(rows[i], 1.0, u);
        u.array() *= w.invMassDiag.array();
        Eigen::VectorXd& x = pinForces[i];
        if (solver.rowCount() > 0) {
            solver.multiplyJ(u, jy);
            rhs = -jy;
            if (i == 0)
                solver.solvePrepared(w, stale, rhs, x);
            else
                solver.solve(rhs, x);
            Eigen::VectorXd f = Eigen::VectorXd::Zero(w.q.size());
            solver.addJTranspose(x, f);
            u.array() += f.array() * w.invMassDiag.array();
        } else {
            x.resize(0);
        }
    }
    matrix.resize(Eigen::Index(k), Eigen::Index(k));
    for (size_t i = 0; i < k; ++i)
        for (size_t j = 0; j < k; ++j) matrix(Eigen::Index(i), Eigen::Index(j)) = rowTimes(rows[i], response[j]);
}

const Eigen::MatrixXd& contactMatrixWith(const World& w, const Contact& trial) {
    Scratch& s = w.scratch();
    s.trialContacts = w.contacts();
    s.trialContacts.push_back(trial);
    s.pins.reset();
    s.contacts.build(w, s.trialContacts, s.pins, s.pins.prepare(w));
    return s.contacts.matrix;
}

Eigen::VectorXd ContactResponse::solve(const Eigen::VectorXd& rhs, const std::vector<char>& in) const {
    std::vector<Eigen::Index> idx;
    for (Eigen::Index i = 0; i < rhs.size(); ++i)
        if (in[size_t(i)]) idx.push_back(i);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(rhs.size());
    if (idx.empty()) return s;
    const Eigen::Index n = Eigen::Index(idx.size());
    Eigen::MatrixXd m(n, n);
    Eigen::VectorXd r(n);
    double largest = 0;
    for (Eigen::Index i = 0; i < n; ++i) {
        r[i] = rhs[idx[size_t(i)]];
        for (Eigen::Index j = 0; j < n; ++j) m(i, j) = matrix(idx[size_t(i)], idx[size_t(j)]);
        largest = std::max(largest, m(i, i));
    }
    // Redundant contacts (two corners on one face of a body that can only
    // slide) leave K singular: the same small shift as the pins' sparse
    // solve picks one of the equally valid splits.
    m.diagonal().array() += 1e-12 * largest;
    const Eigen::VectorXd x = m.ldlt().solve(r);
    for (Eigen::Index i = 0; i < n; ++i) s[idx[size_t(i)]] = x[i];
    return s;
}

Eigen::VectorXd ContactResponse::solvePushing(const Eigen::VectorXd& rhs) const {
    const Eigen::Index k = rhs.size();
    std::vector<char> in(size_t(k), 1);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(k);
    const double scale = std::max(1e-300, matrix.diagonal().cwiseAbs().maxCoeff() * rhs.cwiseAbs().maxCoeff());
    for (int guard = 0; guard < 4 * int(k) + 4; ++guard) {
        s = solve(rhs, in);
        // A push that would pull: that contact parts (most negative first).
        Eigen::Index worst = -1;
        double most = -1e-12 * scale / std::max(1e-300, matrix.diagonal().cwiseAbs().maxCoeff());
        for (Eigen::Index i = 0; i < k; ++i)
            if (in[size_t(i)] && s[i] < most) most = s[i], worst = i;
        if (worst >= 0) {
            in[size_t(worst)] = 0;
            continue;
        }
        // A parted contact that would close deeper: it pushes after all.
        const Eigen::VectorXd y = matrix * s - rhs;
        double deepest = -1e-12 * scale;
        for (Eigen::Index i = 0; i < k; ++i)
            if (!in[size_t(i)] && y[i] < deepest) deepest = y[i], worst = i;
        if (worst < 0) break;
        in[size_t(worst)] = 1;
    }
    for (Eigen::Index i = 0; i < k; ++i)
        if (!in[size_t(i)]) s[i] = 0;
    return s;
}

}  // namespace jl
