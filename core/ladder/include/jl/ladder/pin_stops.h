// Stops on the pins of a general scene (docs/model.md section 18): the angle
// of one body's frame to another's held between limits, with the rules of
// the ladder's hinge limits (docs/model.md section 8): impacts located where
// an angle reaches its limit, perfectly plastic, resolved together as one
// active set, and a closed stop released when its contact would pull.
//
// A closed stop is a weld (the world in weld mode, World::setWeldRigidPairs):
// its two bodies share a second particle, placed so that the two coincide
// exactly at the limit, and the weld's multiplier is the stop's moment.
#pragma once

#include "jl/engine/dynamics.h"
#include "jl/engine/world.h"
#include "jl/ladder/hinge_event.h"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace jl {

struct PinStop {
    PartId a = -1, b = -1;                              // the two bodies' parts
    Vec2 pivotA = Vec2::Zero(), pivotB = Vec2::Zero();  // the pin, in each part's frame (m)
    std::optional<double> min, max;                     // rad, of theta_b - theta_a
    std::string nameA, nameB;                           // for the event log
};

class PinStops {
public:
    // After the scene's pins are made: adds the particles that close each stop.
    PinStops(World& w, std::vector<PinStop> stops);

    int count() const { return int(stops_.size()); }
    const PinStop& stop(int i) const { return stops_[size_t(i)]; }
    // -1 closed at its least angle, +1 at its greatest, 0 free.
    int closedAt(int i) const { return closed_[size_t(i)]; }
    double angle(const World& w, int i) const;  // theta_b - theta_a, rad
    double rate(const World& w, int i) const;   // rad/s

    // Where an angle starts outside its stops (by more than the pins'
    // rounding), in words; nothing when every one is within them.
    std::optional<std::string> outsideAtStart(const World& w) const;

    // One event function per stop, negative once its event has happened: a
    // free stop's distance from its nearer limit (rad, positional), a closed
    // stop's push (N m, less the tolerance that tells a pull). Returns the
    // smallest of the closed stops' (1 if none is closed).
    double eventFunctions(const World& w, const Dynamics& d, std::vector<double>& out) const;
    bool positional(int i) const { return closed_[size_t(i)] == 0; }
    bool anyClosed() const;

    // The events at instant t, settled as the ladder's are: impacts at the
    // stops reached, releases of contacts that would pull, until nothing
    // changes. Impact losses and the hand's work in impacts add to the two.
    std::vector<Event> settle(World& w, Dynamics& d, double t, double* impactLoss, double* heldWork);
    const Powers& settledPowers() const { return settled_; }
    const std::string& error() const { return error_; }

    // The moment stop i's contact exerts on body b about the pin (N m; N m s
    // from `impulses` in an impact), signed so that positive pushes b away
    // from the limit it is closed at.
    double push(const World& w, const Eigen::VectorXd& multipliers, int i) const;

private:
    bool touching(const World& w, int i, int side, bool resting) const;
    void close(World& w, int i, int side);
    void open(World& w, int i);
    std::optional<int> pulling(const World& w, const Eigen::VectorXd& multipliers, bool impulse) const;
    std::vector<Event> impact(World& w, Dynamics& d, double t, const std::vector<std::pair<int, int>>& hits,
                              double* loss, double* heldWork, std::vector<int>& released);
    Event event(double t, int i, bool closing) const;

    std::vector<PinStop> stops_;
    std::vector<int> closed_;
    // The particle pair that closes each stop at its least (0) and greatest (1) angle.
    std::vector<std::array<std::array<ParticleId, 2>, 2>> pairs_;
    double forceTolerance_ = 1e-9, impulseTolerance_ = 1e-9, restingRate_ = 1e-9;  // N m, N m s, rad/s
    Powers settled_;
    std::string error_;
};

}  // namespace jl
