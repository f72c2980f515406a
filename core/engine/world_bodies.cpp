// World: which parts move as one body (union-find over combined particles), and
// the bodies' flat arrays that every evaluation reads.
#include "jl/engine/world.h"
#include "scratch.h"

#include <algorithm>
#include <functional>
#include <numeric>
#include <unordered_map>

namespace jl {

// The parts of `parts` that move as one, each group sorted by PartId, the
// groups in the order of their union-find roots. Sorted vectors and a hash
// of shared pairs rather than trees: a ladder's still tail regroups
// thousands of parts at once (docs/model.md section 3.7), and the order of
// the unions (hence of the groups, hence of the bodies) is the one the
// operations have always had, so trajectories stay the same bit for bit.
std::vector<std::vector<PartId>> World::rigidGroups(const std::vector<PartId>& parts) const {
    Scratch& s = *scratch_;
    std::vector<std::pair<PartId, int>>& index = s.partIndex;
    index.resize(parts.size());
    for (int i = 0; i < int(parts.size()); ++i) index[size_t(i)] = {parts[size_t(i)], i};
    std::sort(index.begin(), index.end());
    const auto indexOf = [&](PartId p) {
        const auto it = std::lower_bound(index.begin(), index.end(), std::pair<PartId, int>{p, -1});
        return it != index.end() && it->first == p ? it->second : -1;
    };
    std::vector<int>& root = s.root;
    root.resize(parts.size());
    std::iota(root.begin(), root.end(), 0);
    auto find = [&](int i) {
        while (root[size_t(i)] != i) i = root[size_t(i)] = root[size_t(root[size_t(i)])];
        return i;
    };
    auto unite = [&](int i, int j) { root[size_t(find(i))] = find(j); };

    // Two extended parts sharing two distinct particles are rigid together;
    // a point part is rigid with anything it shares a particle with.
    std::vector<ParticleId>& seen = s.seen;
    seen.clear();
    for (PartId part : parts)
        for (ParticleId id : particlesOfPart_[size_t(part)])
            if (isLive(id)) seen.push_back(id);
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    // How many particles each pair of parts shares so far: a short list
    // searched in order for the few parts of a lock or a trial, a hash for
    // the thousands of a still tail.
    constexpr size_t kFewParts = 16;
    const bool few = parts.size() <= kFewParts;
    std::vector<std::pair<std::uint64_t, int>>& sharedFew = s.shared;
    sharedFew.clear();
    std::unordered_map<std::uint64_t, int> sharedMany;
    const auto sharedCount = [&](std::uint64_t key) -> int& {
        if (!few) return sharedMany[key];
        for (auto& [k, count] : sharedFew)
            if (k == key) return count;
        return sharedFew.emplace_back(key, 0).second;
    };
    std::vector<int>& members = s.members;
    for (ParticleId id : seen) {
        members.clear();
        forEachAttachment(id, [&](const Attachment& x) {
            if (const int i = indexOf(x.part); i >= 0) members.push_back(i);
        });
        std::sort(members.begin(), members.end());
        members.erase(std::unique(members.begin(), members.end()), members.end());
        for (size_t i = 0; i < members.size(); ++i)
            for (size_t j = i + 1; j < members.size(); ++j) {
                const int x = members[i], y = members[j];
                const std::uint64_t key = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
                // In weld mode two extended parts stay apart: a weld holds them.
                if (parts_[size_t(parts[size_t(x)])].isPoint || parts_[size_t(parts[size_t(y)])].isPoint ||
                    (++sharedCount(key) >= 2 && !weldRigidPairs_))
                    unite(x, y);
            }
    }
    std::vector<std::pair<int, PartId>>& byRoot = s.byRoot;
    byRoot.resize(parts.size());
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
        if (b != 0) {
            freeBodies_.push_back(b);
            std::push_heap(freeBodies_.begin(), freeBodies_.end(), std::greater<>());
        }
    }
    std::vector<Pose> gp;
    std::vector<Twist> gv;
    for (const std::vector<PartId>& g : rigidGroups(parts)) {
        gp.clear();
        gv.clear();
        for (PartId p : g) {
            const auto it =
                std::lower_bound(was.begin(), was.end(), p, [](const auto& x, PartId id) { return x.first < id; });
            gp.push_back(it->second.first);
            gv.push_back(it->second.second);
        }
        makeBody(g, gp, gv);
    }
    regrouped_.insert(regrouped_.end(), parts.begin(), parts.end());
    pinsStale_ = true;
}

int World::allocateBody() {
    if (!freeBodies_.empty()) {
        std::pop_heap(freeBodies_.begin(), freeBodies_.end(), std::greater<>());
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
    coordinateParts_.setZero(q.size());
    for (int b = 0; b < bodyCount(); ++b) {
        const Body& body = bodies_[size_t(b)];
        for (Eigen::Index i = 3 * b; i < 3 * b + 3 && i < std::min(q.size(), invMassDiag.size()); ++i)
            if (invMassDiag[i] != 0) coordinateParts_[i] = double(body.parts.size());
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

const Eigen::VectorXd& World::coordinateParts() const {
    indexBodies();
    return coordinateParts_;
}

const std::vector<Pin>& World::pins() const {
    if (pinsStale_) rebuildPins();
    return pins_;
}

const std::vector<Weld>& World::welds() const {
    if (pinsStale_) rebuildPins();
    return welds_;
}

}  // namespace jl
