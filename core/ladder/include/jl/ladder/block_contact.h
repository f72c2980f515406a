// Contact between blocks that are not neighbours (docs/model.md section
// 17): a corner of one block against a face of another, frictionless and
// unilateral. Neighbours meet through their hinge (LOCK and FOLD) and are
// never tested here.
#pragma once

#include "jl/engine/dynamics.h"
#include "jl/engine/world.h"
#include "jl/ladder/hinge_event.h"

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace jl {

class Ladder;

// Where a corner stands against a block's box, in the box's frame: the
// signed distance to the face it is nearest to crossing (> 0 outside that
// face's plane, < 0 inside every face's), and that face.
struct CornerAgainstBox {
    double gap = 0;  // m: max over the four faces of (n . local - half size)
    int face = 0;    // 0, 1: -x, +x (the long faces); 2, 3: -y, +y (the ends)
};

// Pairs of blocks whose bounding circles overlap, by a grid hashed on the
// blocks' centres: O(moving blocks + segments of the still tail) per search,
// the pairs within a skin kept until a block has moved by half of it.
// Neighbours, blocks of one body and blocks both in the still tail are left
// out.
class BlockPairs {
public:
    // At most this many blocks in the search: every pair compared, no grid.
    static constexpr size_t kDirect = 16;
    void find(const World& w, const Ladder& ladder, std::vector<std::pair<int, int>>& out);
    // The next call searches again, as if nothing were kept (the benchmark
    // times a search and a call that keeps its pairs apart).
    void forget() { kept_ = false; }
    // Whether two blocks of a pair are apart by more than `by` along one of
    // their axes (a separating axis), from the distances of each one's four
    // corners to the other's face planes: beyond[0][k][f], corner k of the
    // first against face f of the second; beyond[1], the other way round.
    using CornerDistances = std::array<std::array<std::array<double, 4>, 4>, 2>;
    static bool apart(const CornerDistances& beyond, double by);

    // What it holds on the heap (jl/base/heap_bytes.h): what a copy takes.
    std::size_t heapBytes() const;

private:
    struct Segment {
        int body = 0, first = 0, end = 0;  // blocks [first, end) of one body of the still tail
        Vec2 lo, hi;                       // m: the box of their centres in the body's frame
        Pose foundAt;                      // the body's pose at the last search
        bool searched = false;             // its blocks were members of that search
    };
    // m: how far beyond touching the kept pairs reach (the largest half
    // diagonal: 31 mm for the default block).
    double skin() const { return reach_; }
    void listSegments(const World& w, const Ladder& ladder, int still);
    bool stillNear(const World& w, const Ladder& ladder);
    void search(const World& w, const Ladder& ladder, int moving);
    void comparePairwise(const World& w, const Ladder& ladder, int moving, std::vector<std::pair<int, int>>& out) const;
    std::vector<int> head_, next_, members_;
    std::vector<long long> key_;
    std::vector<Vec2> centre_, foundAt_;     // m: the members' centres now, and at the last search
    std::vector<std::pair<int, int>> near_;  // the pairs whose circles widened by the skin overlapped then
    bool kept_ = false;                      // near_ holds the last search's pairs
    int keptFor_ = -1;                       // the still tail's first block at that search
    std::vector<double> radius_;             // m, each block's half diagonal
    std::vector<Segment> segments_;
    int segmentsFor_ = -1;  // the still tail's first block they were listed for
    double reach_ = 0;      // m, the largest half diagonal
    int reachFor_ = -1;     // the block count it was found for
};

class BlockContacts {
public:
    // Off: the paper's model, blocks pass through one another.
    void setEnabled(bool on) { enabled_ = on; }
    bool enabled() const { return enabled_; }
    // A level table top at `height` (m), or none: block corners meet it as
    // they meet a block's face (docs/model.md section 17.8), whether or not
    // blocks meet each other. `other` is kFloor for it.
    void setFloor(std::optional<double> height) { floor_ = height; }
    const std::optional<double>& floor() const { return floor_; }
    static constexpr int kFloor = -1;
    // Anything to watch at all: contact between blocks, or a floor.
    bool active() const { return enabled_ || floor_.has_value(); }

    // After a step, at its end: the corners of blocks near each other, each
    // watched against the other block, and the contacts that rest. The
    // event functions of the next location are these, at any state.
    void refresh(const World& w, const Ladder& ladder);
    // At a state the run keeps (a step's end that settles nothing, a
    // settled instant): the corners parted inside a face and clear of it
    // now go back to the plain zero.
    void forgetCleared(const World& w, const Ladder& ladder);
    // Appends the functions (>= 0 while nothing happens): each watched
    // corner's gap, and each resting contact's push and how far its corner
    // is from sliding off the face. Returns the smallest push (+inf if none).
    double eventFunctions(const World& w, const Dynamics& d, const Ladder& ladder, std::vector<double>& out) const;
    // Whether function k of those needs positions alone (a gap or a slide),
    // its value, and the bodies whose coordinates it reads.
    bool positional(int k) const { return k < int(watched_.size()) || isSlide(k); }
    double positionFunction(const World& w, const Ladder& ladder, int k) const;
    std::array<int, 2> bodies(const World& w, const Ladder& ladder, int k) const;

    // At an instant, after the hinges are settled (the dynamics evaluated
    // there): contacts whose push would pull, or whose corner has slid off
    // the face or moves away, part; corners that touch while closing (or
    // rest with their acceleration into the face) make contact, in one
    // plastic impact (restitution as the hinges'). Returns what happened;
    // empty if nothing did.
    std::vector<Event> resolveOnce(World& w, Dynamics& d, const Ladder& ladder, double t, double* loss,
                                   double* heldWork);
    // A new instant: the contacts parted in the last one may touch again.
    void newInstant() {
        partedNow_.clear();
        heldNow_ = false;
    }
    // While an event is located, the corners' functions cross where the
    // gap does (the rounding of a pose aside); at a step's end a corner
    // must be past the face by more than the pins' own tolerance (`gap`,
    // m) to count: where the ladder folds flat, a block's corner lies on
    // the face of the block beyond the next with gap zero to the
    // projection's noise (the heavy-middle example, 2.4e-12 m), and that
    // is no contact.
    void setLocating(bool on) { locating_ = on; }
    void setAllowance(double gap) { allowance_ = gap; }
    // The functions (indices into those eventFunctions appended) whose
    // crossing was located: those corners touch however little they are
    // past the face. Forgotten once the instant is settled.
    void markLocated(const std::vector<int>& functions);
    void forgetLocated() { located_.clear(); }
    // The corners (block, corner, other) whose crossing of another block's
    // face this instant located and that close on it faster than v_min L
    // where the pins do not hold them already: they strike it (a graze, or
    // a corner at a hinge, does not).
    std::vector<std::array<int, 3>> striking(const World& w, const Ladder& ladder) const;

    // Which blocks each of World::contacts() joins: the corner's block and
    // corner, the face's block and face.
    struct Touch {
        int block = 0, corner = 0, other = 0, face = 0;
        double since = 0;  // s, when it closed
        // s: how long it was apart before this close, if an impact parted
        // it (a rebound); infinite when it last parted by its push or never.
        double rebound = std::numeric_limits<double>::infinity();
        // Closed at the end of a rebound shorter than the Zeno time and than
        // the one before: the limit of a shrinking sequence (docs/model.md
        // section 8.6, held contacts). It does not bounce, and an impact
        // elsewhere in the instant it became held does not part it.
        bool held = false;
        double sunk = 0;  // m, <= 0: how far inside the face it was met and is held
        bool operator==(const Touch&) const = default;
    };
    const std::vector<Touch>& touches() const { return touches_; }
    // The resting contacts as the views draw them (pushes from the last
    // evaluation of the dynamics).
    std::vector<BlockContactFrame> frames(const World& w, const Dynamics& d) const;
    // How many pairs and corners the broad phase passed on at the last refresh.
    int pairCount() const { return pairCount_; }

    // `through`: the face the corner last stood clearly outside of, or -1.
    // A corner that slides along the plane of one face while it crosses
    // another (blocks side by side with their ends flush, as the hinges
    // stack them) stands on both planes at once: the plain maximum would
    // read 0, a rounding's width from either face, all the way in. So the
    // face it comes through counts as is, and the others only once they
    // are `kFlush` beyond it.
    // Where a corner of one block is inside another that is not its
    // neighbour (with contact between blocks on), or under the table top,
    // by more than the touch band: the words of the first such corner, or
    // nothing. The contacts meet corners only as they arrive at a face; a
    // scripted pull that puts one inside a block is refused with this.
    std::optional<std::string> inside(const World& w, const Ladder& ladder) const;

    // m: how far inside a face a corner may be found and still be at it.
    static double touchBand(const Ladder& ladder);

    static CornerAgainstBox cornerAgainst(const World& w, const Ladder& ladder, int block, int corner, int other,
                                          int through = -1);
    // The same against `other` or the floor (other == kFloor: the gap above
    // the table top, face 3).
    CornerAgainstBox against(const World& w, const Ladder& ladder, int block, int corner, int other,
                             int through = -1) const;

    // What it holds on the heap (jl/base/heap_bytes.h): what a copy takes.
    std::size_t heapBytes() const;

private:
    struct Watch {
        int block = 0, corner = 0, other = 0;
        double zero = 0;   // m, <= 0: where the gap counts as zero (a contact just parted reads a hair inside)
        int through = -1;  // the face it last stood clearly outside of (cornerAgainst)
    };
    // The face each watched corner last stood clearly outside of, kept from
    // one refresh to the next.
    // `plain`: where the corner stands against the box (cornerAgainst
    // without a face it came through).
    int throughFace(const Ladder& ladder, const CornerAgainstBox& plain, int block, int corner, int other) const;
    // A block's pose, half size and corners, and the rotation back into its
    // frame: worked out once for every corner tested against it.
    struct Placed {
        Pose pose;
        Vec2 half;
        std::array<Vec2, 4> corner;
        double backCos = 1, backSin = 0;  // of -pose.angle
        // Point p (m, in the world) in the block's frame.
        Vec2 local(const Vec2& p) const {
            const Vec2 r = p - pose.position;
            return {backCos * r.x() - backSin * r.y(), backSin * r.x() + backCos * r.y()};
        }
        // Signed distances of a point in the block's frame to its faces'
        // planes (faces 0 to 3), > 0 outside.
        std::array<double, 4> beyond(const Vec2& l) const {
            return {-l.x() - half.x(), l.x() - half.x(), -l.y() - half.y(), l.y() - half.y()};
        }
    };
    enum class Need { Both, Corners, Box };  // the corners, the rotation back, or both
    static Placed placed(const World& w, const Ladder& ladder, int block, Need need = Need::Both);
    // cornerAgainst for a point p (m, in the world) and a placed box.
    static CornerAgainstBox pointAgainst(const Vec2& p, const Placed& box, double flush, int through = -1);
    // The face whose plane a point is farthest beyond, from its distances
    // to the four (Placed::beyond).
    static CornerAgainstBox nearestFace(const std::array<double, 4>& d);

    // The watched corners' functions: the gap past its zero, less the
    // allowance (below).
    double watchFunction(const World& w, const Ladder& ladder, const Watch& c) const;
    double watchValue(const Ladder& ladder, double against, const Watch& c) const;  // `against`: its gap (m)
    bool isSlide(int k) const {
        return k >= int(watched_.size()) + int(touches_.size()) && k < int(watched_.size()) + 2 * int(touches_.size());
    }
    double slideRoom(const World& w, size_t i) const;
    static bool heldAlready(const World& w, const Contact& c, const ContactRow& row);
    static double share(const World& w, const ContactRow& row, const Eigen::MatrixXd& matrix, Eigen::Index i);
    int entryFace(const World& w, const Ladder& ladder, int block, int corner, int other, int through) const;
    Contact contactAt(const Ladder& ladder, int block, int corner, int other, int face) const;
    void keepThrough(const std::array<int, 3>& id, int face);
    // Where through_ holds (block, corner, other), or -1.
    std::ptrdiff_t throughOf(const std::array<int, 3>& id) const;
    // The corners of moving blocks near the floor, watched against it.
    void watchFloor(const World& w, const Ladder& ladder);
    bool resting(int block, int corner, int other) const;
    static bool atHingeOf(const Ladder& ladder, const Vec2& p, int b, const Placed& box);
    static bool onPin(const World& w, const Ladder& ladder, const Vec2& p, int a, int b);
    double gapZero(int block, int corner, int other) const;
    // `byImpact`: it moves away after an impact (a rebound starts), not
    // parted by its push or off its face's end.
    void part(World& w, size_t i, double t, bool byImpact);

    bool enabled_ = true;
    std::optional<double> floor_;  // m, the table top's height
    bool locating_ = false;
    double allowance_ = 1e-10;  // m
    std::vector<Watch> watched_;
    // (block, corner, other) and the face it came through, for every corner
    // of a near pair (watched or not), sorted; the next refresh's is built
    // in throughNext_, both kept without an allocation per corner.
    std::vector<std::pair<std::array<int, 3>, int>> through_, throughNext_;
    std::vector<Touch> touches_;  // parallel to World::contacts()
    // Parted at some instant, and the gap they parted at (the projection's
    // noise): their zero, until they are clear by kClear.
    struct Parted {
        int block = 0, corner = 0, other = 0;
        double gap = 0;                                            // m; 0 once clear
        double at = 0;                                             // s, when it parted
        bool byImpact = false;                                     // a rebound started then
        double rebound = std::numeric_limits<double>::infinity();  // s, the one that ended before it
    };
    std::vector<Parted> parted_;
    std::vector<std::array<int, 3>> partedNow_;
    bool heldNow_ = false;                     // a contact became held in this instant
    std::vector<std::array<int, 3>> located_;  // in this instant: they stay apart in it
    std::vector<std::pair<int, int>> pairs_;
    int pairCount_ = 0;
    BlockPairs broad_;
};

}  // namespace jl
