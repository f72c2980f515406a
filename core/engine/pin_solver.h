// The pins' equations (J W J^T) x = r: O(N) block-tridiagonal elimination
// along chains of bodies, Eigen's sparse LDLT for branched or looped graphs.
// Private to the engine: other parts reach it through Dynamics and the
// projections (projection.h), which own or borrow one.
#pragma once

#include "jl/base/geometry.h"

#include <Eigen/Core>
#include <Eigen/SparseCholesky>

#include <array>
#include <cstdint>
#include <vector>

namespace jl {

class World;

class PinSolver {
public:
    // Arms and matrix at the world's current positions, then factorise.
    // Re-derives the pin ordering only when the world's structure changed,
    // and does nothing at all for the world it last assembled (the same
    // World::revision and turns of the bodies bit for bit, which is all the
    // matrix depends on): a step's velocity projection and the evaluation of
    // its end share one factorisation.
    void assemble(const World& w);
    // The same with other inverse masses and inertias, (1/m, 1/I) per body,
    // kinematic ones ignored: the linearly implicit integrator's matrix,
    // whose bodies carry the stiffness and damping of one step as extra
    // mass (docs/model.md section 6.4).
    void assemble(const World& w, const std::vector<Eigen::Vector2d>& inverseMass);
    // assemble() in two halves, for a caller that needs the arms to form its
    // right-hand side: prepare() turns the arms (armA, armB) and returns
    // whether the factorisation in hand is stale; if it is, factorAndSolve()
    // factorises and solves in one sweep, else solve() uses the one in hand.
    bool prepare(const World& w);
    // (cos, sin) of every body's turn at the world's positions, worked out
    // once for one set of turns, bit for bit, whoever asks first: the
    // projection's gaps and then the factorisation at the same positions
    // (a sine and a cosine per body were a sixth of a long ladder's run).
    const std::vector<Eigen::Vector2d>& turns(const World& w);
    void factorAndSolve(const World& w, const Eigen::VectorXd& r, Eigen::VectorXd& x);
    // Whether the factorisation in hand (and the arms solve() and
    // addJTranspose() use) is of this world's pins and masses, at whatever
    // turns it was assembled: the last stage of a step, for the projection
    // that follows it (projection.cpp).
    bool holdsFactorisationFor(const World& w) const;
    // The one or the other, as prepare() said (`stale`).
    void solvePrepared(const World& w, bool stale, const Eigen::VectorXd& r, Eigen::VectorXd& x) {
        if (stale)
            factorAndSolve(w, r, x);
        else
            solve(r, x);
    }
    // The dynamics' accelerations: assembles at the world's positions, then
    // sets every dynamic body's a = W (f + J^T lambda) with the pins' forces
    // lambda that hold J a + (the pins' velocity terms) = 0; f: the applied
    // forces, 3 per body; a kinematic body keeps its prescribed a. Along
    // chains with a fresh factorisation, in the solve's two sweeps.
    void accelerations(World& w, const Eigen::VectorXd& force, Eigen::VectorXd& lambda);
    // The velocity projection (docs/model.md section 5.2): P with
    // (J W J^T) P = -J v, and every dynamic body's v += W J^T P, assembling
    // at the world's positions if it must. Along chains J v is formed as the
    // elimination reaches each pin and each body's velocity as the back
    // substitution has both of its pins' impulses, as in accelerations().
    void removeVelocityDrift(World& w, Eigen::VectorXd& impulses);
    // Solves (J W J^T) x = r; r and x hold 2 entries per pin, in w.pins()
    // order, then 1 per weld (w.welds()).
    void solve(const Eigen::VectorXd& r, Eigen::VectorXd& x) const;
    // x = (J W J^T)^{-1} J u and jtx = J^T x (3 per body; zero on kinematic
    // bodies) with the factorisation in hand: the linearly implicit
    // integrator's solve with its own masses.
    void solveApplying(const World& w, const Eigen::VectorXd& u, Eigen::VectorXd& x, Eigen::VectorXd& jtx);
    // out = J u: the relative velocity (or acceleration part) of every pin
    // for body vector u (3 per body, kinematic bodies included).
    void multiplyJ(const Eigen::VectorXd& u, Eigen::VectorXd& out) const;
    // f += J^T x: pin forces (or impulses) x applied to the bodies.
    void addJTranspose(const Eigen::VectorXd& x, Eigen::VectorXd& f) const;

    // Forget the cached ordering (the world was replaced, e.g. by a snapshot).
    void reset() {
        version_ = -1;
        analysed_ = false;
        assembledPlain_ = false;
    }
    int pinCount() const { return int(pins_.size()); }
    int rowCount() const { return int(2 * pins_.size() + welds_.size()); }
    // The O(N) chain elimination handles pins only: welds (and branched or
    // looped graphs) take the sparse factorisation. `forceSparse` takes it
    // for everything, so the two models of a rigid pair can be compared on
    // the same solver.
    void setForceSparse(bool on) {
        forceSparse_ = on;
        version_ = -1;
        assembledPlain_ = false;
    }
    // World-frame arm from body A's (B's) origin to pin i, and the bodies.
    const Vec2& armA(int i) const { return pins_[size_t(i)].rA; }
    const Vec2& armB(int i) const { return pins_[size_t(i)].rB; }
    int bodyA(int i) const { return pins_[size_t(i)].bodyA; }
    int bodyB(int i) const { return pins_[size_t(i)].bodyB; }

    // Work vectors of the projection (projection.cpp), kept here so that a
    // step allocates nothing once the sizes have settled.
    struct Scratch {
        Eigen::VectorXd gap, x, dq, q0;
    };
    Scratch scratch;

private:
    // A tiny diagonal shift for singular pivots (redundant pins): it picks
    // one of the equal solutions instead of dividing by zero.
    static constexpr double kRegularisation = 1e-12;
    struct PinRow {
        int bodyA, bodyB;
        bool dynA, dynB;  // has finite mass
        Vec2 rA, rB;      // world arms
    };
    struct WeldRow {
        int bodyA, bodyB;
        bool dynA, dynB;
        double arm;
    };
    // Consecutive pins of a chain share one dynamic body.
    struct Link {
        int body;
        double signPrev, signNext;  // +1 if the body is the pin's A side
    };
    void assemble(const World& w, const std::vector<Eigen::Vector2d>* inverseMass);
    void order(const World& w);
    void updateBodies(const World& w, const std::vector<Eigen::Vector2d>* inverseMass);
    bool prepare(const World& w, const std::vector<Eigen::Vector2d>* inverseMass);
    template <class RowRhs>
    void factorChain(const RowRhs& rhs, Eigen::VectorXd* x);
    template <class RowRhs>
    void forwardSubstitute(const RowRhs& rhs, Eigen::VectorXd& x) const;
    template <class Passed>
    void backSubstitute(Eigen::VectorXd& x, const Passed& passed) const;
    template <class Start, class Apply>
    void backSubstituteApplying(Eigen::VectorXd& x, const std::vector<unsigned char>& kinematic, const Start& start,
                                const Apply& apply) const;
    void factorSparse(const World& w);

    long long version_ = -1;
    // What the factorisation in hand was assembled from (plain: the world's
    // own masses, not the linearly implicit method's).
    bool assembledPlain_ = false;
    std::uint64_t assembledRevision_ = 0;
    std::vector<double> angle_;  // each body's turn when last assembled
    bool sameTurns(const World& w) const;
    bool chain_ = true;
    std::vector<PinRow> pins_;
    std::vector<WeldRow> welds_;
    bool forceSparse_ = false;
    std::vector<Eigen::Vector2d> rotation_;  // (cos, sin) per body: one sincos per body, not per pin end
    std::vector<double> rotated_;            // the turns rotation_ holds, bit for bit
    std::vector<Eigen::Vector2d> inverse_;   // (1/m, 1/I) per body, or the ones assemble was given
    std::uint64_t inverseRevision_ = 0;      // the world's whose own inverse_ holds; 0: none
    // Chain mode: pins in path order, path starts, and links between neighbours.
    std::vector<std::array<int, 2>> pinsOfBody_;  // order(): the first two pins of each body
    std::vector<int> pinCountOfBody_;
    std::vector<int> unpinned_;  // dynamic bodies with no pin
    Eigen::VectorXd rhs_, jv_;   // accelerations() off the chains' sweeps
    std::vector<char> visited_;
    std::vector<int> sequence_;
    std::vector<int> pathStart_;  // index into sequence_, plus a final end marker
    std::vector<Link> links_;     // links_[i] joins sequence_[i] and sequence_[i+1]
    // S_i^{-1} and L_i = B_{i-1}^T S_{i-1}^{-1} per pin in path order (L_i from
    // the second pin of a path on); back substitution uses L_{i+1}^T = S_i^{-1} B_i.
    std::vector<Eigen::Matrix2d> invPivot_, lower_;
    // Sparse mode.
    Eigen::SparseMatrix<double> matrix_;
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt_;
    bool analysed_ = false;
};

}  // namespace jl
