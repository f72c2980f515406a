#include "jl/engine/dynamics.h"

#include "jl/engine/world.h"

namespace jl {

Powers Dynamics::evaluate(World& w, double t, double within) {
    ++evaluations_;
    w.updateKinematics(t, within);
    Powers powers;
    accumulateForces(w, force_, powers);
    const bool stale = solver_.prepare(w);

    // Pin acceleration: J a + sum(sigma * -omega^2 r) = 0, where a is the
    // unconstrained acceleration: a kinematic body's prescribed one, a
    // dynamic one's W f. One pass over the pins forms each row's right-hand
    // side from the forces as it goes (at 100,000 blocks a pass that wrote
    // W f for every body and one more that read it back were two more
    // streams through memory).
    const std::vector<Pin>& pins = w.pins();
    const std::vector<unsigned char>& kinematic = w.kinematicFlags();
    const auto unconstrained = [&](int b) -> Eigen::Vector3d {
        return kinematic[size_t(b)] ? Eigen::Vector3d(w.a.segment<3>(3 * b))
                                    : Eigen::Vector3d(w.invMassDiag.segment<3>(3 * b).cwiseProduct(force_.segment<3>(3 * b)));
    };
    rhs_.resize(solver_.rowCount());
    for (size_t i = 0; i < pins.size(); ++i) {
        const int A = solver_.bodyA(int(i)), B = solver_.bodyB(int(i));
        const Vec2& rA = solver_.armA(int(i));
        const Vec2& rB = solver_.armB(int(i));
        const Eigen::Vector3d aA = unconstrained(A), aB = unconstrained(B);
        const Vec2 ua = aA.head<2>() + aA[2] * perp(rA);
        const Vec2 ub = aB.head<2>() + aB[2] * perp(rB);
        const double wa = w.v[3 * A + 2], wb = w.v[3 * B + 2];
        rhs_.segment<2>(2 * Eigen::Index(i)) = wa * wa * rA - wb * wb * rB - (ua - ub);
    }
    // Welds fix a relative angle, a linear constraint: no velocity term.
    const Eigen::Index weldRows = 2 * Eigen::Index(pins.size());
    const std::vector<Weld>& welds = w.welds();
    for (size_t i = 0; i < welds.size(); ++i) {
        const Pin& p = pins[size_t(welds[i].pin)];
        rhs_[weldRows + Eigen::Index(i)] = -(welds[i].arm * (unconstrained(p.bodyA)[2] - unconstrained(p.bodyB)[2]));
    }
    if (stale)
        solver_.factorAndSolve(w, rhs_, lambda_);
    else
        solver_.solve(rhs_, lambda_);

    // a = W (f + J^T lambda) for dynamic bodies; kinematic ones keep theirs.
    jv_ = force_;
    solver_.addJTranspose(lambda_, jv_);
    for (int b = 0; b < w.bodyCount(); ++b)
        if (!kinematic[size_t(b)]) w.a.segment<3>(3 * b) = w.invMassDiag.segment<3>(3 * b).cwiseProduct(jv_.segment<3>(3 * b));

    // Power of the pins at held bodies: force on the free side times the
    // velocity of the (shared) point. Only the pins with a held side, listed
    // anew whenever the world changes other than in its motion (every pin's
    // record is a pass over memory at 100,000 blocks, and one or two pins
    // touch the hand); the revision, unlike the structure's count, is never
    // the same for two different worlds.
    if (heldPinsRevision_ != w.revision()) {
        heldPinsRevision_ = w.revision();
        heldPins_.clear();
        for (size_t i = 0; i < pins.size(); ++i)
            if (kinematic[size_t(pins[i].bodyA)] != kinematic[size_t(pins[i].bodyB)]) heldPins_.push_back(i);
    }
    for (size_t i : heldPins_) {
        const Pin& p = pins[i];
        const bool ka = kinematic[size_t(p.bodyA)];
        const Vec2 l = lambda_.segment<2>(2 * Eigen::Index(i));
        if (ka) {
            const Vec2 vp = w.v.segment<2>(3 * p.bodyA) + w.v[3 * p.bodyA + 2] * perp(solver_.armA(int(i)));
            powers.held += (-l).dot(vp);
        } else {
            const Vec2 vp = w.v.segment<2>(3 * p.bodyB) + w.v[3 * p.bodyB + 2] * perp(solver_.armB(int(i)));
            powers.held += l.dot(vp);
        }
    }
    // The moment of a weld to a held body, times the held body's spin.
    for (size_t i = 0; i < welds.size(); ++i) {
        const Pin& p = pins[size_t(welds[i].pin)];
        const bool ka = kinematic[size_t(p.bodyA)], kb = kinematic[size_t(p.bodyB)];
        if (ka == kb) continue;
        const double moment = welds[i].arm * lambda_[weldRows + Eigen::Index(i)];  // on A; -moment on B
        powers.held += ka ? -moment * w.v[3 * p.bodyA + 2] : moment * w.v[3 * p.bodyB + 2];
    }
    // Blocks locked to a held block move with it: the hand supplies the rate
    // of change of their kinetic and potential energy.
    for (int b : w.kinematicBodies()) {
        if (b == 0) continue;  // the ground
        const Body& body = w.body(b);
        const double omega = w.v[3 * b + 2], alpha = w.a[3 * b + 2];
        for (PartId id : body.parts) {
            const Part& part = w.part(id);
            if (part.drive) continue;
            const Vec2 r = rotate(w.q[3 * b + 2], part.inBody.position);
            const Vec2 vel = w.v.segment<2>(3 * b) + omega * perp(r);
            const Vec2 acc = w.a.segment<2>(3 * b) + alpha * perp(r) - omega * omega * r;
            powers.held += part.mass * (acc - w.gravity).dot(vel) + part.inertia * alpha * omega;
        }
    }
    return powers;
}

}  // namespace jl
