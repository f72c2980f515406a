// The contact forces of a hinge: the wrench one side of it exerts on the
// other (summed over the side inside one rigid body, or what the pin and the
// weld carry in weld mode), and its split into the pin and the normal
// forces at the corners, against the thresholds that tell a pull.
#include "jl/engine/applied_forces.h"
#include "jl/ladder/ladder.h"

#include <algorithm>
#include <cmath>

namespace jl {

// The wrench (about hinge j's point) that the blocks above exert on the
// blocks below, inside one rigid body: what the lower side needs for its
// motion, less what gravity, drags and other pins supply. With `impact` it
// is the impulse of an impact instead (the world holds the velocities after
// it; the part velocities before it and the pin impulses are
// passed along with them).
Ladder::Wrench Ladder::internalWrench(const World& w, const Dynamics& d, int j, const Impact* impact) const {
    if (w.weldsRigidPairs()) return weldWrench(w, d, j, impact);
    const int body = w.part(block(j)).body;
    int lo = j - 1, hi = j;
    while (lo > 0 && w.part(block(lo - 1)).body == body) --lo;
    while (hi + 1 < blockCount() && w.part(block(hi + 1)).body == body) ++hi;
    bool heldBelow = false;
    for (int i = j; i <= hi; ++i) heldBelow = heldBelow || w.isHeld(block(i));
    // Sum over the side without the hand; the wrench on the other is opposite.
    const int first = heldBelow ? lo : j, last = heldBelow ? j - 1 : hi;
    const double sign = heldBelow ? -1.0 : 1.0;
    const Vec2 p = cornerWorld(w, j, hinge(j).corner);
    Wrench s;
    addSideMotion(s, w, body, first, last, p, impact);
    // Pins to other bodies act on the side too.
    addPinsOnSide(s, w, impact ? *impact->pinImpulses : d.pinForces(), first, last, p);
    addContactsOnSide(s, w, d, impact, first, last, p);
    // Rotary dampers from outside the body (none in an impact).
    if (!impact) addDampersOnSide(s, w, first, last);
    s.force *= sign;
    s.moment *= sign;
    return s;
}

// Whether a part is one of the blocks first .. last.
bool Ladder::onSide(PartId part, int first, int last) const {
    for (int i = first; i <= last; ++i)
        if (block(i) == part) return true;
    return false;
}

// What the motion of blocks first .. last (of one rigid body) needs, less
// what the applied forces supply; in an impact, their change of momentum.
void Ladder::addSideMotion(Wrench& s, const World& w, int body, int first, int last, const Vec2& p,
                           const Impact* impact) const {
    const Vec2 origin = w.q.segment<2>(3 * body);
    const double omega = w.v[3 * body + 2], alpha = w.a[3 * body + 2];
    for (int i = first; i <= last; ++i) {
        const Part& part = w.part(block(i));
        const Vec2 c = w.partPose(block(i)).position;
        if (impact) {
            const Twist before = (*impact->before)[size_t(block(i))];
            const Twist after = w.partVelocity(block(i));
            const Vec2 dp = part.mass * (after.linear - before.linear);
            s.force += dp;
            s.moment += part.inertia * (after.angular - before.angular) + cross(c - p, dp);
            continue;
        }
        // What the block's motion needs, less what the applied forces supply.
        const Vec2 r = c - origin;
        const Vec2 acc = w.a.segment<2>(3 * body) + alpha * perp(r) - omega * omega * r;
        const AppliedWrench applied = appliedOnPart(w, block(i), p);
        s.force += part.mass * acc - applied.force;
        s.moment += part.inertia * alpha + cross(c - p, part.mass * acc) - applied.moment;
    }
}

// The pins' forces (or impulses) `lambda` on blocks first .. last.
void Ladder::addPinsOnSide(Wrench& s, const World& w, const Eigen::VectorXd& lambda, int first, int last,
                           const Vec2& p) const {
    const std::vector<Pin>& pins = w.pins();
    for (size_t i = 0; i < pins.size(); ++i) {
        const Pin& pin = pins[i];
        const Vec2 l = lambda.segment<2>(2 * Eigen::Index(i));
        if (onSide(pin.partA, first, last)) {
            const Vec2 x = w.bodyPose(pin.bodyA).apply(pin.localA);
            s.force -= l;
            s.moment -= cross(x - p, l);
        }
        if (onSide(pin.partB, first, last)) {
            const Vec2 x = w.bodyPose(pin.bodyB).apply(pin.localB);
            s.force += l;
            s.moment += cross(x - p, l);
        }
    }
}

// Contacts with blocks that are not neighbours push on the side too
// (their pushes follow the pins' impulses in an impact's).
void Ladder::addContactsOnSide(Wrench& s, const World& w, const Dynamics& d, const Impact* impact, int first, int last,
                               const Vec2& p) const {
    const std::vector<Contact>& contacts = w.contacts();
    const Eigen::Index firstPush = impact ? Eigen::Index(w.constraintRows()) : 0;
    const Eigen::VectorXd& push = impact ? *impact->pinImpulses : d.contactForces();
    for (size_t i = 0; i < contacts.size() && firstPush + Eigen::Index(i) < push.size(); ++i) {
        const Vec2 x = w.pointPosition(contacts[i].cornerPart, contacts[i].corner);
        const Vec2 f =
            push[firstPush + Eigen::Index(i)] * rotate(w.partPose(contacts[i].facePart).angle, contacts[i].normal);
        const double sides =
            double(onSide(contacts[i].cornerPart, first, last)) - double(onSide(contacts[i].facePart, first, last));
        s.force -= sides * f;
        s.moment -= sides * cross(x - p, f);
    }
}

// The rotary dampers between blocks of two bodies, on the side: applied
// forces like those of addSideMotion, less what they supply, but summed
// after the pins and contacts (one damper's two ends may be on the side).
void Ladder::addDampersOnSide(Wrench& s, const World& w, int first, int last) const {
    forEachAppliedForce(w, AppliedForce::RotaryDamper, -1, [&](const AppliedForce& a) {
        if (onSide(a.part, first, last)) s.moment -= a.torque;
    });
}

// Weld mode: the two blocks stay separate bodies, so the wrench is what the
// pin and the weld between them carry (their multipliers), not a sum over
// a side. No weld between them (the hand holds both): no wrench to test.
Ladder::Wrench Ladder::weldWrench(const World& w, const Dynamics& d, int j, const Impact* impact) const {
    const int below = w.part(block(j)).body, above = w.part(block(j - 1)).body;
    const std::vector<Pin>& pins = w.pins();
    const std::vector<Weld>& welds = w.welds();
    const Eigen::VectorXd& lambda = impact ? *impact->pinImpulses : d.pinForces();
    const Vec2 p = cornerWorld(w, j, hinge(j).corner);
    Wrench s;
    for (size_t i = 0; i < welds.size(); ++i) {
        const Pin& pin = pins[size_t(welds[i].pin)];
        if (!((pin.bodyA == above && pin.bodyB == below) || (pin.bodyA == below && pin.bodyB == above))) continue;
        // Pin force l and weld moment arm * mu act on A; minus them on B.
        const double sign = pin.bodyB == below ? -1.0 : 1.0;
        const Vec2 l = lambda.segment<2>(2 * Eigen::Index(welds[i].pin));
        const double mu = lambda[2 * Eigen::Index(pins.size()) + Eigen::Index(i)];
        const Vec2 x = w.bodyPose(pin.bodyA).apply(pin.localA);
        s.force = sign * l;
        s.moment = sign * (welds[i].arm * mu + cross(x - p, l));
        break;
    }
    return s;
}

// Splits the wrench on block j into pin + normal forces (docs/model.md section 8.3).
HingeContact Ladder::split(const World& w, int j, const Wrench& on) const {
    const int k = hinge(j).corner;
    const Vec2 pk = cornerWorld(w, j - 1, k);
    const Vec2 da = (cornerWorld(w, j - 1, k ^ 1) - pk).normalized();
    const Vec2 na = (cornerWorld(w, j - 1, k ^ 2) - pk).normalized();
    HingeContact c;
    if (hinge(j).mode == HingeMode::OpenLocked) {
        // N acts at the far side of the shared end face, along -d_a.
        const double t = std::min(thickness_[size_t(j - 1)], thickness_[size_t(j)]);
        c.normal = -on.moment / cross(t * na, da);
        c.load = on.force.norm() + std::abs(c.normal);
    } else if (hinge(j).mode == HingeMode::Folded) {
        const double lever = length_ * cross(da, na);
        c.farEnd = -on.moment / lever;                                    // pin at k, N at k^1
        c.nearEnd = (on.moment - length_ * cross(da, on.force)) / lever;  // pin at k^1, N at k
        c.load = on.force.norm() + std::abs(c.nearEnd) + std::abs(c.farEnd);
    }
    return c;
}

HingeContact Ladder::contact(const World& w, const Dynamics& d, int j) const {
    if (hinge(j).mode != HingeMode::OpenLocked && hinge(j).mode != HingeMode::Folded) return {};
    return split(w, j, internalWrench(w, d, j, nullptr));
}

// The ladder's threshold is 1e-8 of its lightest block's weight (5e-8 of
// it times sqrt(L/g) for impulses); a contact's load raises it by the same
// fraction (docs/model.md section 8.3, "How small counts as zero").
double Ladder::pullThreshold(const HingeContact& c, bool impulse) const {
    return impulse ? std::max(impulseTolerance_, 5e-8 * c.load) : std::max(forceTolerance_, 1e-8 * c.load);
}

}  // namespace jl
