#include "jl/engine/world.h"

#include "jl/base/heap_bytes.h"

#include <algorithm>
#include <atomic>

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
    p.own = {part, local};
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
    std::optional<PartId> shared;
    forEachAttachment(p, [&](const Attachment& x) {
        forEachAttachment(q, [&](const Attachment& y) {
            if (x.part == y.part && !shared) shared = x.part;
        });
    });
    if (shared) return WorldError{"cannot combine two points of the same part " + std::to_string(*shared)};
    return std::nullopt;
}

void World::absorb(ParticleId p, ParticleId q, std::vector<int>& touched) {
    forEachAttachment(p, [&](const Attachment& x) { touched.push_back(parts_[size_t(x.part)].body); });
    forEachAttachment(q, [&](const Attachment& y) {
        touched.push_back(parts_[size_t(y.part)].body);
        auto& list = particlesOfPart_[size_t(y.part)];
        if (std::find(list.begin(), list.end(), p) == list.end()) list.push_back(p);
    });
    particles_[size_t(q)].absorbedBefore = particles_[size_t(p)].lastAbsorbed;
    particles_[size_t(p)].lastAbsorbed = q;
    particles_[size_t(q)].mergedInto = p;
}

std::optional<WorldError> World::combine(ParticleId p, ParticleId q) {
    touch();
    if (auto e = checkCombine(p, q)) return e;
    std::vector<int> touched;
    absorb(p, q, touched);
    regroup(touched);
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

std::optional<WorldError> World::checkSeparate(ParticleId p) const {
    if (auto e = checkParticle(p)) return e;
    if (particles_[size_t(p)].lastAbsorbed < 0)
        return WorldError{"particle " + std::to_string(p) + " has nothing combined into it"};
    return std::nullopt;
}

void World::unabsorb(ParticleId p, std::vector<int>& touched) {
    forEachAttachment(p, [&](const Attachment& x) { touched.push_back(parts_[size_t(x.part)].body); });
    Particle& pp = particles_[size_t(p)];
    const ParticleId q = pp.lastAbsorbed;
    pp.lastAbsorbed = particles_[size_t(q)].absorbedBefore;
    particles_[size_t(q)].absorbedBefore = -1;
    particles_[size_t(q)].mergedInto = -1;
}

std::optional<WorldError> World::separate(ParticleId p) {
    touch();
    if (auto e = checkSeparate(p)) return e;
    std::vector<int> touched;
    unabsorb(p, touched);
    regroup(touched);
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
        const PartId lead =
            *std::find_if(body.parts.begin(), body.parts.end(), [&](PartId p) { return parts_[p].drive.has_value(); });
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

std::size_t World::heapBytes() const {
    using jl::heapBytes;
    std::size_t n = heapBytes(parts_) + heapBytes(bodies_) + heapBytes(particles_) + heapBytes(particlesOfPart_) +
                    heapBytes(pins_) + heapBytes(pinning_) + heapBytes(regrouped_) + heapBytes(welds_) +
                    heapBytes(kinematicBodies_) + heapBytes(kinematicFlags_) + heapBytes(weights_) +
                    heapBytes(coordinateParts_) + heapBytes(springs_) + heapBytes(dampers_) + heapBytes(drags_) +
                    heapBytes(loads_) + heapBytes(contacts_) + heapBytes(freeBodies_) + heapBytes(dampedParts_) +
                    heapBytes(q) + heapBytes(v) + heapBytes(a) + heapBytes(invMassDiag);
    for (const Part& p : parts_)
        if (p.drive) n += heapBytes(p.drive->moves());
    for (const Body& b : bodies_) n += heapBytes(b.parts);
    return n;
}

std::vector<Attachment> World::attachments(ParticleId p) const {
    std::vector<Attachment> at;
    forEachAttachment(p, [&](const Attachment& x) { at.push_back(x); });
    return at;
}

Vec2 World::particlePosition(ParticleId p) const {
    const Attachment& x = particles_[p].own;
    return pointPosition(x.part, x.local);
}

Vec2 World::particleVelocity(ParticleId p) const {
    const Attachment& x = particles_[p].own;
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

}  // namespace jl
