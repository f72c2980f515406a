#include "bench/peers.h"

#include "jl/base/thread_clock.h"

#include <algorithm>
#include <cmath>
#include <functional>

#ifdef JL_BENCH_PEERS
#include "bench/mujoco_chain.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <LinearMath/btScalar.h>
#include <box2d/box2d.h>
#include <btBulletDynamicsCommon.h>
#include <mujoco/mujoco.h>
#endif

#include <cstdio>
#include <memory>
#include <string>

namespace jl::bench {

#ifdef JL_BENCH_PEERS

namespace {

// The falling chain of docs/model.md section 16.1.
constexpr double kL = 0.06, kT = 0.012, kW = 0.045, kRho = 600, kG = 9.81;
constexpr double kMass = kRho * kL * kT * kW;

// One run of a peer: builds a fresh model, steps it, returns the block
// centres in the ladder plane (x right, y up) or an empty vector on NaN.
using PeerRunner = std::function<std::vector<Vec2>(int n, double h, int steps)>;

std::vector<Vec2> runMujoco(int n, double h, int steps, const char* integrator) {
    // Nested bodies, each a box hinged at its inner end about +y; gravity -z.
    // The plane is x-z: our y is MuJoCo's z.
    char geom[256];
    std::snprintf(geom, sizeof geom, "<geom type='box' size='%.17g %.17g %.17g' pos='%.17g 0 0' mass='%.17g'/>", kL / 2,
                  kW / 2, kT / 2, kL / 2, kMass);
    std::vector<std::string> bodies;
    for (int i = 0; i < n; ++i)
        bodies.push_back(std::string("<body pos='") + (i == 0 ? "0" : std::to_string(kL)) +
                         " 0 0'><joint type='hinge' axis='0 1 0'/>" + geom);
    mjModel* m = loadNestedChain("<compiler angle='radian'/><option timestep='" + std::to_string(h) + "' integrator='" +
                                     integrator + "' gravity='0 0 -9.81'><flag contact='disable'/></option>",
                                 bodies);
    if (!m) return {};
    mjData* d = mj_makeData(m);
    for (int s = 0; s < steps; ++s) mj_step(m, d);
    // mj_step leaves the positions of the bodies (xipos) where its last
    // step started: they are computed from the state after it here.
    mj_forward(m, d);
    std::vector<Vec2> out;
    for (int i = 1; i <= n; ++i) {
        const double* c = d->xipos + 3 * i;
        if (!std::isfinite(c[0]) || !std::isfinite(c[2])) {
            out.clear();
            break;
        }
        out.emplace_back(c[0], c[2]);
    }
    mj_deleteData(d);
    mj_deleteModel(m);
    return out;
}

std::vector<Vec2> runBox2d(int n, double h, int steps, int velocityIterations, int positionIterations) {
    b2World world(b2Vec2(0, float(-kG)));
    b2BodyDef groundDef;
    b2Body* ground = world.CreateBody(&groundDef);
    b2PolygonShape box;
    box.SetAsBox(float(kL / 2), float(kT / 2));
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.density = float(kRho * kW);  // per area: mass = rho W L T
    fixture.filter.maskBits = 0;         // no contacts: the chain's links may cross
    std::vector<b2Body*> bodies;
    b2Body* previous = ground;
    for (int i = 0; i < n; ++i) {
        b2BodyDef def;
        def.type = b2_dynamicBody;
        def.position.Set(float((i + 0.5) * kL), 0);
        b2Body* b = world.CreateBody(&def);
        b->CreateFixture(&fixture);
        b2RevoluteJointDef joint;
        joint.Initialize(previous, b, b2Vec2(float(i * kL), 0));
        world.CreateJoint(&joint);
        bodies.push_back(b);
        previous = b;
    }
    for (int s = 0; s < steps; ++s) world.Step(float(h), velocityIterations, positionIterations);
    std::vector<Vec2> out;
    for (b2Body* b : bodies) {
        const b2Vec2 c = b->GetWorldCenter();
        if (!std::isfinite(c.x) || !std::isfinite(c.y)) return {};
        out.emplace_back(c.x, c.y);
    }
    return out;
}

std::vector<Vec2> runBullet(int n, double h, int steps, bool rk4) {
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btMultiBodyConstraintSolver solver;
    btMultiBodyDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, 0, btScalar(-kG)));
    auto body = std::make_unique<btMultiBody>(n, btScalar(0), btVector3(0, 0, 0), true, false);
    const btVector3 inertia(btScalar(kMass * (kW * kW + kT * kT) / 12), btScalar(kMass * (kL * kL + kT * kT) / 12),
                            btScalar(kMass * (kL * kL + kW * kW) / 12));
    for (int i = 0; i < n; ++i)
        body->setupRevolute(i, btScalar(kMass), inertia, i - 1, btQuaternion(0, 0, 0, 1), btVector3(0, 1, 0),
                            btVector3(i == 0 ? 0 : btScalar(kL / 2), 0, 0), btVector3(btScalar(kL / 2), 0, 0), true);
    body->finalizeMultiDof();
    body->setLinearDamping(0);
    body->setAngularDamping(0);
    body->setMaxCoordinateVelocity(btScalar(1e6));
    body->setMaxAppliedImpulse(btScalar(1e6));
    body->useRK4Integration(rk4);
    body->setCanSleep(false);
    world.addMultiBody(body.get());
    for (int s = 0; s < steps; ++s) world.stepSimulation(btScalar(h), 0, btScalar(h));
    std::vector<Vec2> out;
    for (int i = 0; i < n; ++i) {
        const btVector3 c = body->localPosToWorld(i, btVector3(0, 0, 0));
        if (!std::isfinite(double(c.x())) || !std::isfinite(double(c.z()))) return {};
        out.emplace_back(double(c.x()), double(c.z()));
    }
    world.removeMultiBody(body.get());
    return out;
}

}  // namespace

std::vector<PeerRun> measurePeers(int n, const std::vector<double>& steps, double duration,
                                  const std::vector<Vec2>& reference, double minSeconds) {
    const std::vector<std::pair<std::string, PeerRunner>> peers = {
        {"mujoco rk4", [](int k, double h, int s) { return runMujoco(k, h, s, "RK4"); }},
        {"mujoco euler", [](int k, double h, int s) { return runMujoco(k, h, s, "Euler"); }},
        {"box2d 8/3 iterations", [](int k, double h, int s) { return runBox2d(k, h, s, 8, 3); }},
        {"box2d 100/30 iterations", [](int k, double h, int s) { return runBox2d(k, h, s, 100, 30); }},
        {"bullet featherstone", [](int k, double h, int s) { return runBullet(k, h, s, false); }},
        {"bullet featherstone rk4", [](int k, double h, int s) { return runBullet(k, h, s, true); }},
    };
    std::vector<PeerRun> out;
    for (const auto& [name, runner] : peers) {
        // MuJoCo's dense factorisation and Box2D's iterations take minutes at
        // N = 1,000; there the target (docs/model.md section 16.2) names Bullet only.
        if (n >= 1000 && name.rfind("bullet", 0) != 0) continue;
        for (double h : steps) {
            const int count = int(std::lround(duration / h));
            PeerRun r{name, n, h, 0, 0, true};
            std::vector<Vec2> centres;
            int repeats = 0;
            const double start = threadSeconds();
            do {  // repeat short runs so the clock resolves them
                centres = runner(n, h, count);
                ++repeats;
            } while (threadSeconds() - start < minSeconds && !centres.empty());
            r.cost = (threadSeconds() - start) / repeats / duration;
            if (centres.size() != reference.size()) {
                r.finished = false;
                r.error = NAN;
            } else {
                for (size_t i = 0; i < centres.size(); ++i)
                    r.error = std::max(r.error, (centres[i] - reference[i]).norm());
            }
            std::fprintf(stderr, "  %-26s N=%-5d h=%.1e  cost %.3e s/s  error %.3e m\n", name.c_str(), n, h, r.cost,
                         r.error);
            out.push_back(r);
        }
    }
    return out;
}

std::string peerVersions() {
    return "MuJoCo " + std::string(mj_versionString()) + " (Debian libmujoco-dev), Box2D " +
           std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
           std::to_string(b2_version.revision) + " (libbox2d-dev), Bullet " + std::to_string(btGetVersion()) +
           " double precision (libbullet-dev, float64 libraries)";
}

#else

std::vector<PeerRun> measurePeers(int, const std::vector<double>&, double, const std::vector<Vec2>&, double) {
    return {};
}

std::string peerVersions() { return "not measured: this build has JL_BENCH_PEERS off"; }

#endif

}  // namespace jl::bench
