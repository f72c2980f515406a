#include "bench/folding_peers.h"

#include "jl/base/thread_clock.h"

#include <cmath>
#include <cstdio>
#include <functional>
#include <memory>

#ifdef JL_BENCH_PEERS
#include "bench/mujoco_chain.h"

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointLimitConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <LinearMath/btScalar.h>
#include <algorithm>
#include <box2d/box2d.h>
#include <btBulletDynamicsCommon.h>
#include <cctype>
#include <mujoco/mujoco.h>
#endif

namespace jl::bench {

#ifdef JL_BENCH_PEERS

namespace {

using namespace folding;

// The steps every peer is run at: each divides the sample times exactly.
constexpr double kFoldingSteps[] = {2e-3, 1e-3, 2.5e-4, 1e-4, 2.5e-5, 1e-5};
// A run projected to take longer than this (from the one before it at a
// larger step) is dropped, with the rest of its series.
constexpr double kLongestRun = 30;  // CPU s
// A hinge counts as closed when |phi| is within this of its stop: Box2D stops a
// joint speculatively, at the stop to within single-precision rounding.
constexpr double kClosingSlack = 1e-4;  // rad (foldingPeerNote says so)

// The motion of the blocks in the ladder plane (x right, y up).
struct FoldingMotion {
    std::vector<Vec2> centre, velocity;
    std::vector<double> omega;
};

// One engine's folding chain, stepped at a fixed step.
class FoldingModel {
public:
    virtual ~FoldingModel() = default;
    virtual void step() = 0;
    // phi of hinges 1 .. N-1 (the sign may be flipped: the stops are symmetric).
    virtual void hingeAngles(std::vector<double>& phi) const = 0;
    virtual FoldingMotion motion() const = 0;
};

// Kinetic plus gravitational energy of the chain.
double chainEnergy(const FoldingMotion& m) {
    double e = 0;
    for (size_t i = 0; i < m.centre.size(); ++i)
        e += kMass * (0.5 * m.velocity[i].squaredNorm() + kGravity * m.centre[i].y()) +
             0.5 * kInertia * m.omega[i] * m.omega[i];
    return e;
}

// ---- MuJoCo: nested bodies, each a box hinged at its inner end about +y,
// gravity -z; the plane is x-z, our y is MuJoCo's z.

struct MujocoLimits {
    bool stiff = false;  // solreflimit (2 dt, 1), solimplimit 0.99 0.999 0.001, else MuJoCo's defaults
    bool stops = true;
};

class FoldingMujoco : public FoldingModel {
public:
    FoldingMujoco(int n, double h, const char* integrator, MujocoLimits limits) {
        char geom[256], joint[256], head[512];
        std::snprintf(geom, sizeof geom, "<geom type='box' size='%.17g %.17g %.17g' pos='%.17g 0 0' mass='%.17g'/>",
                      kLength / 2, kWidth / 2, kThickness / 2, kLength / 2, kMass);
        std::snprintf(joint, sizeof joint, "<joint type='hinge' axis='0 1 0' limited='true' range='%.17g %.17g'/>",
                      -stopAngle(n), stopAngle(n));
        // refsafe stays on: MuJoCo raises a time constant below 2 dt to 2 dt,
        // so the stiff limits (2 dt) are the stiffest it integrates stably.
        // With refsafe off, a time constant of dt / 5 blows up at a strike,
        // 0.32 to 0.78 s in (N = 10, dt = 1e-3 and 1e-4, every integrator).
        std::snprintf(head, sizeof head,
                      "<compiler angle='radian'/><option timestep='%.17g' integrator='%s' gravity='0 0 -%.17g'><flag "
                      "contact='disable'/></option>%s",
                      h, integrator, kGravity,
                      limits.stiff ? ("<default><joint solreflimit='" + std::to_string(2 * h) +
                                      " 1' solimplimit='0.99 0.999 0.001 0.5 2'/></default>")
                                         .c_str()
                                   : "");
        std::vector<std::string> bodies;
        for (int i = 0; i < n; ++i)
            bodies.push_back(std::string("<body pos='") + (i == 0 ? "0" : std::to_string(kLength)) + " 0 0'>" +
                             (i == 0 || !limits.stops ? "<joint type='hinge' axis='0 1 0'/>" : joint) + geom);
        model_ = loadNestedChain(head, bodies);
        if (!model_) return;
        data_ = mj_makeData(model_);
        mj_forward(model_, data_);
    }
    ~FoldingMujoco() override {
        if (data_) mj_deleteData(data_);
        if (model_) mj_deleteModel(model_);
    }
    FoldingMujoco(const FoldingMujoco&) = delete;
    FoldingMujoco& operator=(const FoldingMujoco&) = delete;

    bool loaded() const { return data_ != nullptr; }
    void step() override { mj_step(model_, data_); }
    void hingeAngles(std::vector<double>& phi) const override {
        for (size_t i = 0; i < phi.size(); ++i) phi[i] = data_->qpos[i + 1];
    }
    FoldingMotion motion() const override {
        // mj_step leaves the kinematics of the state it started from.
        mj_forward(model_, data_);
        FoldingMotion m;
        for (int i = 1; i < model_->nbody; ++i) {
            mjtNum v[6];
            mj_objectVelocity(model_, data_, mjOBJ_BODY, i, v, 0);  // rotation, then translation, world frame
            const double* c = data_->xipos + 3 * i;
            m.centre.emplace_back(c[0], c[2]);
            m.velocity.emplace_back(v[3], v[5]);
            m.omega.push_back(v[1]);
        }
        return m;
    }

private:
    mjModel* model_ = nullptr;
    mjData* data_ = nullptr;
};

// ---- Box2D: bodies in the x-y plane joined by revolute joints (single precision).

class FoldingBox2d : public FoldingModel {
public:
    FoldingBox2d(int n, double h, int velocityIterations, int positionIterations, bool stops)
        : world_(b2Vec2(0, float(-kGravity))), h_(h), velocity_(velocityIterations), position_(positionIterations) {
        world_.SetAllowSleeping(false);
        b2BodyDef groundDef;
        b2Body* ground = world_.CreateBody(&groundDef);
        b2PolygonShape box;
        box.SetAsBox(float(kLength / 2), float(kThickness / 2));
        b2FixtureDef fixture;
        fixture.shape = &box;
        fixture.density = float(kDensity * kWidth);  // per area: mass = rho W L T
        fixture.filter.maskBits = 0;                 // no contacts: the chain's links may cross
        b2Body* previous = ground;
        for (int i = 0; i < n; ++i) {
            b2BodyDef def;
            def.type = b2_dynamicBody;
            def.position.Set(float((i + 0.5) * kLength), 0);
            b2Body* b = world_.CreateBody(&def);
            b->CreateFixture(&fixture);
            b2RevoluteJointDef joint;
            joint.Initialize(previous, b, b2Vec2(float(i * kLength), 0));  // angle: theta_B - theta_A
            joint.enableLimit = stops && i > 0;
            joint.lowerAngle = float(-stopAngle(n));
            joint.upperAngle = float(stopAngle(n));
            b2Joint* j = world_.CreateJoint(&joint);
            if (i > 0) hinges_.push_back(static_cast<b2RevoluteJoint*>(j));
            bodies_.push_back(b);
            previous = b;
        }
    }
    void step() override { world_.Step(float(h_), velocity_, position_); }
    void hingeAngles(std::vector<double>& phi) const override {
        for (size_t i = 0; i < phi.size(); ++i) phi[i] = hinges_[i]->GetJointAngle();
    }
    FoldingMotion motion() const override {
        FoldingMotion m;
        for (const b2Body* b : bodies_) {
            m.centre.emplace_back(b->GetWorldCenter().x, b->GetWorldCenter().y);
            m.velocity.emplace_back(b->GetLinearVelocity().x, b->GetLinearVelocity().y);
            m.omega.push_back(b->GetAngularVelocity());
        }
        return m;
    }

private:
    b2World world_;
    double h_;
    int velocity_, position_;
    std::vector<b2Body*> bodies_;
    std::vector<b2RevoluteJoint*> hinges_;
};

// ---- Bullet: one btMultiBody with a fixed base at the origin, a revolute
// link per block about +y, gravity -z; the plane is x-z as for MuJoCo.

class FoldingBullet : public FoldingModel {
public:
    FoldingBullet(int n, double h, bool rk4, bool stops)
        : dispatcher_(&config_), world_(&dispatcher_, &broadphase_, &solver_, &config_), h_(h) {
        world_.setGravity(btVector3(0, 0, btScalar(-kGravity)));
        body_ = std::make_unique<btMultiBody>(n, btScalar(0), btVector3(0, 0, 0), true, false);
        const btVector3 inertia(btScalar(kMass * (kWidth * kWidth + kThickness * kThickness) / 12), btScalar(kInertia),
                                btScalar(kMass * (kLength * kLength + kWidth * kWidth) / 12));
        for (int i = 0; i < n; ++i)
            body_->setupRevolute(i, btScalar(kMass), inertia, i - 1, btQuaternion(0, 0, 0, 1), btVector3(0, 1, 0),
                                 btVector3(i == 0 ? 0 : btScalar(kLength / 2), 0, 0),
                                 btVector3(btScalar(kLength / 2), 0, 0), true);
        body_->finalizeMultiDof();
        body_->setLinearDamping(0);
        body_->setAngularDamping(0);
        body_->setMaxCoordinateVelocity(btScalar(1e6));
        body_->setMaxAppliedImpulse(btScalar(1e6));
        body_->useRK4Integration(rk4);
        body_->setCanSleep(false);
        world_.addMultiBody(body_.get());
        // Bullet solves a multibody's constraints per simulation island, and
        // only links with a collider are in one: without colliders the limits
        // are never solved. The colliders collide with nothing (mask 0).
        shape_ = std::make_unique<btBoxShape>(
            btVector3(btScalar(kLength / 2), btScalar(kWidth / 2), btScalar(kThickness / 2)));
        for (int i = 0; stops && i < n; ++i) {
            colliders_.push_back(std::make_unique<btMultiBodyLinkCollider>(body_.get(), i));
            btMultiBodyLinkCollider* c = colliders_.back().get();
            c->setCollisionShape(shape_.get());
            c->setWorldTransform(body_->getLink(i).m_cachedWorldTransform);
            c->setActivationState(DISABLE_DEACTIVATION);
            world_.addCollisionObject(c, 1, 0);
            body_->getLink(i).m_collider = c;
        }
        for (int i = 1; stops && i < n; ++i) {
            limits_.push_back(std::make_unique<btMultiBodyJointLimitConstraint>(body_.get(), i, btScalar(-stopAngle(n)),
                                                                                btScalar(stopAngle(n))));
            world_.addMultiBodyConstraint(limits_.back().get());
        }
    }
    ~FoldingBullet() override {
        for (auto& l : limits_) world_.removeMultiBodyConstraint(l.get());
        for (auto& c : colliders_) world_.removeCollisionObject(c.get());
        world_.removeMultiBody(body_.get());
    }
    FoldingBullet(const FoldingBullet&) = delete;
    FoldingBullet& operator=(const FoldingBullet&) = delete;

    void step() override { world_.stepSimulation(btScalar(h_), 0, btScalar(h_)); }
    void hingeAngles(std::vector<double>& phi) const override {
        for (size_t i = 0; i < phi.size(); ++i) phi[i] = double(body_->getJointPos(int(i) + 1));
    }
    FoldingMotion motion() const override {
        const int n = body_->getNumLinks();
        // Each link's angular and centre velocity in its own frame, the base first.
        std::vector<btVector3> omega(size_t(n) + 1), velocity(size_t(n) + 1);
        body_->compTreeLinkVelocities(omega.data(), velocity.data());
        FoldingMotion m;
        for (int i = 0; i < n; ++i) {
            const btVector3 c = body_->localPosToWorld(i, btVector3(0, 0, 0));
            const btVector3 v = body_->localDirToWorld(i, velocity[size_t(i) + 1]);
            m.centre.emplace_back(double(c.x()), double(c.z()));
            m.velocity.emplace_back(double(v.x()), double(v.z()));
            m.omega.push_back(double(omega[size_t(i) + 1].y()));  // every axis is +y: local y is world y
        }
        return m;
    }

private:
    btDefaultCollisionConfiguration config_;
    btCollisionDispatcher dispatcher_;
    btDbvtBroadphase broadphase_;
    btMultiBodyConstraintSolver solver_;
    btMultiBodyDynamicsWorld world_;
    double h_;
    std::unique_ptr<btMultiBody> body_;
    std::unique_ptr<btBoxShape> shape_;
    std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders_;
    std::vector<std::unique_ptr<btMultiBodyJointLimitConstraint>> limits_;
};

// ---- Running one model to kDuration and reading what FoldingRun asks.

// Told the time and every hinge's phi after each step (the sanity checks).
using HingeWatch = std::function<void(double t, const std::vector<double>& phi)>;

// Steps `model` at h to kDuration; fills r's samples and first closings.
void simulate(FoldingModel& model, int n, double h, FoldingRun& r, const HingeWatch& watch = nullptr) {
    const int steps = int(std::lround(kDuration / h));
    const double start = chainEnergy(model.motion());
    const double target = stopAngle(n) - kClosingSlack;
    std::vector<double> phi(size_t(n) - 1), previous(size_t(n) - 1, 0.0);
    r.firstClosing.assign(size_t(n) - 1, kNever);
    size_t sample = 0;
    for (int s = 1; s <= steps; ++s) {
        model.step();
        model.hingeAngles(phi);
        for (size_t i = 0; i < phi.size(); ++i) {
            const double now = std::abs(phi[i]), before = std::abs(previous[i]);
            if (!std::isfinite(now)) {
                r.finished = false;
                r.why = "hinge " + std::to_string(i + 1) + " not finite at t = " + std::to_string(s * h) + " s";
                return;
            }
            if (std::isnan(r.firstClosing[i]) && now >= target)
                r.firstClosing[i] = (s - 1 + (target - before) / (now - before)) * h;
        }
        previous = phi;
        if (watch) watch(s * h, phi);
        if (sample < kSampleTimes.size() && s == int(std::lround(kSampleTimes[sample] / h))) {
            const FoldingMotion m = model.motion();
            r.centres[sample] = m.centre;
            r.dissipated[sample] = start - chainEnergy(m);
            ++sample;
        }
    }
}

// A peer's series: its name, stop model, and how to build it at a step.
struct FoldingSeries {
    std::string engine, method, stopModel;
    std::function<std::unique_ptr<FoldingModel>(int n, double h)> build;
};

std::string mujocoVersion() { return "mujoco " + std::string(mj_versionString()); }
std::string box2dVersion() {
    return "box2d " + std::to_string(b2_version.major) + "." + std::to_string(b2_version.minor) + "." +
           std::to_string(b2_version.revision);
}
std::string bulletVersion() {
    return "bullet " + std::to_string(btGetVersion() / 100) + "." + std::to_string(btGetVersion() % 100);
}

std::vector<FoldingSeries> foldingSeries(bool stops) {
    const std::string mujocoDefault =
        "soft constraint: the limit's force from MuJoCo's convex solver (Newton) toward a reference acceleration "
        "of a spring-damper, solref 0.02 s 1, solimp 0.9 0.95 0.001 (its defaults)";
    const std::string mujocoStiff =
        "soft constraint as MuJoCo's default but stiff: solref 2 dt 1 (the smallest time constant refsafe "
        "allows), solimp 0.99 0.999 0.001";
    std::vector<FoldingSeries> out;
    for (const char* integrator : {"Euler", "RK4", "implicit"})
        for (bool stiff : {false, true}) {
            std::string method = integrator;
            std::transform(method.begin(), method.end(), method.begin(), [](char c) { return char(std::tolower(c)); });
            out.push_back({mujocoVersion(), method + (stiff ? ", stiff limits" : ""),
                           stiff ? mujocoStiff : mujocoDefault, [integrator, stiff, stops](int n, double h) {
                               auto m = std::make_unique<FoldingMujoco>(n, h, integrator, MujocoLimits{stiff, stops});
                               return m->loaded() ? std::unique_ptr<FoldingModel>(std::move(m)) : nullptr;
                           }});
        }
    const std::string box2d =
        "b2RevoluteJoint limit: a speculative one-sided row in the sequential-impulse velocity iterations (plastic), "
        "overshoot past 2 deg of slop pushed back in the position iterations";
    for (auto [v, p] : {std::pair{8, 3}, std::pair{100, 30}})
        out.push_back({box2dVersion(), std::to_string(v) + "/" + std::to_string(p) + " iterations", box2d,
                       [v, p, stops](int n, double h) { return std::make_unique<FoldingBox2d>(n, h, v, p, stops); }});
    const std::string bullet =
        "btMultiBodyJointLimitConstraint: a unilateral row of the sequential-impulse solver (10 iterations), "
        "added once the hinge is past its stop; target velocity zero (plastic) plus Baumgarte/split-impulse "
        "correction of the overshoot";
    for (bool rk4 : {false, true})
        out.push_back({bulletVersion(), rk4 ? "featherstone rk4" : "featherstone", bullet,
                       [rk4, stops](int n, double h) { return std::make_unique<FoldingBullet>(n, h, rk4, stops); }});
    return out;
}

std::string stepText(double h) {
    char s[32];
    std::snprintf(s, sizeof s, "dt = %g s", h);
    return s;
}

}  // namespace

std::vector<FoldingRun> runFoldingPeers(int n, double minSeconds) {
    std::vector<FoldingRun> out;
    for (const FoldingSeries& series : foldingSeries(true)) {
        double lastCpu = 0, lastStep = 0;
        for (double h : kFoldingSteps) {
            if (lastCpu * lastStep / h > kLongestRun) break;
            FoldingRun r;
            r.engine = series.engine;
            r.method = series.method;
            r.stopModel = series.stopModel;
            r.setting = stepText(h);
            r.blocks = n;
            int repeats = 0;
            const double start = threadSeconds();
            do {  // repeat short runs so the clock resolves them
                r.finished = true;
                const std::unique_ptr<FoldingModel> model = series.build(n, h);
                if (!model) {
                    r.finished = false;
                    r.why = "the model could not be built";
                    break;
                }
                simulate(*model, n, h, r);
                ++repeats;
            } while (threadSeconds() - start < minSeconds && r.finished);
            r.cpuSeconds = (threadSeconds() - start) / std::max(repeats, 1);
            lastCpu = r.cpuSeconds;
            lastStep = h;
            std::fprintf(stderr, "  %-14s %-22s N=%-4d %-14s CPU %.3e s%s%s\n", r.engine.c_str(), r.method.c_str(), n,
                         r.setting.c_str(), r.cpuSeconds, r.finished ? "" : "  failed: ", r.why.c_str());
            out.push_back(r);
        }
    }
    return out;
}

std::string foldingPeerNote() {
    char steps[160];
    std::snprintf(steps, sizeof steps, "%g, %g, %g, %g, %g and %g s", kFoldingSteps[0], kFoldingSteps[1],
                  kFoldingSteps[2], kFoldingSteps[3], kFoldingSteps[4], kFoldingSteps[5]);
    return mujocoVersion() + ", " + box2dVersion() +
           " (single precision; Debian's libbox2d 2.4.1 calls itself 2.4.0), " + bulletVersion() +
           " (double precision), each at fixed steps " + steps + " (a step whose run would take over " +
           std::to_string(int(kLongestRun)) + " CPU s, judged from the one before, dropped with the smaller ones); " +
           "a hinge counts as closed within 1e-4 rad of its stop";
}

#else

std::vector<FoldingRun> runFoldingPeers(int, double) { return {}; }

std::string foldingPeerNote() { return "not measured: this build has JL_BENCH_PEERS off"; }

#endif

}  // namespace jl::bench
