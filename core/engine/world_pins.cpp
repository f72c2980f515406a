// World: the pins and welds, derived from the particles after a change of structure.
#include "jl/engine/world.h"
#include "scratch.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace jl {

// Pins are derived lazily: a builder making many combines pays once.
void World::rebuildPins() const {
    pinsStale_ = false;
    pins_.clear();
    updatePinning();
    // The bodies a particle already joins; one list for all of them (a list
    // per particle was an allocation each, at every change of structure).
    std::vector<int>& done = scratch_->joined;
    for (ParticleId id : pinning_) {
        const Attachment& first = particles_[id].own;
        const int ba = parts_[first.part].body;
        done.assign(1, ba);
        const auto pinTo = [&](const Attachment& x) {
            const int bb = parts_[x.part].body;
            if (std::find(done.begin(), done.end(), bb) != done.end()) return;
            done.push_back(bb);
            if (bodies_[ba].kinematic && bodies_[bb].kinematic) return;
            pins_.push_back({ba, bb, first.part, x.part, parts_[first.part].inBody.apply(first.local),
                             parts_[x.part].inBody.apply(x.local), id});
        };
        forEachAbsorbed(id, [&](ParticleId q) { forEachAttachment(q, pinTo); });
    }
    welds_.clear();
    if (weldRigidPairs_) weldSharedPairs();
}

namespace {

// Whether particle `id` makes a pin: it is live and lies on two bodies, not
// both kinematic (what rebuildPins derives a pin from).
bool makesPin(const World& w, const std::vector<Part>& parts, const std::vector<Body>& bodies, ParticleId id) {
    const Particle& p = w.particle(id);
    if (p.mergedInto >= 0 || p.lastAbsorbed < 0) return false;
    const int ba = parts[size_t(p.own.part)].body;
    bool pin = false;
    w.forEachAbsorbed(id, [&](ParticleId q) {
        w.forEachAttachment(q, [&](const Attachment& x) {
            const int bb = parts[size_t(x.part)].body;
            pin = pin || (bb != ba && !(bodies[size_t(ba)].kinematic && bodies[size_t(bb)].kinematic));
        });
    });
    return pin;
}

}  // namespace

// Brings `pinning_` up to date for the parts regrouped since it last was:
// only their particles can have begun or ceased to make a pin. They are
// merged into the list in one pass (as long as the pins that are derived
// from it next); where they are most of the world (a ladder built hinge by
// hinge) every particle is looked at once, as the pins were derived before
// the list was kept.
void World::updatePinning() const {
    std::vector<ParticleId> affected;
    for (PartId part : regrouped_)
        affected.insert(affected.end(), particlesOfPart_[size_t(part)].begin(), particlesOfPart_[size_t(part)].end());
    regrouped_.clear();
    const auto pins = [this](ParticleId id) { return makesPin(*this, parts_, bodies_, id); };
    if (affected.size() * 4 > particles_.size()) {
        pinning_.clear();
        for (ParticleId id = 0; id < particleCount(); ++id)
            if (pins(id)) pinning_.push_back(id);
        return;
    }
    std::sort(affected.begin(), affected.end());
    affected.erase(std::unique(affected.begin(), affected.end()), affected.end());
    std::vector<ParticleId> merged;
    merged.reserve(pinning_.size() + affected.size());
    size_t i = 0;
    for (ParticleId id : affected) {
        while (i < pinning_.size() && pinning_[i] < id) merged.push_back(pinning_[i++]);
        if (i < pinning_.size() && pinning_[i] == id) ++i;
        if (pins(id)) merged.push_back(id);
    }
    merged.insert(merged.end(), pinning_.begin() + std::ptrdiff_t(i), pinning_.end());
    pinning_ = std::move(merged);
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
