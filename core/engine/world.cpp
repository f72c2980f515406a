#include "jl/engine/world.h"

#include "jl/engine/projection.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <map>
#include <numbers>
#include <numeric>
#include <unordered_map>

namespace jl {

std::uint64_t World::freshRevision() {
    static std::atomic<std::uint64_t> next{1};
    return next.fetch_add(1, std::memory_order_relaxed);
}

World::World() {
    // Part 0 is the ground: held still forever, alone in kinematic body 0.
    Part g;
    g.body = 0;
    g.drive = Drive(Pose{});
    parts_.push_back(g);
    particlesOfPart_.emplace_back();
    Body b;
    b.alive = true;
    b.kinematic = true;
    b.parts = {ground};
    bodies_.push_back(b);
    q = v = a = invMassDiag = Eigen::VectorXd::Zero(3);
}

PartId World::addBox(double mass, const Vec2& size, double width, const Pose& pose, const Twist& velocity,
                     std::optional<double> inertia) {
    touch();
    Part p;
    p.mass = mass;
    p.inertia = inertia ? *inertia : mass * size.squaredNorm() / 12.0;
    p.halfSize = size / 2;
    p.width = width;
    parts_.push_back(p);
    particlesOfPart_.emplace_back();
    const PartId id = PartId(parts_.size()) - 1;
    makeBody({id}, {pose}, {velocity});
    pinsStale_ = true;
    return id;
}

PartId World::addPoint(double mass, const Vec2& position, const Vec2& velocity) {
    touch();
    Part p;
    p.mass = mass;
    p.isPoint = true;
    parts_.push_back(p);
    particlesOfPart_.emplace_back();
    const PartId id = PartId(parts_.size()) - 1;
    makeBody({id}, {Pose{position, 0}}, {Twist{velocity, 0}});
    addParticle(id, Vec2::Zero());
    return id;
}

ParticleId World::addParticle(PartId part, const Vec2& local) {
    touch();
    Particle p;
    p.at.push_back({part, local});
    particles_.push_back(p);
    const ParticleId id = ParticleId(particles_.size()) - 1;
    particlesOfPart_[part].push_back(id);
    return id;
}

void World::setDamping(PartId p, double linear, double angular) {
    touch();
    parts_[p].linearDamping = linear;
    parts_[p].angularDamping = angular;
    const auto at = std::lower_bound(dampedParts_.begin(), dampedParts_.end(), p);
    const bool listed = at != dampedParts_.end() && *at == p;
    const bool damped = linear > 0 || angular > 0;
    if (damped && !listed) dampedParts_.insert(at, p);
    if (!damped && listed) dampedParts_.erase(at);
}

ParticleId World::anchor(const Vec2& worldPoint) { return addParticle(ground, worldPoint); }

int World::addSpring(const Spring& s) {
    touch();
    springs_.push_back(s);
    return int(springs_.size()) - 1;
}

int World::addRotaryDamper(const RotaryDamper& d) {
    touch();
    dampers_.push_back(d);
    return int(dampers_.size()) - 1;
}

bool World::isLive(ParticleId p) const { return validParticle(p) && particles_[p].mergedInto < 0; }

std::optional<WorldError> World::checkParticle(ParticleId p) const {
    if (!validParticle(p)) return WorldError{"particle " + std::to_string(p) + " does not exist"};
    if (!isLive(p))
        return WorldError{"particle " + std::to_string(p) + " was combined into particle " +
                          std::to_string(particles_[p].mergedInto)};
    return std::nullopt;
}

std::optional<WorldError> World::checkCombine(ParticleId p, ParticleId q) const {
    if (auto e = checkParticle(p)) return e;
    if (auto e = checkParticle(q)) return e;
    if (p == q) return WorldError{"cannot combine a particle with itself"};
    for (const Attachment& x : particles_[size_t(p)].at)
        for (const Attachment& y : particles_[size_t(q)].at)
            if (x.part == y.part)
                return WorldError{"cannot combine two points of the same part " + std::to_string(x.part)};
    return std::nullopt;
}

void World::absorb(ParticleId p, ParticleId q, std::vector<int>& touched) {
    for (const Attachment& x : particles_[size_t(p)].at) touched.push_back(parts_[size_t(x.part)].body);
    for (const Attachment& y : particles_[size_t(q)].at) touched.push_back(parts_[size_t(y.part)].body);
    Particle& pp = particles_[size_t(p)];
    for (const Attachment& y : particles_[size_t(q)].at) {
        pp.at.push_back(y);
        auto& list = particlesOfPart_[size_t(y.part)];
        if (std::find(list.begin(), list.end(), p) == list.end()) list.push_back(p);
    }
    pp.absorbed.push_back(q);
    particles_[size_t(q)].mergedInto = p;
}

std::optional<WorldError> World::combine(ParticleId p, ParticleId q, bool consistent) {
    touch();
    if (auto e = checkCombine(p, q)) return e;
    std::vector<int> touched;
    absorb(p, q, touched);
    regroup(touched);
    if (consistent) return closePins("combine");
    return std::nullopt;
}

std::optional<WorldError> World::combine(const std::vector<std::pair<ParticleId, ParticleId>>& pairs) {
    touch();
    std::vector<ParticleId> used;
    for (const auto& [p, q] : pairs) {
        if (auto e = checkCombine(p, q)) return e;
        used.push_back(p);
        used.push_back(q);
    }
    std::sort(used.begin(), used.end());
    if (std::adjacent_find(used.begin(), used.end()) != used.end())
        return WorldError{"particle " + std::to_string(*std::adjacent_find(used.begin(), used.end())) +
                          " is in more than one pair of one combine"};
    std::vector<int> touched;
    for (const auto& [p, q] : pairs) absorb(p, q, touched);
    regroup(touched);
    return std::nullopt;
}

// After a change of structure: the pins closed and the velocities made
// consistent. The projection aims at restructureTolerance; a gap left beyond 1e-9 m (ten
// times the default tolerance of a step's projection) is a projection that
// failed, said in words. The structure has changed by then: a caller that
// gets this error stops (the simulation keeps its last good frame).
std::optional<WorldError> World::closePins(const char* operation) {
    return pinsLeftOpen(operation, makeConsistent(*this, restructure_.solver, restructureTolerance));
}

std::optional<WorldError> World::closePinGaps(const char* operation) {
    touch();
    restructure_.solver.reset();
    return pinsLeftOpen(operation, projectPositions(*this, restructure_.solver, restructureTolerance));
}

std::optional<WorldError> World::pinsLeftOpen(const char* operation, const ProjectionResult& r) {
    constexpr double kFailedGap = 1e-9;  // m
    if (r.converged || r.residual <= kFailedGap) return std::nullopt;
    return WorldError{std::string(operation) + ": the pins could not be closed after the change of structure (gap " +
                      std::to_string(r.residual) + " m after " + std::to_string(r.iterations) + " iterations)"};
}

std::optional<WorldError> World::checkSeparate(ParticleId p) const {
    if (auto e = checkParticle(p)) return e;
    if (particles_[size_t(p)].absorbed.empty())
        return WorldError{"particle " + std::to_string(p) + " has nothing combined into it"};
    return std::nullopt;
}

void World::unabsorb(ParticleId p, std::vector<int>& touched) {
    Particle& pp = particles_[size_t(p)];
    for (const Attachment& x : pp.at) touched.push_back(parts_[size_t(x.part)].body);
    const ParticleId q = pp.absorbed.back();
    pp.absorbed.pop_back();
    pp.at.resize(pp.at.size() - particles_[size_t(q)].at.size());  // combine appended q's last
    particles_[size_t(q)].mergedInto = -1;
}

std::optional<WorldError> World::separate(ParticleId p, bool consistent) {
    touch();
    if (auto e = checkSeparate(p)) return e;
    std::vector<int> touched;
    unabsorb(p, touched);
    regroup(touched);
    if (consistent) return closePins("separate");
    return std::nullopt;
}

std::optional<WorldError> World::separate(const std::vector<ParticleId>& particles) {
    touch();
    std::vector<ParticleId> sorted = particles;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end())
        return WorldError{"particle " + std::to_string(*std::adjacent_find(sorted.begin(), sorted.end())) +
                          " is separated twice in one separate"};
    for (ParticleId p : particles)
        if (auto e = checkSeparate(p)) return e;
    std::vector<int> touched;
    for (ParticleId p : particles) unabsorb(p, touched);
    regroup(touched);
    return std::nullopt;
}

void World::hold(PartId part, const Drive& d) {
    touch();
    parts_[part].drive = d;
    regroup({parts_[part].body});
    makeConsistent(*this, restructure_.solver, restructureTolerance);
}

void World::release(PartId part) {
    touch();
    if (part == ground || !parts_[part].drive) return;
    parts_[part].drive.reset();
    regroup({parts_[part].body});
}

void World::updateKinematics(double t, double within) {
    for (int b : kinematicBodies()) {
        const Body& body = bodies_[size_t(b)];
        const PartId lead = *std::find_if(body.parts.begin(), body.parts.end(),
                                          [&](PartId p) { return parts_[p].drive.has_value(); });
        const Part& part = parts_[lead];
        const DriveSample s = part.drive->at(t, within);
        const Pose pose = s.pose.compose(part.inBody.inverse());
        const Vec2 r = pose.position - s.pose.position;  // lead centre to body origin
        const double w = s.velocity.angular, alpha = s.acceleration.angular;
        q.segment<2>(3 * b) = pose.position;
        q[3 * b + 2] = pose.angle;
        v.segment<2>(3 * b) = s.velocity.linear + w * perp(r);
        v[3 * b + 2] = w;
        a.segment<2>(3 * b) = s.acceleration.linear + alpha * perp(r) - w * w * r;
        a[3 * b + 2] = alpha;
    }
}

bool World::pathsOnOnePiece(double a, double b) const {
    for (int body : kinematicBodies())
        for (PartId p : bodies_[size_t(body)].parts)
            if (parts_[p].drive && !parts_[p].drive->samePiece(a, b)) return false;
    return true;
}

// A part alone in its body sits at the body's origin: its pose and velocity
// need no rotation (bit for bit the same as the general formula, as
// rotating a zero offset gives zero; the books and frames ask for them for
// every block at every step).
Pose World::partPose(PartId p) const {
    const Part& part = parts_[p];
    if (part.inBody.position.isZero()) return {q.segment<2>(3 * part.body), q[3 * part.body + 2] + part.inBody.angle};
    return bodyPose(part.body).compose(part.inBody);
}

Twist World::partVelocity(PartId p) const {
    const int b = parts_[p].body;
    if (parts_[p].inBody.position.isZero()) return bodyVelocity(b);
    const Twist bv = bodyVelocity(b);
    const Vec2 r = rotate(q[3 * b + 2], parts_[p].inBody.position);
    return {bv.linear + bv.angular * perp(r), bv.angular};
}

Vec2 World::pointPosition(PartId p, const Vec2& local) const { return partPose(p).apply(local); }

Vec2 World::pointVelocity(PartId p, const Vec2& local) const {
    const int b = parts_[p].body;
    const Twist bv = bodyVelocity(b);
    return bv.linear + bv.angular * perp(pointPosition(p, local) - q.segment<2>(3 * b));
}

Vec2 World::particlePosition(ParticleId p) const {
    const Attachment& x = particles_[p].at.front();
    return pointPosition(x.part, x.local);
}

Vec2 World::particleVelocity(ParticleId p) const {
    const Attachment& x = particles_[p].at.front();
    return pointVelocity(x.part, x.local);
}

void World::setPartState(PartId p, const Pose& pose, const Twist& velocity) {
    touch();
    const int b = parts_[p].body;
    const Pose bp = pose.compose(parts_[p].inBody.inverse());
    const Vec2 r = bp.position - pose.position;
    q.segment<2>(3 * b) = bp.position;
    q[3 * b + 2] = bp.angle;
    v.segment<2>(3 * b) = velocity.linear + velocity.angular * perp(r);
    v[3 * b + 2] = velocity.angular;
}

std::vector<Twist> World::partVelocities() const {
    std::vector<Twist> out(parts_.size());
    for (PartId p = 0; p < partCount(); ++p) out[size_t(p)] = partVelocity(p);
    return out;
}

void World::setPartVelocities(const std::vector<Twist>& velocities) {
    touch();
    for (int b = 1; b < bodyCount(); ++b) {
        const Body& body = bodies_[b];
        if (!body.alive || body.kinematic) continue;
        Vec2 momentum = Vec2::Zero();
        for (PartId p : body.parts) momentum += parts_[p].mass * velocities[size_t(p)].linear;
        const Vec2 vel = body.mass > 0 ? Vec2(momentum / body.mass) : Vec2::Zero();
        double spin = 0;
        for (PartId p : body.parts) {
            const Vec2 r = partPose(p).position - q.segment<2>(3 * b);
            spin += parts_[p].inertia * velocities[size_t(p)].angular +
                    parts_[p].mass * cross(r, velocities[size_t(p)].linear - vel);
        }
        v.segment<2>(3 * b) = vel;
        v[3 * b + 2] = body.inertia > 0 ? spin / body.inertia : 0.0;
    }
}

// ---- grouping parts into bodies ----

// The parts of `parts` that move as one, each group sorted by PartId, the
// groups in the order of their union-find roots. Sorted vectors and a hash
// of shared pairs rather than trees: a ladder's still tail regroups
// thousands of parts at once (docs/model.md section 3.7), and the order of
// the unions (hence of the groups, hence of the bodies) is the one the
// operations have always had, so trajectories stay the same bit for bit.
std::vector<std::vector<PartId>> World::rigidGroups(const std::vector<PartId>& parts) const {
    std::vector<std::pair<PartId, int>> index(parts.size());
    for (int i = 0; i < int(parts.size()); ++i) index[size_t(i)] = {parts[size_t(i)], i};
    std::sort(index.begin(), index.end());
    const auto indexOf = [&](PartId p) {
        const auto it = std::lower_bound(index.begin(), index.end(), std::pair<PartId, int>{p, -1});
        return it != index.end() && it->first == p ? it->second : -1;
    };
    std::vector<int> root(parts.size());
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](int i) {
        while (root[size_t(i)] != i) i = root[size_t(i)] = root[size_t(root[size_t(i)])];
        return i;
    };
    auto unite = [&](int i, int j) { root[size_t(find(i))] = find(j); };

    // Two extended parts sharing two distinct particles are rigid together;
    // a point part is rigid with anything it shares a particle with.
    std::vector<ParticleId> seen;
    for (PartId part : parts)
        for (ParticleId id : particlesOfPart_[size_t(part)])
            if (isLive(id)) seen.push_back(id);
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    std::unordered_map<std::uint64_t, int> shared;
    std::vector<int> members;
    for (ParticleId id : seen) {
        members.clear();
        for (const Attachment& x : particles_[size_t(id)].at)
            if (const int i = indexOf(x.part); i >= 0) members.push_back(i);
        std::sort(members.begin(), members.end());
        members.erase(std::unique(members.begin(), members.end()), members.end());
        for (size_t i = 0; i < members.size(); ++i)
            for (size_t j = i + 1; j < members.size(); ++j) {
                const int x = members[i], y = members[j];
                const std::uint64_t key = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
                // In weld mode two extended parts stay apart: a weld holds them.
                if (parts_[size_t(parts[size_t(x)])].isPoint || parts_[size_t(parts[size_t(y)])].isPoint ||
                    (++shared[key] >= 2 && !weldRigidPairs_))
                    unite(x, y);
            }
    }
    std::vector<std::pair<int, PartId>> byRoot(parts.size());
    for (int i = 0; i < int(parts.size()); ++i) byRoot[size_t(i)] = {find(i), parts[size_t(i)]};
    std::sort(byRoot.begin(), byRoot.end());
    std::vector<std::vector<PartId>> out;
    for (size_t i = 0; i < byRoot.size(); ++i) {
        if (i == 0 || byRoot[i].first != byRoot[i - 1].first) out.emplace_back();
        out.back().push_back(byRoot[i].second);
    }
    return out;
}

void World::regroup(const std::vector<int>& touchedBodies) {
    std::vector<int> olds = touchedBodies;
    std::sort(olds.begin(), olds.end());
    olds.erase(std::unique(olds.begin(), olds.end()), olds.end());
    std::vector<PartId> parts;
    for (int b : olds) parts.insert(parts.end(), bodies_[size_t(b)].parts.begin(), bodies_[size_t(b)].parts.end());
    // Where each part was (its pose and velocity), by PartId.
    std::vector<std::pair<PartId, std::pair<Pose, Twist>>> was(parts.size());
    for (size_t i = 0; i < parts.size(); ++i) was[i] = {parts[i], {partPose(parts[i]), partVelocity(parts[i])}};
    std::sort(was.begin(), was.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
    for (int b : olds) {
        bodies_[size_t(b)] = Body{};
        invMassDiag.segment<3>(3 * b).setZero();  // dead until reused: no mass to move
        if (b != 0) freeBodies_.push_back(b);
    }
    std::vector<Pose> gp;
    std::vector<Twist> gv;
    for (const std::vector<PartId>& g : rigidGroups(parts)) {
        gp.clear();
        gv.clear();
        for (PartId p : g) {
            const auto it = std::lower_bound(was.begin(), was.end(), p,
                                             [](const auto& x, PartId id) { return x.first < id; });
            gp.push_back(it->second.first);
            gv.push_back(it->second.second);
        }
        makeBody(g, gp, gv);
    }
    pinsStale_ = true;
}

int World::allocateBody() {
    if (!freeBodies_.empty()) {
        std::sort(freeBodies_.begin(), freeBodies_.end(), std::greater<>());
        const int b = freeBodies_.back();
        freeBodies_.pop_back();
        return b;
    }
    bodies_.emplace_back();
    const Eigen::Index n = 3 * Eigen::Index(bodies_.size());
    if (q.size() < n) {  // grow geometrically: building N bodies stays O(N)
        const Eigen::Index old = q.size(), grown = std::max(n, 2 * old);
        for (Eigen::VectorXd* x : {&q, &v, &a, &invMassDiag}) {
            x->conservativeResize(grown);
            x->tail(grown - old).setZero();
        }
    }
    return int(bodies_.size()) - 1;
}

// Makes one body of the parts at the given poses; the body's velocity keeps
// the parts' linear and angular momentum (a merge is a plastic impact among
// them, a split of a rigid body changes nothing). Held parts make it
// kinematic: it then moves as its first held part does.
int World::makeBody(const std::vector<PartId>& g, const std::vector<Pose>& poses,
                    const std::vector<Twist>& velocities) {
    const bool hasGround = g.front() == ground;
    int b;
    if (hasGround) {
        b = 0;
    } else {
        b = allocateBody();
    }
    Body& body = bodies_[b];
    body = Body{};
    body.alive = true;
    body.parts = g;
    int lead = -1;
    double m = 0;
    Vec2 c = Vec2::Zero(), momentum = Vec2::Zero();
    for (size_t i = 0; i < g.size(); ++i) {
        const Part& part = parts_[g[i]];
        if (part.drive && lead < 0) lead = int(i);
        m += part.mass;
        c += part.mass * poses[i].position;
        momentum += part.mass * velocities[i].linear;
    }
    body.kinematic = lead >= 0;
    const Pose& first = poses[lead >= 0 ? size_t(lead) : 0];
    // A lone part keeps its own frame exactly: rounding in c / m would give a
    // point particle a spurious ~1e-35 inertia (and a huge spin).
    Pose frame{m > 0 && !hasGround && g.size() > 1 ? Vec2(c / m) : first.position, first.angle};
    if (hasGround) frame = Pose{};
    double inertia = 0, spin = 0;
    const Vec2 vel = m > 0 ? Vec2(momentum / m) : Vec2::Zero();
    for (size_t i = 0; i < g.size(); ++i) {
        Part& part = parts_[g[i]];
        const Vec2 r = poses[i].position - frame.position;
        inertia += part.inertia + part.mass * r.squaredNorm();
        spin += part.inertia * velocities[i].angular + part.mass * cross(r, velocities[i].linear - vel);
        part.body = b;
        part.inBody = frame.inverse().compose(poses[i]);
    }
    // Points that coincide (combined free particles) have no orientation.
    const bool allPoints = std::all_of(g.begin(), g.end(), [&](PartId p) { return parts_[p].isPoint; });
    if (allPoints && inertia <= 1e-12 * m * 1e-6) inertia = 0;
    body.mass = m;
    body.inertia = inertia;
    q.segment<2>(3 * b) = frame.position;
    q[3 * b + 2] = frame.angle;
    if (body.kinematic) {
        const Twist& lv = velocities[size_t(lead)];
        const Vec2 r = frame.position - poses[size_t(lead)].position;
        v.segment<2>(3 * b) = lv.linear + lv.angular * perp(r);
        v[3 * b + 2] = lv.angular;
        invMassDiag.segment<3>(3 * b).setZero();
    } else {
        body.invMass = m > 0 ? 1.0 / m : 0.0;
        body.invInertia = inertia > 0 ? 1.0 / inertia : 0.0;
        v.segment<2>(3 * b) = vel;
        v[3 * b + 2] = inertia > 0 ? spin / inertia : 0.0;
        invMassDiag.segment<3>(3 * b) << body.invMass, body.invMass, body.invInertia;
    }
    a.segment<3>(3 * b).setZero();
    ++structureVersion_;
    return b;
}

void World::compactBodies() {
    touch();
    std::vector<int> to(bodies_.size(), -1);
    int n = 0;
    for (int b = 0; b < bodyCount(); ++b)
        if (bodies_[size_t(b)].alive) to[size_t(b)] = n++;
    freeBodies_.clear();
    if (n == bodyCount()) return;
    std::vector<Body> bodies(static_cast<size_t>(n));
    Eigen::VectorXd q1(3 * n), v1(3 * n), a1(3 * n), m1(3 * n);
    for (int b = 0; b < bodyCount(); ++b) {
        const int to_b = to[size_t(b)];
        if (to_b < 0) continue;
        bodies[size_t(to_b)] = std::move(bodies_[size_t(b)]);
        q1.segment<3>(3 * to_b) = q.segment<3>(3 * b);
        v1.segment<3>(3 * to_b) = v.segment<3>(3 * b);
        a1.segment<3>(3 * to_b) = a.segment<3>(3 * b);
        m1.segment<3>(3 * to_b) = invMassDiag.segment<3>(3 * b);
    }
    for (Part& p : parts_) p.body = to[size_t(p.body)];
    bodies_ = std::move(bodies);
    q = std::move(q1);
    v = std::move(v1);
    a = std::move(a1);
    invMassDiag = std::move(m1);
    pinsStale_ = true;
    ++structureVersion_;
}

void World::shrinkToFit() {
    touch();
    const Eigen::Index n = 3 * Eigen::Index(bodies_.size());
    for (Eigen::VectorXd* x : {&q, &v, &a, &invMassDiag}) x->conservativeResize(n);
}

void World::indexBodies() const {
    if (indexedVersion_ == structureVersion_ && indexedGravity_ == gravity && weights_.size() == q.size()) return;
    indexedVersion_ = structureVersion_;
    indexedGravity_ = gravity;
    kinematicBodies_.clear();
    kinematicFlags_.assign(bodies_.size(), 0);
    weights_.setZero(q.size());
    for (int b = 0; b < bodyCount(); ++b) {
        const Body& body = bodies_[size_t(b)];
        if (!body.alive) continue;
        if (body.kinematic) {
            kinematicBodies_.push_back(b);
            kinematicFlags_[size_t(b)] = 1;
        } else {
            // The body's origin is its centre of mass: its weight has no torque.
            weights_.segment<2>(3 * b) = body.mass * gravity;
        }
    }
}

const std::vector<int>& World::kinematicBodies() const {
    indexBodies();
    return kinematicBodies_;
}

const std::vector<unsigned char>& World::kinematicFlags() const {
    indexBodies();
    return kinematicFlags_;
}

const Eigen::VectorXd& World::weights() const {
    indexBodies();
    return weights_;
}

const std::vector<Pin>& World::pins() const {
    if (pinsStale_) rebuildPins();
    return pins_;
}

const std::vector<Weld>& World::welds() const {
    if (pinsStale_) rebuildPins();
    return welds_;
}

// Pins are derived lazily: a builder making many combines pays once.
void World::rebuildPins() const {
    pinsStale_ = false;
    pins_.clear();
    for (ParticleId id = 0; id < particleCount(); ++id) {
        const Particle& p = particles_[id];
        if (p.mergedInto >= 0 || p.at.size() < 2) continue;
        const Attachment& first = p.at.front();
        const int ba = parts_[first.part].body;
        std::vector<int> done{ba};
        for (size_t i = 1; i < p.at.size(); ++i) {
            const int bb = parts_[p.at[i].part].body;
            if (std::find(done.begin(), done.end(), bb) != done.end()) continue;
            done.push_back(bb);
            if (bodies_[ba].kinematic && bodies_[bb].kinematic) continue;
            pins_.push_back({ba, bb, first.part, p.at[i].part, parts_[first.part].inBody.apply(first.local),
                             parts_[p.at[i].part].inBody.apply(p.at[i].local), id});
        }
    }
    welds_.clear();
    if (weldRigidPairs_) weldSharedPairs();
}

// Weld mode: of the pins between one pair of bodies (two bodies that share
// two particles), the one whose points lie closer stays a pin and the other
// becomes a weld of their relative angle, taken from where the two shared
// points lie on each body; any further pin is redundant and dropped.
void World::weldSharedPairs() const {
    std::map<std::pair<int, int>, int> firstPin;
    const auto gap = [this](const Pin& p) {
        const auto at = [this](int b, const Vec2& local) {
            return Vec2(q.segment<2>(3 * b) + rotate(q[3 * b + 2], local));
        };
        return (at(p.bodyA, p.localA) - at(p.bodyB, p.localB)).norm();
    };
    std::vector<Pin> kept;
    std::vector<char> welded;
    kept.reserve(pins_.size());
    for (const Pin& p : pins_) {
        const std::pair<int, int> key{std::min(p.bodyA, p.bodyB), std::max(p.bodyA, p.bodyB)};
        auto it = firstPin.find(key);
        if (it == firstPin.end()) {
            firstPin[key] = int(kept.size());
            kept.push_back(p);
            welded.push_back(0);
            continue;
        }
        const int index = it->second;
        if (welded[size_t(index)]) continue;
        // The pin stays where the bodies really meet: blocks of unequal
        // thickness locked end to end share their hinge corners, while their
        // other pair of corners lies apart by the difference (pulling those
        // together would shift the pair sideways).
        // Where both pairs meet (equal thicknesses), the first stays, so the
        // choice never turns on rounding.
        Pin candidate = p;
        const double firstGap = gap(kept[size_t(index)]);
        const Pin& kept0 = kept[size_t(index)];
        const double spacing = ((p.bodyA == kept0.bodyA ? p.localA : p.localB) - kept0.localA).norm();
        if (firstGap > 1e-6 * spacing && gap(p) < firstGap) std::swap(candidate, kept[size_t(index)]);
        const Pin& first = kept[size_t(index)];
        const Pin& second = candidate;
        const bool same = second.bodyA == first.bodyA;
        const Vec2 dA = (same ? second.localA : second.localB) - first.localA;
        const Vec2 dB = (same ? second.localB : second.localA) - first.localB;
        const double arm = dA.norm();
        if (!(arm > 1e-12)) continue;  // the same point twice: the pin holds it
        const double base = std::atan2(dB.y(), dB.x()) - std::atan2(dA.y(), dA.x());
        const double now = q[3 * first.bodyA + 2] - q[3 * first.bodyB + 2];
        const double turns = std::round((now - base) / (2 * std::numbers::pi));
        welds_.push_back({index, arm, base + turns * 2 * std::numbers::pi});
        welded[size_t(index)] = 1;
    }
    pins_ = std::move(kept);
}

}  // namespace jl
