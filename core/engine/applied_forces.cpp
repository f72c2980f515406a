// The force laws of the applied forces that need more than a line, and
// the energy a spring stores.
#include "jl/engine/applied_forces.h"

namespace jl {

bool springForce(const World& w, const Spring& s, Vec2& xa, Vec2& xb, Vec2& f, double& rate) {
    if (!w.validParticle(s.a) || !w.validParticle(s.b)) return false;
    xa = w.particlePosition(s.a);
    xb = w.particlePosition(s.b);
    const Vec2 d = xb - xa;
    const double len = d.norm();
    if (len <= 0) return false;
    const Vec2 u = d / len;
    rate = (w.particleVelocity(s.b) - w.particleVelocity(s.a)).dot(u);
    f = (s.stiffness * (len - s.restLength) + s.damping * rate) * u;
    return true;
}

double elasticEnergy(const World& w, const Spring& s) {
    if (!w.validParticle(s.a) || !w.validParticle(s.b)) return 0;  // an absorbed end still acts
    const double stretch = (w.particlePosition(s.b) - w.particlePosition(s.a)).norm() - s.restLength;
    return 0.5 * s.stiffness * stretch * stretch;
}

Vec2 dragForce(const World& w, const UserDrag& g, Vec2& x, Vec2& vx) {
    x = w.pointPosition(g.part, g.local);
    vx = w.pointVelocity(g.part, g.local);
    Vec2 f = g.stiffness * (g.target - x) - g.damping * vx;
    const double n = f.norm();
    if (n > g.maxForce && n > 0) f *= g.maxForce / n;
    return f;
}

bool onlyWeights(const World& w) {
    return w.dampedParts().empty() && w.springs().empty() && w.rotaryDampers().empty() && w.loads().empty() &&
           w.drags().empty();
}

}  // namespace jl
