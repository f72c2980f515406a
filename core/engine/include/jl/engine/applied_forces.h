// The applied forces of a world, listed once: gravity, air drag, springs,
// rotary dampers, loads and the mouse. The dynamics sums them into the
// bodies' forces and books their power; a locked pair's contact force is
// found against those on one side of it (Ladder); the energy books take the
// potentials of the conservative ones. All walk these lists, so a new kind
// of force is added here and reaches each of them.
#pragma once

#include "jl/engine/world.h"

namespace jl {

// One piece of an applied force: a push at a point of a part, or a couple on
// it. A force between two parts comes as two pieces, one on each.
struct AppliedForce {
    enum Source : unsigned { Weight = 1, Air = 2, Spring = 4, RotaryDamper = 8, Load = 16, Mouse = 32 };
    static constexpr unsigned kAll = Weight | Air | Spring | RotaryDamper | Load | Mouse;
    Source source;
    PartId part;
    bool couple = false;  // a torque alone, else `force` at `at`
    Vec2 at = Vec2::Zero(), force = Vec2::Zero();
    double torque = 0;
    // The power the force's element takes out (damping) or the user puts in,
    // given once per element, with its last piece.
    double dissipated = 0, userPower = 0;
    // A spring's or a damper's end on a held body does work through the
    // hand; the air, a load or the mouse on a held body is taken by the hand.
    bool betweenParts() const { return source == Spring || source == RotaryDamper; }
};

// The force law of a spring-damper, on its end a (minus it on b); false if
// its ends coincide (no direction). An end absorbed by combine still has its
// own attachment at the shared point: the spring keeps acting there.
bool springForce(const World& w, const Spring& s, Vec2& xa, Vec2& xb, Vec2& f, double& rate);
// What one spring stores, 0.5 k (length - rest)^2 (J).
double elasticEnergy(const World& w, const Spring& s);
// The mouse spring of docs/model.md section 11.3 at its point x, capped.
Vec2 dragForce(const World& w, const UserDrag& g, Vec2& x, Vec2& vx);
// True when the world's only applied forces are the weights (World::weights()).
bool onlyWeights(const World& w);

// The potential energy of each conservative applied force but the weights
// (whose potential goes with each body's mass: jl::energy), handed to `add`:
// the energy books' side of the list below.
template <class Add>
void forEachAppliedPotential(const World& w, Add&& add) {
    for (const jl::Spring& s : w.springs()) add(elasticEnergy(w, s));
}

// Visits the pieces of the `sources` (AppliedForce::Source bits), in a fixed
// order: each source in turn, each element's pieces together. With `only` a
// part, the pieces on that part alone; without (-1), every piece, but no
// weights: the world keeps their sums per body (World::weights()).
template <class Visit>
void forEachAppliedForce(const World& w, unsigned sources, PartId only, Visit&& visit) {
    using F = AppliedForce;
    const bool all = only < 0;
    auto on = [&](PartId p) { return all || p == only; };
    if ((sources & F::Weight) && !all) {
        const Part& part = w.part(only);
        visit(F{F::Weight, only, false, w.partPose(only).position, part.mass * w.gravity});
    }
    if (sources & F::Air) {
        auto air = [&](PartId p) {
            const Part& part = w.part(p);
            const Twist vel = w.partVelocity(p);
            visit(F{F::Air, p, false, w.partPose(p).position, -part.linearDamping * vel.linear});
            F turn{F::Air, p, true};
            turn.torque = -part.angularDamping * vel.angular;
            turn.dissipated =
                part.linearDamping * vel.linear.squaredNorm() + part.angularDamping * vel.angular * vel.angular;
            visit(turn);
        };
        if (!all)
            air(only);
        else
            for (PartId p : w.dampedParts())
                if (p != World::ground) air(p);
    }
    if (sources & F::Spring)
        for (const jl::Spring& s : w.springs()) {
            Vec2 xa, xb, f;  // f on a
            double rate = 0;
            if (!springForce(w, s, xa, xb, f, rate)) continue;
            const PartId pa = w.particle(s.a).own.part, pb = w.particle(s.b).own.part;
            if (on(pa)) visit(F{F::Spring, pa, false, xa, f});
            F end{F::Spring, pb, false, xb, -f};
            end.dissipated = s.damping * rate * rate;
            if (on(pb)) visit(end);
        }
    if (sources & F::RotaryDamper)
        for (const jl::RotaryDamper& d : w.rotaryDampers()) {
            const int ba = w.part(d.a).body, bb = w.part(d.b).body;
            if (ba == bb) continue;  // locked together: internal
            const double rel = w.v[3 * bb + 2] - w.v[3 * ba + 2];
            F onB{F::RotaryDamper, d.b, true}, onA{F::RotaryDamper, d.a, true};
            onB.torque = -d.damping * rel;
            onA.torque = d.damping * rel;
            onA.dissipated = d.damping * rel * rel;
            if (on(d.b)) visit(onB);
            if (on(d.a)) visit(onA);
        }
    if (sources & F::Load)
        for (const AppliedLoad& l : w.loads()) {
            if (!on(l.part)) continue;
            visit(F{F::Load, l.part, false, w.pointPosition(l.part, l.local), l.force});
            F turn{F::Load, l.part, true};
            turn.torque = l.torque;
            turn.userPower = l.force.dot(w.pointVelocity(l.part, l.local)) + l.torque * w.partVelocity(l.part).angular;
            visit(turn);
        }
    if (sources & F::Mouse)
        for (const UserDrag& g : w.drags()) {
            if (!on(g.part)) continue;
            Vec2 x, vx;
            const Vec2 f = dragForce(w, g, x, vx);
            F pull{F::Mouse, g.part, false, x, f};
            pull.userPower = f.dot(vx);
            visit(pull);
        }
}

}  // namespace jl
