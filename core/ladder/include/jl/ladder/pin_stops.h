// Stops on the pins of a general scene (docs/model.md section 18): the angle
// of one body's frame to another's held between limits, with the rules of
// the ladder's hinge limits (docs/model.md section 8): impacts located where
// an angle reaches its limit, perfectly plastic, resolved together as one
// active set, and a closed stop released when its contact would pull.
//
// A closed stop is a weld (the world in weld mode, World::setWeldRigidPairs):
// its two bodies share a second particle, placed so that the two coincide
// exactly at the limit, and the weld's multiplier is the stop's moment.
//
// The no-chattering rules of the ladder's contacts (docs/model.md section
// 8.6) hold here too: a release that would only close again at once is not
// made (the slow-release rule), and a stop that closes at the end of a
// short, shrinking rebound is held through the impacts of its sequence.
#pragma once

#include "jl/engine/dynamics.h"
#include "jl/engine/world.h"
#include "jl/ladder/hinge_event.h"

#include <array>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace jl {

struct PinStop {
    PartId a = -1, b = -1;                              // the two bodies' parts
    Vec2 pivotA = Vec2::Zero(), pivotB = Vec2::Zero();  // the pin, in each part's frame (m)
    std::optional<double> min, max;                     // rad, of theta_b - theta_a
    std::string nameA, nameB;                           // for the event log
    double restitution = 0;                             // [0, 1): bounce at a strike
};

class PinStops {
public:
    // After the scene's pins are made: adds the particles that close each stop.
    PinStops(World& w, std::vector<PinStop> stops);

    int count() const { return int(stops_.size()); }
    const PinStop& stop(int i) const { return stops_[size_t(i)]; }
    // -1 closed at its least angle, +1 at its greatest, 0 free.
    int closedAt(int i) const { return closed_[size_t(i)]; }
    // s: when stop i first closed (struck, or closed at the start); NaN if it has not.
    double firstClosing(int i) const { return contacts_[size_t(i)].firstClosing; }
    // Closed at the accumulation point of a shrinking sequence of rebounds.
    bool held(int i) const { return contacts_[size_t(i)].held; }
    // s: a rebound shorter than this, and than the one before it, belongs to
    // a Zeno sequence (0.0125 sqrt(L / g), L the shortest body's length).
    double zenoTime() const { return zenoTime_; }
    double angle(const World& w, int i) const;         // theta_b - theta_a, rad
    double rate(const World& w, int i) const;          // rad/s
    double acceleration(const World& w, int i) const;  // rad/s^2, as the world's last evaluation has it

    // Where an angle starts outside its stops (by more than the pins'
    // rounding), in words; nothing when every one is within them.
    std::optional<std::string> outsideAtStart(const World& w) const;

    // One event function per stop, negative once its event has happened: a
    // free stop's distance from its nearer limit (rad, positional), a closed
    // stop's push (N m, less the tolerance that tells a pull). Returns the
    // smallest of the closed stops' (1 if none is closed).
    double eventFunctions(const World& w, const Dynamics& d, std::vector<double>& out) const;
    bool positional(int i) const { return closed_[size_t(i)] == 0; }
    // After a step: a released stop that has moved clear of its limits
    // measures them from zero again.
    void track(const World& w);
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

    // s into a step of length h from the state (q0, v0, a0) to the one the
    // world holds, where a free stop's angle swung past a limit and back
    // (no sign change at the ends shows it: docs/model.md section 9.1); 0
    // when none did.
    double limitDip(const World& w, const Eigen::VectorXd& q0, const Eigen::VectorXd& v0, const Eigen::VectorXd& a0,
                    double h) const;

    // What it holds on the heap (jl/base/heap_bytes.h): what a copy takes.
    std::size_t heapBytes() const;

private:
    // What the rules of docs/model.md 8.6 keep of a stop's contact, as
    // the ladder's Hinge does: its last release, the rebound that launched
    // it (> 0), an impact that ended none (0) or its own force (-1).
    struct Contact {
        double releasedAt = -1e300, launchedBy = -1, lastRebound = 0;  // s
        bool held = false;
        // rad, <= 0: how far past the limit it left the pair read (the
        // projection's noise); its limits are measured from there until it
        // moves clear of them, as a ladder hinge's (Hinge::releaseGap).
        double releaseGap = 0;
        double firstClosing = std::numeric_limits<double>::quiet_NaN();  // s
    };

    bool touching(const World& w, int i, int side, bool resting) const;
    void close(World& w, int i, int side, double t);
    void open(World& w, int i);
    void release(World& w, int i, double t, double launchedBy);
    bool noteClose(int i, double t);
    int weldOf(const World& w, int i) const;
    bool wouldChatter(const World& w, double t, int i, const std::vector<Twist>& before) const;
    // What an instant did to one stop, as it happened, before net() says
    // what it amounts to.
    struct Said {
        Event event;
        int stop = 0;
        bool atSpeed = true;  // a strike moving into the limit (else one that only touched it at rest)
    };
    std::vector<Said> impact(World& w, Dynamics& d, double t, const std::vector<std::pair<int, int>>& hits,
                             double* loss, double* heldWork);
    double bounceAt(World& w, double t, const std::vector<std::pair<int, int>>& hits,
                    const std::vector<double>& approach, double rebound, std::vector<Said>& events);
    Event event(double t, int i, EventKind kind) const;
    void say(std::vector<Said>& said, double t, int i, EventKind kind, bool atSpeed = true);
    std::vector<Event> net(const std::vector<Said>& trials, const std::vector<int>& closedBefore) const;

    std::vector<PinStop> stops_;
    std::vector<int> closed_;
    std::vector<Contact> contacts_;
    // The world's weld that closes each stop, as weldOf last found it (checked
    // before use): found again only after a change of structure.
    mutable std::vector<int> welds_;
    // The particle pair that closes each stop at its least (0) and greatest (1) angle.
    std::vector<std::array<std::array<ParticleId, 2>, 2>> pairs_;
    double forceTolerance_ = 1e-9, impulseTolerance_ = 1e-9, restingRate_ = 1e-9;  // N m, N m s, rad/s
    double zenoTime_ = 1e-3;                                                       // s
    Powers settled_;
    std::string error_;
};

}  // namespace jl
