// labels: physics
// Three blocks, worked by hand (docs/model.md section 17.7): the hand holds
// the top two, bent at hinge 1, and lets the bottom one go. It swings about
// hinge 2, folds face to face onto block 1, flips over block 1's far end,
// swings on about that end and strikes the held top block with a corner:
// where it comes to rest, when each thing happens, the energy each plastic
// impact takes, and the push that holds it there, all from the geometry of
// two swings of a rigid block about a fixed point.
#include "tests/scene_run.h"

#include <QtTest>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>

using namespace jl;
using namespace jl::test;

namespace {

constexpr double kG = 9.81;
constexpr double kL = 0.06, kT = 0.012, kW = 0.045, kDensity = 600;

// Block 0 lies flat at the origin; hinge 1 bent to 1.2 rad puts block 1
// above its left end, leaning out; block 2 starts square to block 1.
const char* kScene =
    "format: jacobs-ladder/1\n"
    "title: flip and strike\n"
    "ladder:\n"
    "  blocks: 3\n"
    "  block: {length: 0.06, thickness: 0.012, width: 0.045, density: 600}\n"
    "  held: [0, 1]\n"
    "  initial:\n"
    "    kind: fold_angles\n"
    "    poses:\n"
    "      - {block: 0, position: [0, 0], angle: -90deg}\n"
    "    fold_angles: [1.2, 1.5707963267948966]\n"
    "duration: 2\n"
    "solver: {block_contact: on, event_tolerance: 1e-12, integrator: rk4, step: 1e-4}\n";

// A rigid block turning about a fixed point P: its pose after turning by a.
struct Swing {
    Vec2 pivot, centre;            // centre at the start
    double mass = 0, inertia = 0;  // inertia about the pivot
    Vec2 centreAt(double a) const { return pivot + rotate(a, centre - pivot); }
    Vec2 pointAt(const Vec2& p, double a) const { return pivot + rotate(a, p - pivot); }
    // Released at rest: how long it takes to turn by `angle` (signed, the
    // way gravity turns it). The speed is sqrt(2 m g (y0 - y(a)) / I); the
    // change of variable a = u^2 takes away the start's 1/sqrt(a), and
    // Gauss-Legendre on many panels does the rest to rounding.
    double timeToTurn(double angle) const {
        const double sign = angle < 0 ? -1 : 1;
        const double y0 = centre.y();
        auto integrand = [&](double u) {
            const double drop = y0 - centreAt(sign * u * u).y();
            return 2 * u / std::sqrt(2 * mass * kG * drop / inertia);
        };
        static constexpr std::array<double, 5> x{0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640,
                                                 0.9061798459386640};
        static constexpr std::array<double, 5> wgt{0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
                                                   0.2369268850561891, 0.2369268850561891};
        const double end = std::sqrt(std::abs(angle));
        const int panels = 400;
        double sum = 0;
        for (int k = 0; k < panels; ++k) {
            const double a = end * k / panels, b = end * (k + 1) / panels;
            for (size_t i = 0; i < x.size(); ++i)
                sum += wgt[i] * (b - a) / 2 * integrand((a + b) / 2 + (b - a) / 2 * x[i]);
        }
        return sum;
    }
};

// The corners of a block of centre c and angle a (the order does not matter).
std::array<Vec2, 4> corners(const Vec2& c, double a) {
    std::array<Vec2, 4> out;
    int k = 0;
    for (double sx : {-1.0, 1.0})
        for (double sy : {-1.0, 1.0}) out[size_t(k++)] = c + rotate(a, Vec2(sx * kT / 2, sy * kL / 2));
    return out;
}

// Whether point p is inside the block of centre c and angle a (by more than e).
bool inside(const Vec2& p, const Vec2& c, double a, double e = 0) {
    const Vec2 local = rotate(-a, p - c);
    return std::abs(local.x()) < kT / 2 - e && std::abs(local.y()) < kL / 2 - e;
}

// The first turn (signed as `sign`, between 0 and pi) at which a corner of
// the swinging block enters the fixed one, found where it first happens on
// a fine scan and then to rounding by bisection on that corner's depth.
struct Strike {
    double angle = 0;
    int corner = -1;  // of the swinging block
};
std::optional<Strike> firstStrike(const Swing& s, const std::array<Vec2, 4>& start, const Vec2& fixedCentre,
                                  double fixedAngle, double sign) {
    const int scan = 200000;
    for (int n = 1; n <= scan; ++n) {
        const double a = sign * std::numbers::pi * n / scan;
        for (int k = 0; k < 4; ++k) {
            if (!inside(s.pointAt(start[size_t(k)], a), fixedCentre, fixedAngle)) continue;
            // Depth below the face it crossed: the largest signed distance
            // to the four face planes (negative inside), zero at the face.
            auto depth = [&](double t) {
                const Vec2 local = rotate(-fixedAngle, s.pointAt(start[size_t(k)], t) - fixedCentre);
                return std::max(std::abs(local.x()) - kT / 2, std::abs(local.y()) - kL / 2);
            };
            double lo = sign * std::numbers::pi * (n - 1) / scan, hi = a;
            for (int i = 0; i < 200 && lo != hi; ++i) {
                const double mid = (lo + hi) / 2;
                if (mid == lo || mid == hi) break;
                (depth(mid) < 0 ? hi : lo) = mid;
            }
            return Strike{hi, k};
        }
    }
    return std::nullopt;
}

}  // namespace

class FlipAndStrikeTest : public QObject {
    Q_OBJECT

private slots:
    void theBottomBlockFoldsFlipsAndComesToRestOnTheTopBlock() {
        auto sim = simulate(kScene);
        QVERIFY(sim);
        const Ladder& ladder = *sim->ladder();
        const World& w0 = sim->world();
        const double m = kDensity * kL * kT * kW;
        const double centreInertia = m * (kL * kL + kT * kT) / 12;
        QVERIFY(std::abs(w0.part(ladder.block(2)).mass - m) < 1e-15);
        QVERIFY(std::abs(w0.part(ladder.block(2)).inertia - centreInertia) < 1e-18);

        // The held blocks, as the scene puts them.
        const Pose top = w0.partPose(ladder.block(0)), middle = w0.partPose(ladder.block(1));
        const Pose start = w0.partPose(ladder.block(2));
        const Vec2 hinge2 = ladder.cornerWorld(w0, 1, ladder.hinge(2).corner);

        // First swing: about hinge 2, the way gravity turns it, until its
        // face lies on block 1's (the fold angle 1.5708 rad has closed).
        Swing first{hinge2, start.position, m, centreInertia + m * (start.position - hinge2).squaredNorm()};
        const double sign1 = (start.position.x() - hinge2.x()) > 0 ? -1 : 1;
        const double turn1 = sign1 * std::numbers::pi / 2;
        const Vec2 folded = first.centreAt(turn1);
        const double foldedAngle = start.angle + turn1;
        // Face to face: a thickness from block 1's centre, square to its length.
        QVERIFY(std::abs((folded - middle.position).norm() - kT) < 1e-12);
        QVERIFY(std::abs(rotate(-middle.angle, folded - middle.position).y()) < 1e-12);
        const double foldTime = first.timeToTurn(turn1);
        const double foldLoss = m * kG * (start.position.y() - folded.y());

        // The flip: block 2 now turns about block 1's other corner on that
        // face, the one of its two shared corners that is not hinge 2.
        Vec2 hinge2After = Vec2::Zero();
        int shared = 0;
        for (const Vec2& p : corners(middle.position, middle.angle))
            for (const Vec2& q : corners(folded, foldedAngle))
                if ((p - q).norm() < 1e-12 && (p - hinge2).norm() > kL / 2) hinge2After = p, ++shared;
        QCOMPARE(shared, 1);

        // Second swing: from rest, about that corner, until a corner of
        // block 2 enters block 0.
        Swing second{hinge2After, folded, m, centreInertia + m * (folded - hinge2After).squaredNorm()};
        const double sign2 = (folded.x() - hinge2After.x()) > 0 ? -1 : 1;
        const std::optional<Strike> strike =
            firstStrike(second, corners(folded, foldedAngle), top.position, top.angle, sign2);
        QVERIFY(strike);
        const double strikeTime = foldTime + second.timeToTurn(strike->angle);
        const Vec2 rest = second.centreAt(strike->angle);
        const double restAngle = foldedAngle + strike->angle;
        const double strikeLoss = m * kG * (folded.y() - rest.y());
        // Gravity still turns it into block 0 there, so it stays: the face
        // the corner is on (of block 0, its outward normal n) pushes it, and
        // the moments about the pivot balance, s ((q - P) x n) = m g (c - P).x.
        const Vec2 q = second.pointAt(corners(folded, foldedAngle)[size_t(strike->corner)], strike->angle);
        const Vec2 local = rotate(-top.angle, q - top.position);
        const bool onEnd = std::abs(std::abs(local.y()) - kL / 2) < 1e-12;
        QVERIFY(onEnd != (std::abs(std::abs(local.x()) - kT / 2) < 1e-12));
        const Vec2 n = rotate(top.angle, onEnd ? Vec2(0, local.y() > 0 ? 1 : -1) : Vec2(local.x() > 0 ? 1 : -1, 0));
        const double push = m * kG * (rest.x() - hinge2After.x()) / cross(q - hinge2After, n);
        QVERIFY(push > 0);
        qInfo("by hand: fold %.12f s (loss %.9g J), strike %.12f s after %.9f rad (loss %.9g J), push %.9g N", foldTime,
              foldLoss, strikeTime, strike->angle, strikeLoss, push);

        // The engine: the same story, event by event.
        double fold = -1, flip = -1, touch = -1;
        double lossAtFlip = -1;
        std::vector<std::string> words;
        const Run run = runUntil(*sim, 2.0, [&](const Frame& f) {
            for (const Event& e : f.events) {
                words.push_back(e.text);
                if (e.kind == EventKind::Fold && fold < 0) fold = e.time;
                if (e.kind == EventKind::FlipFlop && flip < 0) flip = e.time, lossAtFlip = f.energy.impactLoss;
                if (e.kind == EventKind::Touch && touch < 0) touch = e.time;
            }
        });
        for (const std::string& s : words) qInfo("  %s", s.c_str());
        QVERIFY2(run.failure.empty(), run.failure.c_str());
        qInfo("engine: fold %.12f s, flip %.12f s, strike %.12f s (%.2g and %.2g s from the hand)", fold, flip, touch,
              fold - foldTime, touch - strikeTime);
        QVERIFY(std::abs(fold - foldTime) < 1e-10);
        QCOMPARE(flip, fold);
        QVERIFY(std::abs(touch - strikeTime) < 1e-10);
        QVERIFY(std::abs(lossAtFlip - foldLoss) < 1e-9 * foldLoss);
        QCOMPARE(int(words.size()), 3);
        QVERIFY(words.back().starts_with("block 2 strikes block 0"));

        // At rest where the strike left it, held up by one push.
        const Frame f = sim->frame();
        const Pose end = sim->world().partPose(ladder.block(2));
        qInfo("rest (%.12f, %.12f) %.12f rad; by hand (%.12f, %.12f) %.12f rad", end.position.x(), end.position.y(),
              end.angle, rest.x(), rest.y(), restAngle);
        QVERIFY((end.position - rest).norm() < 1e-9);
        QVERIFY(std::abs(std::remainder(end.angle - restAngle, 2 * std::numbers::pi)) < 1e-9);
        QVERIFY(sim->world().partVelocity(ladder.block(2)).linear.norm() < 1e-9);
        QCOMPARE(int(f.blockContacts.size()), 1);
        QVERIFY((f.blockContacts[0].normal - n).norm() < 1e-9);
        qInfo("push %.12g N, by hand %.12g N; loss %.12g J, by hand %.12g J", f.blockContacts[0].push, push,
              f.energy.impactLoss, foldLoss + strikeLoss);
        QVERIFY(std::abs(f.blockContacts[0].push - push) < 1e-9 * push);
        QVERIFY(std::abs(f.energy.impactLoss - (foldLoss + strikeLoss)) < 1e-9 * (foldLoss + strikeLoss));
        QVERIFY(run.worstBalance < 1e-9);
    }
};

QTEST_APPLESS_MAIN(FlipAndStrikeTest)
#include "test_flip_and_strike.moc"
