// Test support: the known-answer cases that the integrator suites share.
#pragma once

#include "jl/engine/motion.h"
#include "jl/engine/projection.h"
#include "jl/ladder/ladder.h"
#include "jl/reference/elliptic.h"
#include "jl/scene/scene_io.h"
#include "jl/sim/simulation.h"
#include "tests/restructure_closed.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>

namespace jl::test {

// A block 60 x 12 x 45 mm of density 600 swinging from a corner pinned to
// the ground, released at theta0 from its hanging pose, in n equal steps of
// `kind` over one exact period (the complete elliptic integral): how far it
// is from where it began (angle, and angular speed over the small-swing
// frequency).
inline double pendulumErrorAfterOnePeriod(Integrator kind, double theta0, int n, double projection = 1e-13) {
    constexpr double L = 0.06, T = 0.012, W = 0.045, rho = 600, g = 9.81;
    const double mass = rho * L * T * W, r = std::hypot(L / 2, T / 2);
    const double inertia = mass * (L * L + T * T) / 12 + mass * r * r;
    const Vec2 corner(-L / 2, -T / 2);
    const double rest = std::numbers::pi / 2 - std::atan2(corner.y(), corner.x());
    World w;
    const PartId block = w.addBox(mass, Vec2(L, T), W, Pose{-rotate(rest + theta0, corner), rest + theta0});
    combineClosed(w, w.anchor(Vec2::Zero()), w.addParticle(block, corner));
    const double period = pendulumPeriod(inertia, mass, g, r, theta0), h = period / n;
    Dynamics d;
    Stepper s(kind);
    Ledger ledger;
    for (int i = 0; i < n; ++i)
        if (!advanceAndProject(w, d, s, i * h, h, ledger, projection, true).ok()) return INFINITY;
    const double omegaScale = std::sqrt(mass * g * r / inertia);
    return std::hypot(w.partPose(block).angle - rest - theta0, w.partVelocity(block).angular / omegaScale);
}

// A ladder of n blocks hanging at rest from its held top block, every block
// given a small random spin (made consistent with the pins): all its modes
// ring, the fastest (neighbouring blocks rocking against each other) included.
struct RingingLadder {
    World world;
    std::optional<Ladder> ladder;
    explicit RingingLadder(int n) {
        LadderSpec spec;
        spec.blocks = n;
        ladder.emplace(world, spec);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> spin(-0.05, 0.05);  // rad/s
        for (int b = 0; b < world.bodyCount(); ++b)
            if (world.invMassDiag[3 * b + 2] > 0) world.v[3 * b + 2] = spin(random);
        projectVelocities(world);
    }
};

// The classic example's cascade for 3 s with `kind` at `tolerance`.
inline Frame classicCascade(Integrator kind, double tolerance) {
    SceneLoad loaded = loadScene(std::string(JL_SOURCE_DIR) + "/examples/classic.yaml");
    Scene s = *loaded.scene;
    s.solver.integrator = kind;
    s.solver.tolerance = tolerance;
    Simulation::Built built = Simulation::build(s);
    built.simulation->advanceExactlyTo(3.0);
    return built.simulation->frame();
}

// The largest difference in time of the same events (kind and hinge) of
// two runs; infinite if the sequences differ.
inline double worstEventTimeDifference(const Frame& a, const Frame& b) {
    if (a.events.size() != b.events.size()) return INFINITY;
    double worst = 0;
    for (size_t i = 0; i < a.events.size(); ++i) {
        if (a.events[i].kind != b.events[i].kind || a.events[i].hinge != b.events[i].hinge) return INFINITY;
        worst = std::max(worst, std::abs(a.events[i].time - b.events[i].time));
    }
    return worst;
}

}  // namespace jl::test
