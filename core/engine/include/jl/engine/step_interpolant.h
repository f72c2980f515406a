// The motion inside an accepted step, without re-running it: quintic Hermite
// interpolation of every body's coordinates from the positions, velocities
// and accelerations at both ends. Locating an event then costs one
// evaluation of the event functions per trial instead of a whole step.
#pragma once

#include <Eigen/Core>

namespace jl {

class StepInterpolant {
public:
    // How the motion inside a step is read. Quintic: the Hermite polynomial
    // through both ends (every method of order two and up). The method's own
    // step cut short, for symplectic Euler: v = v0 + tau a0, q = q0 + tau v,
    // the state that method reaches in a step of length tau (before the
    // projection onto the pins). A run goes on from a located event's state;
    // read off the quintic, that state is not one symplectic Euler's steps
    // could reach, and each event shifted the energy its steps keep bounded
    // (docs/model.md section 9.2): runs with many stop events ran away.
    enum class Inside { Quintic, SymplecticEuler };
    explicit StepInterpolant(Inside inside = Inside::Quintic) : inside_(inside) {}

    // The step of length h from (q0, v0, a0) to (q1, v1, a1), its end given
    // first (the caller evaluates it first). Copies into buffers kept from
    // step to step: no allocation once warmed up.
    void setEnd(const Eigen::VectorXd& q1, const Eigen::VectorXd& v1, const Eigen::VectorXd& a1);
    void setStart(double h, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, const Eigen::VectorXd& a0);
    // Position and velocity a time `tau` (0 <= tau <= h) into the step.
    // Quintic: exact for motion polynomial of degree 5 in time; error O(h^6)
    // in position and O(h^5) in velocity otherwise.
    void at(double tau, Eigen::VectorXd& q, Eigen::VectorXd& v) const;
    // Coordinate i of the position alone (the same polynomial): a trial that
    // reads a few coordinates costs a few, not the whole world.
    double coordinateAt(double tau, Eigen::Index i) const;

private:
    Inside inside_;
    double h_ = 0;
    Eigen::VectorXd q0_, v0_, a0_, q1_, v1_, a1_;
};

}  // namespace jl
