// Contact between blocks that are not neighbours (docs/model.md section 17):
// which corners are watched, the event functions, and what happens at an
// instant where a corner touches a face or a resting contact lets go.
#include "jl/ladder/block_contact.h"

#include "block_contact_lengths.h"
#include "jl/base/heap_bytes.h"
#include "jl/engine/energy.h"
#include "jl/engine/projection.h"
#include "jl/ladder/ladder.h"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

namespace jl {

using namespace block_contact;

namespace {

// An event in the words of the log: "block 3 strikes block 0 (corner 2)",
// "block 5 strikes the floor (corner 1)".
std::string contactWords(int block, const char* what, int other, int corner) {
    const std::string face = other == BlockContacts::kFloor ? "the floor" : "block " + std::to_string(other);
    return "block " + std::to_string(block) + " " + what + " " + face + " (corner " + std::to_string(corner) + ")";
}

// The body a contact's face is on: the other block's, or the ground's.
int faceBody(const World& w, const Ladder& ladder, int other) {
    return w.part(other == BlockContacts::kFloor ? World::ground : ladder.block(other)).body;
}

Vec2 faceNormal(int face) {
    switch (face) {
        case 0:
            return {-1, 0};
        case 1:
            return {1, 0};
        case 2:
            return {0, -1};
        default:
            return {0, 1};
    }
}

}  // namespace

std::optional<std::string> BlockContacts::inside(const World& w, const Ladder& ladder) const {
    const double band = kTouchBand * ladder.length();
    auto words = [](int block, int corner, const std::string& where, double depth) {
        return "corner " + std::to_string(corner) + " of block " + std::to_string(block) + " would be " +
               std::to_string(depth * 1e3) + " mm " + where;
    };
    if (enabled_) {
        BlockPairs broad;
        std::vector<std::pair<int, int>> pairs;
        broad.find(w, ladder, pairs);
        for (const auto& [i, j] : pairs)
            for (const auto& [a, b] : {std::pair{i, j}, std::pair{j, i}})
                for (int k = 0; k < 4; ++k)
                    if (const double gap = cornerAgainst(w, ladder, a, k, b).gap; gap < -band)
                        return words(a, k, "inside block " + std::to_string(b), -gap);
    }
    if (floor_)
        for (int i = 0; i < ladder.blockCount(); ++i) {
            if (w.body(w.part(ladder.block(i)).body).kinematic) continue;
            for (int k = 0; k < 4; ++k)
                if (const double gap = ladder.cornerWorld(w, i, k).y() - *floor_; gap < -band)
                    return words(i, k, "under the table top", -gap);
        }
    return std::nullopt;
}

double BlockContacts::touchBand(const Ladder& ladder) { return kTouchBand * ladder.length(); }

bool BlockContacts::resting(int block, int corner, int other) const {
    return std::any_of(touches_.begin(), touches_.end(),
                       [&](const Touch& t) { return t.block == block && t.corner == corner && t.other == other; });
}

double BlockContacts::gapZero(int block, int corner, int other) const {
    for (const Parted& p : parted_)
        if (p.block == block && p.corner == corner && p.other == other) return std::min(0.0, p.gap);
    return 0.0;
}

// A corner parted at some instant is back to the plain zero once clear
// (the record stays, for the Zeno time, until the next parting). Judged
// only on a state the run keeps: a step's end where an event is then
// located inside the step is not one. A corner parted 22 um inside a
// block (held where it was met) and clear of it at such an end lost its
// zero, and at the located instant 1 ns in, inside again, it struck and
// parted: 172,742 times in 0.17 ms, in a wrong-way turn of 7 blocks.
void BlockContacts::forgetCleared(const World& w, const Ladder& ladder) {
    for (Parted& p : parted_)
        if (p.gap != 0 && against(w, ladder, p.block, p.corner, p.other).gap > kClear * ladder.length()) p.gap = 0;
}

void BlockContacts::refresh(const World& w, const Ladder& ladder) {
    watched_.clear();
    if (!active()) return;
    const double length = ladder.length();
    if (enabled_) {
        broad_.find(w, ladder, pairs_);
        pairCount_ = int(pairs_.size());
        for (const auto& [i, j] : pairs_) {
            // Each block's pose and corners worked out once for the pair,
            // and each corner's distances to the other's face planes.
            const Placed blockI = placed(w, ladder, i), blockJ = placed(w, ladder, j);
            BlockPairs::CornerDistances beyond;
            for (int k = 0; k < 4; ++k) {
                beyond[0][size_t(k)] = blockJ.beyond(blockJ.local(blockI.corner[size_t(k)]));
                beyond[1][size_t(k)] = blockI.beyond(blockI.local(blockJ.corner[size_t(k)]));
            }
            // Boxes apart along one of their axes by more than the clear
            // distance (most pairs whose circles overlap): every corner of
            // each is outside the other by more than the touch band, so its
            // function is positive and counts nowhere (one counts once it
            // is negative), and none touches. Not watched, the same events
            // at less cost; their faces are still kept.
            const bool apart = BlockPairs::apart(beyond, kClear * length);
            for (const auto& [a, b] : {std::pair{i, j}, std::pair{j, i}}) {
                const Placed& corners = a == i ? blockI : blockJ;
                const Placed& box = b == i ? blockI : blockJ;
                for (int k = 0; k < 4; ++k) {
                    const Vec2& p = corners.corner[size_t(k)];
                    const int through = throughFace(ladder, nearestFace(beyond[a == i ? 0 : 1][size_t(k)]), a, k, b);
                    // A corner at a hinge, or resting, is not watched for
                    // now but keeps the face it came through for when it is
                    // again: a corner passing a hinge's corner on its way in
                    // would otherwise be judged by the plane it is nearest.
                    throughNext_.push_back({{a, k, b}, through});
                    if (apart || resting(a, k, b) || atHingeOf(ladder, p, b, box)) continue;
                    watched_.push_back({a, k, b, gapZero(a, k, b), through});
                }
            }
        }
    }
    if (floor_) watchFloor(w, ladder);
    std::sort(throughNext_.begin(), throughNext_.end());
    std::swap(through_, throughNext_);
    throughNext_.clear();
}

// Each moving block whose bounding circle reaches the table top has its
// four corners watched against it: O(blocks) per call, and nothing for a
// ladder hanging clear of the floor. A block the hand holds goes through
// the table (two immovable things cannot push each other apart).
void BlockContacts::watchFloor(const World& w, const Ladder& ladder) {
    const double near = *floor_ + kTouchBand * ladder.length();
    for (int i = 0; i < std::min(ladder.blockCount(), ladder.stillFrom()); ++i) {
        const Pose pose = w.partPose(ladder.block(i));
        if (pose.position.y() - ladder.cornerLocal(i, 3).norm() > near) continue;
        if (w.body(w.part(ladder.block(i)).body).kinematic) continue;
        for (int k = 0; k < 4; ++k)
            if (!resting(i, k, kFloor)) watched_.push_back({i, k, kFloor, gapZero(i, k, kFloor), 3});
    }
}

void BlockContacts::markLocated(const std::vector<int>& functions) {
    for (int k : functions)
        if (k < int(watched_.size())) {
            const Watch& c = watched_[size_t(k)];
            located_.push_back({c.block, c.corner, c.other});
        }
}

double BlockContacts::watchFunction(const World& w, const Ladder& ladder, const Watch& c) const {
    return watchValue(ladder, against(w, ladder, c.block, c.corner, c.other, c.through).gap, c);
}

double BlockContacts::watchValue(const Ladder& ladder, double against, const Watch& c) const {
    const double gap = against - c.zero;
    return gap + (locating_ ? kRounding * ladder.length() : std::max(kRounding * ladder.length(), allowance_));
}

double BlockContacts::slideRoom(const World& w, size_t i) const {
    const Contact& c = w.contacts()[i];
    return c.halfLength - std::abs(contactSlide(w, c));
}

double BlockContacts::eventFunctions(const World& w, const Dynamics& d, const Ladder& ladder,
                                     std::vector<double>& out) const {
    double smallestForce = std::numeric_limits<double>::infinity();
    if (!active()) return smallestForce;
    // The watched corners come four by four for each ordered pair of
    // blocks: each block placed once for its run.
    const double flush = kFlush * ladder.length();
    Placed corners, box;
    int placedBlock = -1, placedBox = -1;
    for (const Watch& c : watched_) {
        if (c.other == kFloor) {
            out.push_back(watchFunction(w, ladder, c));
            continue;
        }
        if (c.block != placedBlock) corners = placed(w, ladder, c.block, Need::Corners), placedBlock = c.block;
        if (c.other != placedBox) box = placed(w, ladder, c.other, Need::Box), placedBox = c.other;
        out.push_back(watchValue(ladder, pointAgainst(corners.corner[size_t(c.corner)], box, flush, c.through).gap, c));
    }
    const Eigen::VectorXd& push = d.contactForces();
    for (size_t i = 0; i < touches_.size(); ++i) {
        const double f = (Eigen::Index(i) < push.size() ? push[Eigen::Index(i)] : 0.0) + ladder.forceTolerance();
        out.push_back(f);
        smallestForce = std::min(smallestForce, f);
    }
    for (size_t i = 0; i < touches_.size(); ++i) out.push_back(slideRoom(w, i) + kTouchBand * ladder.length());
    return smallestForce;
}

double BlockContacts::positionFunction(const World& w, const Ladder& ladder, int k) const {
    if (k < int(watched_.size())) {
        const Watch& c = watched_[size_t(k)];
        return watchFunction(w, ladder, c);
    }
    const size_t i = size_t(k) - watched_.size() - touches_.size();
    return slideRoom(w, i) + kTouchBand * ladder.length();
}

std::array<int, 2> BlockContacts::bodies(const World& w, const Ladder& ladder, int k) const {
    if (k < int(watched_.size())) {
        const Watch& c = watched_[size_t(k)];
        return {w.part(ladder.block(c.block)).body, faceBody(w, ladder, c.other)};
    }
    const Touch& t = touches_[size_t(k) - watched_.size() - touches_.size()];
    return {w.part(ladder.block(t.block)).body, faceBody(w, ladder, t.other)};
}

// Whether point p is where a pin joins the bodies of blocks a and b: a
// hinge's corner, after a flip or a lock, can be a corner of a block that
// is not the hinge's (two hinges at one end of a block; a locked pair's
// second shared corner). A pin already keeps the two bodies together
// there, and a contact at the same point would be the pin's own equation
// again, with a push the solve cannot tell from the pin's force.
bool BlockContacts::onPin(const World& w, const Ladder& ladder, const Vec2& p, int a, int b) {
    const int bodyA = w.part(ladder.block(a)).body, bodyB = faceBody(w, ladder, b);
    const double near = kClear * ladder.length();
    for (const Pin& pin : w.pins())
        if ((pin.bodyA == bodyA && pin.bodyB == bodyB) || (pin.bodyA == bodyB && pin.bodyB == bodyA))
            if ((w.bodyPose(pin.bodyA).apply(pin.localA) - p).norm() <= near) return true;
    return false;
}

// Whether point p lies on one of block b's hinges. After a flip both
// hinges of a block sit at one end, T apart, and the neighbour folded
// against it has a corner on the other hinge: it meets the block beyond at
// that hinge's corner, with gap zero to rounding, held there by the pins
// (the classic cascade does this at every flip). A corner there is the
// hinges' business, not a contact's.
bool BlockContacts::atHingeOf(const Ladder& ladder, const Vec2& p, int b, const Placed& box) {
    const double near = kClear * ladder.length();
    for (int j : {b, b + 1})
        if (j >= 1 && j < ladder.blockCount() && ladder.hinge(j).mode != HingeMode::Cut &&
            (box.corner[size_t(ladder.hinge(j).corner)] - p).norm() <= near)
            return true;
    return false;
}

// Whether the pins, and the contacts resting already, hold the contact's
// two points together along its normal: a push there moves nothing (the Delassus entry G u, with the pins
// active, is a vanishing fraction of what it is for the two bodies alone).
// A corner can coincide with a hinge of a third block (two hinges at one
// end of a block after a flip, T apart: a neighbour's corner lies on the
// other hinge) and touch a face there without the pins letting it press:
// the push would be the pins' indeterminate share, not a contact.
bool BlockContacts::heldAlready(const World& w, const Contact& c, const ContactRow& row) {
    const Eigen::MatrixXd& matrix = contactMatrixWith(w, c);
    return !(share(w, row, matrix, matrix.rows() - 1) > 1e-6);
}

// What a push at contact i of `matrix` (the Delassus matrix of the pins and
// the contacts, 17.2) moves with the others held as well (the Schur
// complement of the others), over what it would move the two bodies alone.
double BlockContacts::share(const World& w, const ContactRow& row, const Eigen::MatrixXd& matrix, Eigen::Index i) {
    double free = 0;
    for (int b : {row.bodyA, row.bodyB}) {
        const Vec2 arm = b == row.bodyA ? row.armA : row.armB;
        free += w.invMassDiag[3 * b] + w.invMassDiag[3 * b + 2] * cross(arm, row.normal) * cross(arm, row.normal);
    }
    const Eigen::Index n = matrix.rows();
    double own = matrix(i, i);
    if (n > 1) {
        std::vector<Eigen::Index> others;
        for (Eigen::Index j = 0; j < n; ++j)
            if (j != i) others.push_back(j);
        const Eigen::MatrixXd held = matrix(others, others);
        const Eigen::VectorXd across = matrix(others, i);
        own -= across.dot(held.ldlt().solve(across));
    }
    return free > 0 ? own / free : 0.0;
}

// Corner `corner` of `block` against face `face` of `other`, or the table
// top: a resting contact from now on.
Contact BlockContacts::contactAt(const Ladder& ladder, int block, int corner, int other, int face) const {
    if (other == kFloor) {
        Contact c;
        c.cornerPart = ladder.block(block);
        c.corner = ladder.cornerLocal(block, corner);
        c.facePart = World::ground;
        c.normal = Vec2(0, 1);
        c.offset = *floor_;
        c.halfLength = kTableHalfLength;
        return c;
    }
    const Vec2 half = ladder.cornerLocal(other, 3).cwiseAbs();
    Contact c;
    c.cornerPart = ladder.block(block);
    c.corner = ladder.cornerLocal(block, corner);
    c.facePart = ladder.block(other);
    c.normal = faceNormal(face);
    c.offset = face < 2 ? half.x() : half.y();
    c.halfLength = face < 2 ? half.y() : half.x();
    return c;
}

void BlockContacts::part(World& w, size_t i, double t, bool byImpact) {
    const Touch& c = touches_[i];
    const double gap = contactGap(w, w.contacts()[i]) + c.sunk;
    std::erase_if(parted_,
                  [&](const Parted& p) { return p.block == c.block && p.corner == c.corner && p.other == c.other; });
    parted_.push_back({c.block, c.corner, c.other, gap, t, byImpact, c.rebound});
    partedNow_.push_back({c.block, c.corner, c.other});
    w.editContacts().erase(w.contacts().begin() + std::ptrdiff_t(i));
    touches_.erase(touches_.begin() + std::ptrdiff_t(i));
}

std::vector<Event> BlockContacts::resolveOnce(World& w, Dynamics& d, const Ladder& ladder, double t, double* loss,
                                              double* heldWork) {
    std::vector<Event> events;
    if (!active()) return events;
    const double length = ladder.length();
    const double band = kTouchBand * length;
    const double still = ladder.restingRate() * length;  // m/s: a gap changing slower rests
    // m/s: an impact elsewhere that parts a resting contact slower than
    // this leaves it closed, and the force test decides (the slow-release rule of
    // docs/model.md section 8.6, with the hinges' v_min times a length).
    const double parting = ladder.hingeOptions().minReboundSpeed * length;
    auto words = [](const char* what, const Touch& c) { return contactWords(c.block, what, c.other, c.corner); };
    // 1. Partings, one at a time: a corner that has slid off its face, or
    // that moves away (an impact elsewhere parted it); else the push that
    // would pull the most.
    // A contact the pins now hold by themselves parts too: a flip or a lock
    // at this instant put a pin on its normal line, its share (17.2) is the
    // rounding's, and its push the solve's noise. In the wrong-way turn with
    // a fixed step of 1 ms, block 2's flip at 2.3869 s left block 3's corner
    // on block 0 with a share of -3e-34 and a push of 1.2e17 N, and the next
    // step's projection failed.
    const Eigen::MatrixXd& matrix = d.contactMatrix();
    for (size_t i = 0; i < touches_.size() && matrix.rows() == Eigen::Index(touches_.size()); ++i) {
        if (share(w, contactRow(w, w.contacts()[i]), matrix, Eigen::Index(i)) > kRedundant) continue;
        const Touch c = touches_[i];
        part(w, i, t, false);
        events.push_back({t, EventKind::Part, -1, -1, words("leaves", c)});
        return events;
    }
    for (size_t i = 0; i < touches_.size(); ++i) {
        const ContactRow row = contactRow(w, w.contacts()[i]);
        const bool off = slideRoom(w, i) < -band;
        const bool away = !(touches_[i].held && heldNow_) && rowTimes(row, w.v) > parting;
        if (off || away) {
            const Touch c = touches_[i];
            part(w, i, t, !off);
            events.push_back({t, EventKind::Part, -1, -1, words(off ? "slides off" : "leaves", c)});
            return events;
        }
    }
    const Eigen::VectorXd& push = d.contactForces();
    Eigen::Index worst = -1;
    double most = -ladder.forceTolerance();
    for (Eigen::Index i = 0; i < push.size() && i < Eigen::Index(touches_.size()); ++i)
        if (push[i] < most) most = push[i], worst = i;
    if (worst >= 0) {
        const Touch c = touches_[size_t(worst)];
        part(w, size_t(worst), t, false);
        events.push_back({t, EventKind::Part, -1, -1, words("leaves", c)});
        return events;
    }
    // 2. Touches: corners at a face (within the band, or past it by any
    // amount when events are not located) that close on it, or rest on it
    // with their acceleration into it. Every one at this instant is one
    // impact.
    refresh(w, ladder);
    std::vector<double> approach;
    const size_t first = touches_.size();
    for (const Watch& c : watched_) {
        const std::array<int, 3> id{c.block, c.corner, c.other};
        if (std::find(partedNow_.begin(), partedNow_.end(), id) != partedNow_.end()) continue;
        // Its function has crossed zero (where a located event leaves it,
        // or anywhere past it at the end of a step): a corner merely near a
        // face, at any instant, is not touching it.
        // A corner within the band that closes faster than v_min lands at
        // the same instant (a block landing flat lands on both ends at
        // once, whichever crossing rounding puts first).
        const double gap = against(w, ladder, c.block, c.corner, c.other, c.through).gap - c.zero;
        if (gap > band) continue;
        const bool located = std::find(located_.begin(), located_.end(), id) != located_.end();
        const int face = entryFace(w, ladder, c.block, c.corner, c.other, c.through);
        if (gap >= -allowance_ && !located) {
            const Contact candidate = contactAt(ladder, c.block, c.corner, c.other, face);
            if (!(rowTimes(contactRow(w, candidate), w.v) < -parting)) continue;
        }
        // At a corner against a corner each touches the other's face: the
        // two are one contact when their normals agree (heldAlready below
        // finds the second redundant), two when they do not (the corners
        // meet at an angle, and each keeps the other out of one face).
        const Vec2 p = ladder.cornerWorld(w, c.block, c.corner);
        if (onPin(w, ladder, p, c.block, c.other)) continue;
        // Tried without touching the world: a corner that does not close
        // leaves every cache of the engine as it was.
        const Contact candidate = contactAt(ladder, c.block, c.corner, c.other, face);
        const ContactRow row = contactRow(w, candidate);
        const double rate = rowTimes(row, w.v);
        // Closing slower than v_min L (the speed below which nothing
        // bounces and an impact elsewhere parts nothing) with an
        // acceleration that takes it away, the corner grazes the face: no
        // impact. Struck there, its push would pull at once, and the next
        // step would find it a hair closer again.
        const bool into = rate < -parting || (gap < -band) ||
                          (rate <= still && rowTimes(row, w.a) + rowBias(w, row) < -ladder.forceTolerance());
        if (!into || heldAlready(w, candidate, row)) continue;
        // Met inside the face by more than the band (a corner the pins held
        // there while its push could move nothing, or found at a step's
        // end): the contact holds it where it is. Pulled out in one
        // instant, the projection would move the blocks as far as the pins'
        // near-singular share magnifies the depth, and the step's
        // interpolant would read that jump as motion.
        const double met = contactGap(w, candidate);
        const double sunk = met < -band ? met : 0.0;
        Contact kept = candidate;
        kept.offset += sunk;
        w.editContacts().push_back(kept);
        Touch made{c.block, c.corner, c.other, face, t};
        if (face != c.through) keepThrough({c.block, c.corner, c.other}, face);
        made.sunk = sunk;
        for (const Parted& p : parted_)
            if (p.block == c.block && p.corner == c.corner && p.other == c.other && p.byImpact) {
                made.rebound = t - p.at;
                made.held = made.rebound < ladder.zenoTime() && made.rebound < p.rebound;
            }
        heldNow_ = heldNow_ || made.held;
        touches_.push_back(made);
        approach.push_back(-rate);
        events.push_back({t, EventKind::Touch, -1, -1, words("strikes", touches_.back())});
    }
    if (touches_.size() == first) return events;
    // The plastic impact with every pin and every contact active, the
    // contacts pushing only (the velocity projection is unilateral in
    // them): the hand's blocks have infinite mass.
    const std::vector<Twist> before = w.partVelocities();
    const double keBefore = energy(w).kinetic;
    projectVelocities(w, d);
    double dissipated = jumpEnergy(w, before);
    const HingeOptions& hinges = ladder.hingeOptions();
    const double e = hinges.restitution;
    if (e > 0) {
        // Restitution: a touch fast enough rebounds, the gap opening at e
        // times the speed it closed at (for one contact with nothing else).
        bool anyBounce = false;
        for (size_t i = touches_.size(); i-- > first;)
            if (!touches_[i].held && e * approach[i - first] > hinges.minReboundSpeed * length) {
                const Touch c = touches_[i];
                part(w, i, t, true);
                events.push_back({t, EventKind::Bounce, -1, -1, words("bounces off", c)});
                anyBounce = true;
            }
        if (anyBounce) dissipated = bounce(w, d, before, e);
    }
    *loss += dissipated;
    *heldWork += energy(w).kinetic - keBefore + dissipated;
    return events;
}

std::vector<BlockContactFrame> BlockContacts::frames(const World& w, const Dynamics& d) const {
    std::vector<BlockContactFrame> out;
    const Eigen::VectorXd& push = d.contactForces();
    for (size_t i = 0; i < touches_.size() && i < w.contacts().size(); ++i) {
        const Contact& c = w.contacts()[i];
        const Touch& t = touches_[i];
        const double s = Eigen::Index(i) < push.size() ? push[Eigen::Index(i)] : 0.0;
        out.push_back(
            {t.block, t.corner, t.other, w.pointPosition(c.cornerPart, c.corner), contactRow(w, c).normal, s});
    }
    return out;
}

// The ladder packs (docs/model.md section 17.3): a corner of block a
// strikes block b at the instant the hinges between them close on their
// limits, the loop of blocks a .. b folded flat and locked straight. There
// the loop is at a dead point: the corner's normal line runs through its
// hinges, a push at the corner turns none of them, and a contact resting
// there is held by a push that grows as 1 / (t_c - t). The corner's gap
// then tells the hinges' angles only to the square root of the pins'
// tolerance over a block's length (the gap is quadratic in them), 4e-5 rad
// at 1e-10 m: the closing hinges of the loop within that of a limit reach
// it at the strike's instant, in one plastic impact. Read at the located
// strike instead, they were 7.7e-7 and 5.0e-7 rad short in the wrong-way
// turn (0.8995 s), the strike stopped them there, and the pins of the
// interpolated instant were open by 1.6e-10 m.
std::vector<int> Ladder::packedBy(const World& w) const {
    std::vector<int> hinges;
    const double band = std::sqrt(gapTolerance_ / length());
    for (const auto& [a, corner, b] : blockContacts_.striking(w, *this)) {
        (void)corner;
        for (int j = std::min(a, b) + 1; j <= std::max(a, b) && j < liveEnd(); ++j) {
            if (hinge(j).mode != HingeMode::Free || std::find(hinges.begin(), hinges.end(), j) != hinges.end())
                continue;
            for (bool folded : {false, true}) {
                const double gap = folded ? std::numbers::pi - hinge(j).foldAngle : hinge(j).foldAngle;
                const double rate = folded ? -foldRate(w, j) : foldRate(w, j);
                if (gap < band && rate < -restingRate_) {
                    hinges.push_back(j);
                    break;
                }
            }
        }
    }
    return hinges;
}

// As resolveOnce judges a strike: a corner at a hinge, or past the band,
// does not pack anything (counted, one closed hinge 19 of a 76-block ladder
// of 1 mm blocks 1.2 ns early where nothing struck).
std::vector<std::array<int, 3>> BlockContacts::striking(const World& w, const Ladder& ladder) const {
    std::vector<std::array<int, 3>> out;
    const double parting = ladder.hingeOptions().minReboundSpeed * ladder.length();
    for (const Watch& c : watched_) {
        const std::array<int, 3> id{c.block, c.corner, c.other};
        if (c.other == kFloor || std::find(located_.begin(), located_.end(), id) == located_.end()) continue;
        if (against(w, ladder, c.block, c.corner, c.other, c.through).gap - c.zero > kTouchBand * ladder.length())
            continue;
        if (onPin(w, ladder, ladder.cornerWorld(w, c.block, c.corner), c.block, c.other)) continue;
        const Contact candidate =
            contactAt(ladder, c.block, c.corner, c.other, entryFace(w, ladder, c.block, c.corner, c.other, c.through));
        const ContactRow row = contactRow(w, candidate);
        if (rowTimes(row, w.v) < -parting && !heldAlready(w, candidate, row)) out.push_back(id);
    }
    return out;
}

// An instant settled with the contacts between blocks too: the hinges
// first (their own active set, with every resting contact in each of their
// impacts), the hinges a strike packs, then the block contacts, and the
// hinges again after each change there, until neither has anything to do.
std::vector<Event> Ladder::settle(World& w, Dynamics& d, double t, double* impactLoss, double* heldWork) {
    std::vector<Event> events = resolve(w, d, t, impactLoss, heldWork);
    if (!blockContacts_.active()) return events;
    blockContacts_.forgetCleared(w, *this);
    blockContacts_.newInstant();
    if (const std::vector<int> packed = packedBy(w); !packed.empty()) {
        std::vector<int> released;
        for (Event& e : impact(w, d, t, packed, impactLoss, heldWork, &released)) {
            e.text = words(e.kind, e.hinge);
            events.push_back(std::move(e));
        }
        std::vector<Event> more = resolve(w, d, t, impactLoss, heldWork);
        events.insert(events.end(), more.begin(), more.end());
    }
    for (int guard = 0; guard < 8 * blockCount() + 8; ++guard) {
        std::vector<Event> more = blockContacts_.resolveOnce(w, d, *this, t, impactLoss, heldWork);
        if (more.empty()) {
            blockContacts_.forgetLocated();
            return events;
        }
        events.insert(events.end(), more.begin(), more.end());
        more = resolve(w, d, t, impactLoss, heldWork);
        events.insert(events.end(), more.begin(), more.end());
    }
    if (error_.empty()) error_ = "the contacts between blocks at t = " + std::to_string(t) + " s could not be settled";
    return events;
}

std::size_t BlockContacts::heapBytes() const {
    using jl::heapBytes;
    return heapBytes(watched_) + heapBytes(through_) + heapBytes(throughNext_) + heapBytes(touches_) +
           heapBytes(parted_) + heapBytes(partedNow_) + heapBytes(located_) + heapBytes(pairs_) + broad_.heapBytes();
}

}  // namespace jl
