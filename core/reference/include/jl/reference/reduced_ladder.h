// An independent implementation of the ladder of docs/model.md, to check
// the engine's events against: reduced coordinates (one absolute angle per
// block, the top block's angle prescribed by the hand), a dense mass matrix,
// fixed-step RK4 of its own, events located by bisection on re-run steps,
// and the rules of sections 8.2 to 8.6 (plastic impacts with an active set,
// releases when a contact force would pull, the slow-release rule, held contacts) written
// afresh.
// It shares no code with core/engine or core/ladder; it reads the scene with
// core/scene. Small and slow: meant for ladders of a few dozen blocks.
//
// Covered: a ladder whose block 0 is held at its centre and turned by the
// script (turn actions of block 0), starting in the hanging equilibrium,
// with gravity, no damping and no restitution. Anything else is refused.
#pragma once

#include "jl/base/geometry.h"
#include "jl/scene/scene.h"

#include <Eigen/Core>

#include <string>
#include <vector>

namespace jl {

struct ReducedEvent {
    enum class Kind { Lock, Unlock, Fold, Unfold, FlipFlop };
    double time = 0;  // s
    Kind kind = Kind::Lock;
    int hinge = 0;  // j, between blocks j-1 and j
};

const char* toString(ReducedEvent::Kind k);

class ReducedLadder {
public:
    // Empty error() when the scene is one this model covers.
    explicit ReducedLadder(const Scene& scene, double step = 2e-5);

    const std::string& error() const { return error_; }
    // Runs to time t, appending to events(). False (and error()) if the
    // rules could not settle an instant.
    bool advanceTo(double t);
    double time() const { return t_; }
    const std::vector<ReducedEvent>& events() const { return events_; }
    double foldAngle(int j) const;  // rad, section 7
    double energy() const;          // J, kinetic + potential of blocks 1.. (the hand's block left out)

private:
    enum class Mode { Free, Locked, Folded };
    struct Hinge {
        Mode mode = Mode::Free;
        int corner = 0;
        double offset = 0;           // rad, theta_j - theta_(j-1) while closed
        double releasedAt = -1e300;  // s, the last release
        double launchedBy = -1;      // section 8.6: the rebound that launched the open interval (> 0), 0, or -1
        double lastRebound = 0;      // s
        bool held = false;           // section 8.6
    };
    struct Contact {  // section 8.3, on block j, > 0 pushing it away
        double normal = 0, nearEnd = 0, farEnd = 0;
        double load = 0;  // |F| + the |N|s: its threshold grows with it
    };
    // The blocks' motion as velocities of their centres and turning rates:
    // what an impact starts from. Angle rates alone would not do, because
    // a flip-flop moves a hinge, and the same angle rates then mean another
    // motion.
    struct Motion {
        std::vector<Vec2> velocity;  // m/s, of each centre
        Eigen::VectorXd rate;        // rad/s
    };
    struct Turn {
        double at, duration, angle;
    };

    // Kinematics (reduced_ladder.cpp).
    Vec2 cornerLocal(int i, int k) const;
    // The hand's angle (order 0), rate (1) or acceleration (2) at t, on the
    // piece of its path that holds `within` (section 10).
    double hand(double t, double within, int order) const;
    double foldAngleOf(int j, const Eigen::VectorXd& theta) const;
    void arms(const Eigen::VectorXd& theta, std::vector<Vec2>& arm) const;
    Eigen::VectorXd accelerations(double t, double within, const Eigen::VectorXd& theta,
                                  const Eigen::VectorXd& omega) const;
    Eigen::VectorXd solveClosed(const Eigen::MatrixXd& mass, const Eigen::VectorXd& rhs, double handValue) const;
    Motion motion() const;
    Eigen::VectorXd project(const Motion& before) const;
    void place();
    void evaluate(double within);
    Vec2 hingePoint(int j) const;
    void hingeFrame(int j, Vec2& da, Vec2& na) const;
    double foldRate(int j, const Eigen::VectorXd& rate) const;
    Contact split(int j, const Vec2& force, double moment) const;
    Contact contactForce(int j) const;
    Contact contactImpulse(int j, const Motion& before) const;
    Contact wrenchSplit(int j, const std::vector<Vec2>& momentum, const Eigen::VectorXd& spin) const;
    void hangInEquilibrium();
    std::string readScene(const Scene& scene);

    // Stepping and events (reduced_ladder_events.cpp).
    void rk4(double t, double h, Eigen::VectorXd& theta, Eigen::VectorXd& omega) const;
    void keepClosed(bool velocities);
    void moveTo(double t, double h, const Eigen::VectorXd& theta0, const Eigen::VectorXd& omega0);
    std::vector<double> eventFunctions() const;
    bool crossed(const std::vector<double>& start) const;
    void locate(double h, const Eigen::VectorXd& theta0, const Eigen::VectorXd& omega0,
                const std::vector<double>& start);
    bool touching(int j, bool folded, bool resting) const;
    int pulling(bool impulse, const Motion& before, const std::vector<int>& keep, bool spareHeld,
                ReducedEvent::Kind& kind) const;
    bool wouldChatter(int j, ReducedEvent::Kind kind, const Motion& before) const;
    void close(int j, bool folded);
    void release(int j, ReducedEvent::Kind kind, double launchedBy);
    bool noteClose(int j);
    void impact(const std::vector<int>& hits, std::vector<int>& released);
    bool resolve();

    // The ladder.
    int n_ = 0;  // blocks
    double length_ = 0;
    std::vector<double> mass_, inertia_, thickness_;
    Vec2 gravity_{0, -9.81};
    std::vector<Turn> turns_;     // of block 0, as the script gives them (they add up)
    std::vector<double> breaks_;  // s: where the hand's acceleration jumps
    double threshold(const Contact& c, bool impulse) const;
    double forceTolerance_ = 0, impulseTolerance_ = 0, restingRate_ = 0, zenoTime_ = 0;
    double minReboundSpeed_ = 1e-4;  // rad/s
    // The state: theta_[0] is the hand's; hinges_[j] for j = 1..n-1.
    std::vector<Hinge> hinges_;
    Eigen::VectorXd theta_, omega_, alpha_;
    std::vector<Vec2> centres_, arm_;  // arm_[i * n + l]: d centre_i / d theta_l turned back by 90 degrees
    double t_ = 0, step_ = 2e-5;
    double within_ = 0;  // the time whose piece of the hand's path the state's accelerations used
    std::vector<ReducedEvent> events_;
    std::string error_;
};

}  // namespace jl
