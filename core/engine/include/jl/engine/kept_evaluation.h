// The dynamics evaluated in one state, kept for the next step: a step ends
// by evaluating its end state (the ladder's event functions need the pin
// forces there), and the next step's first stage is that same state at the
// same time. Evaluating it again would give the same numbers bit for bit
// and cost a whole-ladder pass: one of the five evaluations an RK4 step of
// a ladder made.
#pragma once

#include "jl/base/geometry.h"
#include "jl/engine/dynamics.h"

#include <Eigen/Core>

#include <cstdint>

namespace jl {

class World;

class KeptEvaluation {
public:
    // Keeps what d.evaluate(w, t) has just given: w.a, `powers`, and the
    // applied and pin forces d holds.
    void keep(const World& w, const Dynamics& d, double t, const Powers& powers);
    // If w holds the kept state at time t with nothing else changed (same
    // World::revision, gravity, q and v, bit for bit), leaves w and d as
    // that evaluation left them (w.a, d's forces) and returns the powers;
    // otherwise null, with w and d untouched.
    const Powers* recall(World& w, Dynamics& d, double t) const;
    void forget() { kept_ = false; }

private:
    bool kept_ = false;
    double t_ = 0;
    std::uint64_t revision_ = 0;
    Vec2 gravity_ = Vec2::Zero();
    Eigen::VectorXd q_, v_, a_;
    Dynamics::Last forces_;
    Powers powers_;
};

}  // namespace jl
