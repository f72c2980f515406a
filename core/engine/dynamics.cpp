#include "jl/engine/dynamics.h"

#include "jl/engine/applied_forces.h"
#include "jl/engine/world.h"
#include "pin_solver.h"

namespace jl {

Dynamics::Dynamics() : solver_(std::make_unique<PinSolver>()) {}
Dynamics::~Dynamics() = default;

void Dynamics::forgetStructure() { solver_->reset(); }
void Dynamics::setForceSparse(bool on) { solver_->setForceSparse(on); }

Powers Dynamics::evaluate(World& w, double t, double within) {
    ++evaluations_;
    ++forcesGeneration_;
    w.updateKinematics(t, within);
    Powers powers;
    // Gravity alone (no air damping, springs, loads or drags: a falling
    // chain, a ladder in still air): the forces are the bodies' weights, the
    // same until the world or gravity changes, and are copied again only
    // then (on a long chain each copy is a pass over memory).
    const World& cw = w;
    const bool weightsOnly = onlyWeights(cw);
    if (!weightsOnly || weightsRevision_ != cw.revision() || weightsGravity_ != cw.gravity ||
        force_.size() != cw.q.size()) {
        accumulateForces(cw, force_, powers);
        weightsRevision_ = weightsOnly ? cw.revision() : 0;
        weightsGravity_ = cw.gravity;
    }
    solver_->accelerations(w, force_, lambda_);
    if (!w.contacts().empty())
        addContacts(w, powers);
    else
        contactForces_.resize(0);

    const std::vector<Pin>& pins = w.pins();
    const std::vector<unsigned char>& kinematic = w.kinematicFlags();
    const Eigen::Index weldRows = 2 * Eigen::Index(pins.size());
    const std::vector<Weld>& welds = w.welds();
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
            const Vec2 vp = w.v.segment<2>(3 * p.bodyA) + w.v[3 * p.bodyA + 2] * perp(solver_->armA(int(i)));
            powers.held += (-l).dot(vp);
        } else {
            const Vec2 vp = w.v.segment<2>(3 * p.bodyB) + w.v[3 * p.bodyB + 2] * perp(solver_->armB(int(i)));
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

// The resting contacts on top of the pins (docs/model.md section 17.2): with
// a the pins' accelerations and u_i the pins' response to a unit push at
// contact i, the pushes s solve K s = -(G a + bias), each contact's gap
// then accelerating at zero; the pins' forces take their part, s_i x_i.
// Every contact is kept while it rests, even if it would pull: its force
// crossing zero is an event (section 17.4).
void Dynamics::addContacts(World& w, Powers& powers) {
    contactResponse_.build(w, *solver_, false);
    const size_t k = w.contacts().size();
    Eigen::VectorXd rhs(Eigen::Index(k), 1);
    for (size_t i = 0; i < k; ++i) {
        const ContactRow& r = contactResponse_.rows[i];
        rhs[Eigen::Index(i)] = -(rowTimes(r, w.a) + rowBias(w, r));
    }
    contactForces_ = contactResponse_.solve(rhs, std::vector<char>(k, 1));
    const std::vector<unsigned char>& kinematic = w.kinematicFlags();
    for (size_t i = 0; i < k; ++i) {
        const double s = contactForces_[Eigen::Index(i)];
        w.a += s * contactResponse_.response[i];
        if (contactResponse_.pinForces[i].size() == lambda_.size()) lambda_ += s * contactResponse_.pinForces[i];
        // A held face (or corner) pushes the free side at a point that
        // moves with the hand: the hand's power, as for its pins.
        const ContactRow& r = contactResponse_.rows[i];
        if (kinematic[size_t(r.bodyB)] && !kinematic[size_t(r.bodyA)])
            powers.held += s * r.normal.dot(w.v.segment<2>(3 * r.bodyB) + w.v[3 * r.bodyB + 2] * perp(r.armB));
        if (kinematic[size_t(r.bodyA)] && !kinematic[size_t(r.bodyB)])
            powers.held -= s * r.normal.dot(w.v.segment<2>(3 * r.bodyA) + w.v[3 * r.bodyA + 2] * perp(r.armA));
    }
}

}  // namespace jl
