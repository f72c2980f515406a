#include "jl/engine/stiff_mode.h"

#include "jl/base/short_number.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace jl {

namespace {

// The body a particle moves with, or -1 for one that does not move
// (the ground, a held block).
int movingBody(const World& w, ParticleId p) {
    while (p >= 0 && w.particle(p).mergedInto >= 0) p = w.particle(p).mergedInto;
    if (p < 0) return -1;
    const int b = w.part(w.particle(p).own.part).body;
    return b >= 0 && w.body(b).alive && !w.body(b).kinematic ? b : -1;
}

double invMass(const World& w, int b) { return b >= 0 ? 1 / w.body(b).mass : 0; }
double invInertia(const World& w, int b) { return b >= 0 && w.body(b).inertia > 0 ? 1 / w.body(b).inertia : 0; }

struct Fastest {
    StiffMode mode;
    void offer(double rate, bool decay, const std::string& what) {
        if (std::isfinite(rate) && rate > mode.rate) mode = {rate, decay, what};
    }
};

void pinRocking(Fastest& f, const World& w, const Eigen::VectorXd& pinForces) {
    const std::vector<Pin>& pins = w.pins();
    if (pinForces.size() < 2 * Eigen::Index(pins.size())) return;
    std::vector<double> pull(size_t(w.bodyCount()), 0.0);
    for (size_t i = 0; i < pins.size(); ++i) {
        const double force = pinForces.segment<2>(2 * Eigen::Index(i)).norm();
        if (pins[i].bodyA >= 0) pull[size_t(pins[i].bodyA)] += force * pins[i].localA.norm();
        if (pins[i].bodyB >= 0) pull[size_t(pins[i].bodyB)] += force * pins[i].localB.norm();
    }
    for (int b = 0; b < w.bodyCount(); ++b)
        if (w.body(b).alive && !w.body(b).kinematic && w.body(b).inertia > 0)
            f.offer(std::sqrt(pull[size_t(b)] / w.body(b).inertia), false,
                    "the rocking of body " + std::to_string(b) + " on its pins (inertia " +
                        shortNumber(w.body(b).inertia) + " kg m^2)");
}

void springs(Fastest& f, const World& w) {
    for (size_t i = 0; i < w.springs().size(); ++i) {
        const Spring& s = w.springs()[i];
        const int a = movingBody(w, s.a), b = movingBody(w, s.b);
        const double inverse = invMass(w, a) + invMass(w, b);  // of the reduced mass
        const std::string which = "the spring " + std::to_string(i) + " (";
        f.offer(std::sqrt(s.stiffness * inverse), false,
                which + shortNumber(s.stiffness) + " N/m on " + shortNumber(1 / inverse) + " kg)");
        f.offer(s.damping * inverse, true,
                which + "damping " + shortNumber(s.damping) + " N s/m on " + shortNumber(1 / inverse) + " kg)");
    }
}

void dampers(Fastest& f, const World& w) {
    for (PartId p = 0; p < PartId(w.partCount()); ++p) {
        const Part& part = w.part(p);
        const int b = part.body >= 0 && w.body(part.body).alive && !w.body(part.body).kinematic ? part.body : -1;
        if (b < 0) continue;
        f.offer(part.linearDamping * invMass(w, b), true,
                "air damping " + shortNumber(part.linearDamping) + " N s/m on body " + std::to_string(b) + " (" +
                    shortNumber(w.body(b).mass) + " kg)");
        f.offer(part.angularDamping * invInertia(w, b), true,
                "air damping " + shortNumber(part.angularDamping) + " N m s on body " + std::to_string(b) +
                    " (inertia " + shortNumber(w.body(b).inertia) + " kg m^2)");
    }
    for (const RotaryDamper& d : w.rotaryDampers()) {
        const int a = w.part(d.a).body, b = w.part(d.b).body;
        if (a == b) continue;  // one body: the damper is internal
        const auto inertiaOf = [&](int body) {
            return body >= 0 && w.body(body).alive && !w.body(body).kinematic ? invInertia(w, body) : 0;
        };
        f.offer(d.damping * (inertiaOf(a) + inertiaOf(b)), true,
                "hinge damping " + shortNumber(d.damping) + " N m s between parts " + std::to_string(d.a) + " and " +
                    std::to_string(d.b));
    }
}

}  // namespace

StiffMode stiffestMode(const World& w, const Eigen::VectorXd& pinForces) {
    Fastest f;
    pinRocking(f, w, pinForces);
    springs(f, w);
    dampers(f, w);
    return f.mode;
}

std::string describe(const StiffMode& m) {
    if (m.what.empty()) return "nothing in the scene moves fast";
    if (m.decay)
        return m.what + ": it decays at " + shortNumber(m.rate) + " per s, in " + shortNumber(1 / m.rate) + " s";
    return m.what + ": " + shortNumber(m.rate) + " rad/s, a period of " + shortNumber(2 * std::numbers::pi / m.rate) +
           " s";
}

}  // namespace jl
