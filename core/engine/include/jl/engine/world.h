// The simulated world: parts, the bodies they form, particles, and the
// restructuring operations combine/separate of the paper.
#pragma once

#include "jl/base/geometry.h"
#include "jl/engine/contact.h"
#include "jl/engine/drive.h"
#include "jl/engine/fresh.h"

#include <Eigen/Core>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace jl {

using PartId = int;
using ParticleId = int;

// An original rigid piece: a box (a block), a point mass, or the ground.
// Parts are never deleted, so a PartId stays valid for the world's lifetime.
// Each part belongs to exactly one body, the unit the solver moves.
struct Part {
    double mass = 0;               // kg
    double inertia = 0;            // kg m^2 about the part's centre (0 for a point)
    Vec2 halfSize = Vec2::Zero();  // m, half length and half thickness (drawing)
    double width = 0;              // m, out of the plane (drawing)
    bool isPoint = false;          // a free particle: no orientation of its own
    double linearDamping = 0;      // N s/m, air drag at the centre
    double angularDamping = 0;     // N m s
    int body = -1;                 // current body
    Pose inBody;                   // this part's centre and angle in its body's frame
    std::optional<Drive> drive;    // held: the part follows this path
};

// A solver unit: one or more parts moving as one rigid body. The body's frame
// has its origin at the centre of mass. Held and ground bodies are kinematic
// (infinite mass, prescribed motion).
struct Body {
    bool alive = false;
    bool kinematic = false;
    double mass = 0, inertia = 0;
    double invMass = 0, invInertia = 0;
    std::vector<PartId> parts;
};

// A point on a part, in the part's frame.
struct Attachment {
    PartId part = 0;
    Vec2 local = Vec2::Zero();
};

// A particle of the paper: a point on one part, or shared by several parts
// (a hinge), or absorbed into another particle by combine. Where it is (all
// its attachments coincide): its own point, then every point of each
// particle combined into it, in the order they were (World::forEachAttachment).
// Derived so, and the particles combined into it kept as a linked stack,
// not in lists: nearly every particle stands alone (a 100,000-block ladder
// has 1.4 million, 1.2 million of them alone), and a list each was an
// allocation each at every copy of the world. A snapshot of that ladder
// took 121 ms and 193 MB with lists, and takes 50 ms and 106 MB with a
// particle of 40 bytes, copied as they lie.
struct Particle {
    Attachment own;                  // the point it was made as
    ParticleId mergedInto = -1;      // >= 0 while absorbed by combine
    ParticleId lastAbsorbed = -1;    // the top of the stack combined into it (separate takes it off)
    ParticleId absorbedBefore = -1;  // while absorbed: the one below it on that stack
};

// A pin: the same point on two bodies (derived from shared particles).
struct Pin {
    int bodyA = 0, bodyB = 0;
    PartId partA = 0, partB = 0;                        // the parts the shared point is on
    Vec2 localA = Vec2::Zero(), localB = Vec2::Zero();  // in the body frames
    ParticleId particle = -1;
};

// In weld mode (World::setWeldRigidPairs), two bodies that share two or more
// particles are not merged: they keep one pin (at `pin`) and this weld
// closes their relative angle, theta_A - theta_B = angle. Its row is scaled
// by `arm` (the distance between the two shared points) so that its gap is
// a length and its multiplier a force: the gap is arm * (theta_A - theta_B -
// angle), its multiplier times arm a moment on A (minus that on B).
struct Weld {
    int pin = -1;      // index into World::pins(): the same two bodies
    double arm = 0;    // m
    double angle = 0;  // rad
};

// A linear spring-damper between two particles.
struct Spring {
    ParticleId a = -1, b = -1;
    double stiffness = 0;   // N/m
    double restLength = 0;  // m
    double damping = 0;     // N s/m
};

// A viscous torque between two parts, -c (omega_b - omega_a) on b, while they
// are separate bodies (inside one body it is internal and vanishes).
struct RotaryDamper {
    PartId a = -1, b = -1;
    double damping = 0;  // N m s
};

// A constant applied force at a point of a part (world directions) and a
// torque: the engine's "external forces". Their work is booked as the user's.
struct AppliedLoad {
    PartId part = -1;
    Vec2 local = Vec2::Zero();  // where, in the part's frame (m)
    Vec2 force = Vec2::Zero();  // N
    double torque = 0;          // N m
};

// The mouse spring of docs/model.md section 11.3, pulling a point of a part.
struct UserDrag {
    PartId part = -1;
    Vec2 local = Vec2::Zero();
    Vec2 target = Vec2::Zero();
    double stiffness = 0, damping = 0, maxForce = 0;
};

// A failure of an operation, in words, with no state changed.
struct WorldError {
    std::string message;
};

class World {
public:
    World();

    // ---- building ----
    // A box of in-plane size `size` (extent along its local x and y) and
    // out-of-plane `width`; inertia from the box unless given.
    PartId addBox(double mass, const Vec2& size, double width, const Pose& pose, const Twist& velocity = {},
                  std::optional<double> inertia = {});
    PartId addPoint(double mass, const Vec2& position, const Vec2& velocity = Vec2::Zero());
    ParticleId addParticle(PartId part, const Vec2& local);  // a point on a part
    ParticleId anchor(const Vec2& worldPoint);               // a point on the ground
    int addSpring(const Spring& s);
    int addRotaryDamper(const RotaryDamper& d);
    void setRotaryDamping(int id, double damping) {
        touch();
        dampers_[size_t(id)].damping = damping;
    }
    // The editing accessors are named apart from the reading ones: each
    // marks the world changed (a new revision), and a read through a
    // non-const World that chose them would throw away every cache keyed
    // on the revision (the pins' factorisation, the weights, the bound on
    // the step) at every evaluation.
    std::vector<AppliedLoad>& editLoads() {
        touch();
        return loads_;
    }
    const std::vector<AppliedLoad>& loads() const { return loads_; }
    static constexpr PartId ground = 0;

    // ---- restructuring (the paper's combine and separate) ----
    // They only restructure: every part keeps its pose and the momentum of
    // its body (a merge is a plastic impact among the merged parts, a split
    // changes no velocity). Closing the pins and making the velocities
    // consistent is the caller's (projection.h: makeConsistentAfter, or
    // closePinGaps before an impact's own projection), which knows what
    // changed and how many changes come before one projection.
    // combine(p, q): q is absorbed into p. Two points of different bodies
    // become a hinge; a second shared point between the same two bodies
    // makes them one rigid body (at their current relative pose); a point
    // part joins whatever it is combined with.
    std::optional<WorldError> combine(ParticleId p, ParticleId q);
    // separate(p): undoes the last combine into p.
    std::optional<WorldError> separate(ParticleId p);
    // Many combines (or separates) as one change of structure: the parts
    // regroup once, in O(k log k) for the k parts of the bodies concerned,
    // rather than once per pair. Positions and velocities are left as they
    // are (a caller joining parts at rest relative to each other, or
    // splitting a rigid body, needs no projection). Every pair is checked
    // first: on an error nothing has changed.
    std::optional<WorldError> combine(const std::vector<std::pair<ParticleId, ParticleId>>& pairs);
    std::optional<WorldError> separate(const std::vector<ParticleId>& particles);
    bool isLive(ParticleId p) const;
    bool validParticle(ParticleId p) const { return p >= 0 && p < int(particles_.size()); }
    bool validPart(PartId p) const { return p >= 0 && p < int(parts_.size()); }

    void setDamping(PartId p, double linear, double angular);
    // The parts with air damping, in order: the forces visit these alone (a
    // Part is a long stride, and on a long ladder most have none).
    const std::vector<PartId>& dampedParts() const { return dampedParts_; }

    // ---- holding ----
    void hold(PartId part, const Drive& drive);  // the part follows the path (the caller projects)
    void release(PartId part);                   // keeps its current velocity
    // Poses, velocities and accelerations of kinematic bodies at time t
    // (right-continuous where a hand's move starts or stops), or at t along
    // the piece of each path that holds `within` (Drive::at).
    void updateKinematics(double t) { updateKinematics(t, t); }
    void updateKinematics(double t, double within);
    // Whether every held block's path is on one piece from a to b: no
    // move of the hand starts or stops in (a, b].
    bool pathsOnOnePiece(double a, double b) const;
    bool isHeld(PartId part) const { return parts_[part].drive.has_value(); }
    // A held part's path, to add moves to (a new revision, as editLoads()).
    Drive* editDrive(PartId part) {
        touch();
        return parts_[part].drive ? &*parts_[part].drive : nullptr;
    }

    // ---- state ----
    int bodyCount() const { return int(bodies_.size()); }
    int partCount() const { return int(parts_.size()); }
    int particleCount() const { return int(particles_.size()); }
    const Body& body(int b) const { return bodies_[b]; }
    const Part& part(PartId p) const { return parts_[p]; }
    const Particle& particle(ParticleId p) const { return particles_[p]; }
    // What the world holds on the heap (jl/base/heap_bytes.h): what a copy
    // of it takes, for the budgets that keep copies.
    std::size_t heapBytes() const;
    // f(attachment) for each point particle p lies at: its own first. An
    // absorbed particle cannot change while it is absorbed (combine and
    // separate take live particles), so this is what combine appended.
    template <class F>
    void forEachAttachment(ParticleId p, F&& f) const {
        f(particles_[size_t(p)].own);
        forEachAbsorbed(p, [&](ParticleId q) { forEachAttachment(q, f); });
    }
    // f(q) for each particle q combined into p, in the order they were.
    template <class F>
    void forEachAbsorbed(ParticleId p, F&& f) const {
        stackUpTo(particles_[size_t(p)].lastAbsorbed, f);
    }
    std::vector<Attachment> attachments(ParticleId p) const;
    const std::vector<Pin>& pins() const;  // re-derived after a change of structure
    // What the passes of every evaluation ask of each body, in flat arrays
    // re-derived after a change of structure (a Body, with its list of
    // parts, is a long stride to read a flag from): the alive kinematic
    // bodies, a flag per body (1: kinematic), and each alive dynamic body's
    // weight m g (3 per body, as force; the length of q), and on each of its
    // coordinates with an inverse mass the number of its parts, 0 on the
    // others (the length of q; the adaptive integrators' error norm weighs
    // a coordinate by it).
    const std::vector<int>& kinematicBodies() const;
    const std::vector<unsigned char>& kinematicFlags() const;
    const Eigen::VectorXd& weights() const;
    const Eigen::VectorXd& coordinateParts() const;
    const std::vector<Weld>& welds() const;  // empty unless weld mode; with pins()
    // Constraint rows: 2 per pin, then 1 per weld.
    int constraintRows() const { return int(2 * pins().size() + welds().size()); }

    // Model choice for rigid pairs (the benchmark's "model only what a scene
    // needs"): false (default) merges parts that share two particles into
    // one body; true keeps every extended part its own body and holds such
    // pairs together with a pin and a weld instead. Set before building.
    void setWeldRigidPairs(bool on) {
        touch();
        weldRigidPairs_ = on;
    }
    bool weldsRigidPairs() const { return weldRigidPairs_; }
    const std::vector<Spring>& springs() const { return springs_; }
    const std::vector<RotaryDamper>& rotaryDampers() const { return dampers_; }
    std::vector<UserDrag>& editDrags() {
        touch();
        return drags_;
    }
    const std::vector<UserDrag>& drags() const { return drags_; }
    // The resting contacts between non-neighbouring blocks (docs/model.md
    // section 17): unilateral rows solved on top of the pins.
    std::vector<Contact>& editContacts() {
        touch();
        return contacts_;
    }
    const std::vector<Contact>& contacts() const { return contacts_; }

    Pose bodyPose(int b) const { return {q.segment<2>(3 * b), q[3 * b + 2]}; }
    Twist bodyVelocity(int b) const { return {v.segment<2>(3 * b), v[3 * b + 2]}; }
    Pose partPose(PartId p) const;
    Twist partVelocity(PartId p) const;  // of the part's centre
    Vec2 pointPosition(PartId p, const Vec2& local) const;
    Vec2 pointVelocity(PartId p, const Vec2& local) const;
    Vec2 particlePosition(ParticleId p) const;
    Vec2 particleVelocity(ParticleId p) const;
    void setPartState(PartId p, const Pose& pose, const Twist& velocity);  // moves its body
    // Gives every dynamic body the momentum of its parts at these velocities
    // (one per part; the ground's ignored): a plastic merge of each body.
    void setPartVelocities(const std::vector<Twist>& velocities);
    std::vector<Twist> partVelocities() const;

    // Generalised coordinates and velocities (x, y, angle per body) and the
    // accelerations of the last evaluation; the integrators work on these.
    // They may be longer than 3 * bodyCount() (zero padding, grown
    // geometrically while building); shrinkToFit() trims them.
    Eigen::VectorXd q, v, a;
    Eigen::VectorXd invMassDiag;  // 3 per body; 0 for kinematic and dead bodies
    Vec2 gravity{0, -9.81};

    void shrinkToFit();
    // Renumbers the bodies so that the live ones are 0, 1, 2, ... in their
    // order, with no dead ones between them: after a merge of thousands of
    // bodies into one, every pass over the bodies (the integrators' vector
    // updates, the solver's turns) would otherwise walk the dead. A change
    // of structure: body numbers held elsewhere are stale after it.
    void compactBodies();

    // Bumped by every change of structure (bodies or pins).
    long long structureVersion() const { return structureVersion_; }
    // A number no state of any world has had before, taken anew by every
    // change other than to q, v, a and gravity (every non-const member but
    // updateKinematics, the accessors handing out references included): two
    // worlds with one revision differ at most in those, so an evaluation
    // kept with its q, v and time still holds if they are equal.
    std::uint64_t revision() const { return revision_; }

    // How closely the projection after combine, separate and hold closes
    // the pins (m): to rounding, tighter than a step's projection, so that a
    // lock or a grab leaves no gap for the next step to see (docs/model.md
    // section 3.4).
    double restructureTolerance = 1e-12;

    // The buffers the engine's operations on this world reuse from call to
    // call (core/engine/scratch.h): the world's own, shared with no other.
    Scratch& scratch() const { return *scratch_; }

private:
    static std::uint64_t freshRevision();
    void touch() { revision_ = freshRevision(); }

    Fresh<Scratch> scratch_;

    std::optional<WorldError> checkParticle(ParticleId p) const;
    std::optional<WorldError> checkCombine(ParticleId p, ParticleId q) const;
    std::optional<WorldError> checkSeparate(ParticleId p) const;
    void absorb(ParticleId p, ParticleId q, std::vector<int>& touched);  // q into p; the bodies it touches
    void unabsorb(ParticleId p, std::vector<int>& touched);              // the last absorbed out of p
    void regroup(const std::vector<int>& touchedBodies);
    // f(q) for the stack whose top is `top`, from its bottom up.
    template <class F>
    void stackUpTo(ParticleId top, F& f) const {
        if (top < 0) return;
        stackUpTo(particles_[size_t(top)].absorbedBefore, f);
        f(top);
    }
    std::vector<std::vector<PartId>> rigidGroups(const std::vector<PartId>& parts) const;
    int makeBody(const std::vector<PartId>& parts, const std::vector<Pose>& partPoses,
                 const std::vector<Twist>& partVelocities);
    int allocateBody();
    void rebuildPins() const;
    void updatePinning() const;
    void indexBodies() const;
    void weldSharedPairs() const;

    std::vector<Part> parts_;
    std::vector<Body> bodies_;
    std::vector<Particle> particles_;
    std::vector<std::vector<ParticleId>> particlesOfPart_;  // every particle ever on the part
    mutable std::vector<Pin> pins_;
    // The live particles whose attachments lie on two or more bodies (not
    // all kinematic), ascending: the only ones that make pins. Brought up to
    // date with the pins for the particles of the parts regrouped since
    // (`regrouped_`), so that deriving the pins after a lock or a wake of
    // the still tail costs what the moving bodies' pins number, not a pass
    // over every particle of a long ladder.
    mutable std::vector<ParticleId> pinning_;
    mutable std::vector<PartId> regrouped_;
    mutable std::vector<Weld> welds_;
    mutable bool pinsStale_ = false;
    // indexBodies: valid for this structure, gravity and length of q.
    mutable long long indexedVersion_ = -1;
    mutable Vec2 indexedGravity_ = Vec2::Zero();
    mutable std::vector<int> kinematicBodies_;
    mutable std::vector<unsigned char> kinematicFlags_;
    mutable Eigen::VectorXd weights_;
    mutable Eigen::VectorXd coordinateParts_;
    std::vector<Spring> springs_;
    std::vector<RotaryDamper> dampers_;
    std::vector<UserDrag> drags_;
    std::vector<AppliedLoad> loads_;
    std::vector<Contact> contacts_;
    std::vector<int> freeBodies_;      // a heap, the smallest number on top: reused first
    std::vector<PartId> dampedParts_;  // ascending
    long long structureVersion_ = 0;
    std::uint64_t revision_ = freshRevision();
    bool weldRigidPairs_ = false;
};

}  // namespace jl
