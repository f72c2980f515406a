#include "bench/stability.h"

#include "jl/base/thread_clock.h"
#include "jl/engine/projection.h"
#include "jl/sim/simulation.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <random>

namespace jl::bench {

namespace {

constexpr double kAiryZero = 2.338107410459767;  // |a_1|, first zero of Ai

// A default ladder of `blocks`, hanging at rest, or with its top block
// turned half a turn from t = 0 (as the long-ladder study does), with RK4.
Scene ladderScene(int blocks, bool turned, double step) {
    Scene s;
    s.ladder = LadderSpec{};
    s.ladder->blocks = blocks;
    if (turned) s.script.push_back(halfTurn(0.0));
    s.solver.integrator = Integrator::RK4;
    s.solver.step = step;
    return s;
}

struct Block {
    double mass, inertia, diagonal, g;
};

Block defaultBlock() {
    const BlockSpec b{};
    const Scene s{};
    const double m = b.density * b.length * b.thickness * b.width;
    return {m, m * (b.length * b.length + b.thickness * b.thickness) / 12, std::hypot(b.length, b.thickness),
            std::hypot(s.gravity[0], s.gravity[1])};
}

// The largest y such that |R(i y')| <= 1 for all 0 < y' <= y, R the
// stability function of the explicit Runge-Kutta tableau (a, b).
double imaginaryLimit(const std::vector<std::vector<double>>& a, const std::vector<double>& b) {
    auto growth = [&](double y) {
        const std::complex<double> z(0, y);
        std::vector<std::complex<double>> k(b.size());
        std::complex<double> r = 1;
        for (size_t i = 0; i < b.size(); ++i) {
            k[i] = 1;
            for (size_t j = 0; j < i; ++j) k[i] += z * a[i][j] * k[j];
            r += z * b[i] * k[i];
        }
        return std::abs(r);
    };
    double lo = 0, hi = 0;
    for (double y = 1e-3; y < 10; y += 1e-3)
        if (growth(y) > 1 + 1e-13) {
            hi = y;
            break;
        }
    lo = hi - 1e-3;
    for (int i = 0; i < 60; ++i) {
        const double mid = (lo + hi) / 2;
        (growth(mid) > 1 + 1e-13 ? hi : lo) = mid;
    }
    return lo;
}

// Does a ladder run `horizon` seconds with RK4 at `step` without failing?
// cost: CPU seconds per simulated second (the build not counted); why: the
// failure reported.
bool runs(int blocks, bool turned, double step, double horizon, double& cost, std::string& why) {
    Simulation::Built built = Simulation::build(ladderScene(blocks, turned, step));
    if (!built.simulation) {
        why = built.errors.empty() ? "not built" : built.errors.front();
        return false;
    }
    const double start = threadSeconds();
    const bool ok = built.simulation->advanceTo(horizon) && built.simulation->failure().empty();
    cost = (threadSeconds() - start) / std::max(built.simulation->time(), 1e-300);
    why = built.simulation->failure();
    return ok;
}

// Bisection (geometric) for the largest step that runs, starting from a
// bracket around the prediction. pass/fail: NaN if no such step was found;
// passCost: the cost of the run at `pass`; why: the failure at `fail`.
void bisect(int blocks, bool turned, double predicted, double horizon, double ratio, double& pass, double& fail,
            double& passCost, std::string& why, int& count) {
    double lo = predicted / 2, hi = predicted * 2;
    passCost = NAN;
    std::string hiWhy;
    auto ok = [&](double h) {
        ++count;
        double cost = 0;
        std::string failure;
        const bool r = runs(blocks, turned, h, horizon, cost, failure);
        if (r)
            passCost = cost;  // a passing step always becomes the new lower end
        else if (!(h > hi))
            hiWhy = failure;  // and a failing one, not above hi, the new upper end
        std::fprintf(stderr, "    N=%-6d %-8s dt=%.4e s: %s (%.3g CPU s per simulated s)%s%s\n", blocks,
                     turned ? "turned" : "hanging", h, r ? "runs" : "fails", cost, r ? "" : " ", failure.c_str());
        return r;
    };
    bool loOk = false, hiFails = false;
    for (int i = 0; i < 4 && !(loOk = ok(lo)); ++i) {
        hi = lo;
        lo /= 2;
    }
    for (int i = 0; loOk && i < 4 && !(hiFails = !ok(hi)); ++i) {
        lo = hi;
        hi *= 2;
    }
    if (!loOk || !hiFails) {  // the last step tried on the losing side
        pass = loOk ? lo : NAN;
        fail = loOk ? NAN : hi;
        why = hiWhy;
        return;
    }
    while (hi / lo > ratio) {
        const double mid = std::sqrt(lo * hi);
        (ok(mid) ? lo : hi) = mid;
    }
    pass = lo;
    fail = hi;
    why = hiWhy;
}

// Largest (g + a_y) / g over [0, horizon] of hinge 1 (corner 0 of the held
// block, which the turn of ladderScene drives about its centre).
double turnTension(double horizon) {
    const BlockSpec b{};
    const Scene s = ladderScene(2, true, 1e-3);
    Drive drive{Pose{}};
    drive.add(DriveMove{s.script.front().at, s.script.front().duration, Vec2::Zero(), s.script.front().angle});
    const Vec2 corner(-b.thickness / 2, -b.length / 2);
    const double g = std::hypot(s.gravity[0], s.gravity[1]);
    double peak = 0;
    for (int i = 0; i <= 1000; ++i) {
        const DriveSample d = drive.at(horizon * i / 1000);
        const Vec2 r = rotate(d.pose.angle, corner);
        const double w = d.velocity.angular;
        const Vec2 a = d.acceleration.linear + d.acceleration.angular * perp(r) - w * w * r;
        peak = std::max(peak, (g + a.y()) / g);
    }
    return peak;
}

}  // namespace

// ---- omega_max from the engine ----

EngineMode engineOmega2(int blocks) {
    EngineMode out;
    const double start = threadSeconds();
    Simulation::Built built = Simulation::build(ladderScene(blocks, false, 1e-3));
    if (!built.simulation) return out;
    World w = built.simulation->world();  // a copy to perturb
    const Eigen::Index n = w.q.size();
    Eigen::VectorXd mass(n);
    for (Eigen::Index i = 0; i < n; ++i) mass[i] = w.invMassDiag[i] > 0 ? 1 / w.invMassDiag[i] : 0.0;
    const Eigen::VectorXd q0 = w.q;
    w.v.setZero();
    Dynamics dynamics;
    auto dot = [&](const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
        return (x.array() * mass.array() * y.array()).sum();
    };
    // The mass-orthogonal projection onto the pins' tangent space (the
    // engine's velocity projection, applied to a displacement).
    auto project = [&](Eigen::VectorXd& x) {
        x = (mass.array() > 0).select(x, 0.0);
        w.q = q0;
        w.v = x;
        projectVelocities(w);
        x = (mass.array() > 0).select(w.v, 0.0);
        w.v.setZero();
    };
    // y = K x = -(da/dq) x by central differences at rest (v = 0), the
    // largest displacement 1e-6 (m or rad).
    Eigen::VectorXd y;
    auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& out) {
        const double eps = 1e-6 / x.cwiseAbs().maxCoeff();
        w.v.setZero();
        w.q = q0 + eps * x;
        dynamics.evaluate(w, 0);
        out = w.a;
        w.v.setZero();
        w.q = q0 - eps * x;
        dynamics.evaluate(w, 0);
        out = (w.a - out) / (2 * eps);
        w.q = q0;
        project(out);
    };

    // Lanczos in the mass inner product (K is self-adjoint in it on the
    // tangent space), fully reorthogonalised.
    std::mt19937_64 rng(20240607);
    std::normal_distribution<double> normal;
    Eigen::VectorXd r(n);
    for (Eigen::Index i = 0; i < n; ++i) r[i] = normal(rng);
    project(r);
    std::vector<Eigen::VectorXd> basis{r / std::sqrt(dot(r, r))};
    std::vector<double> alpha, beta;
    constexpr int kMaxIterations = 400;
    Eigen::VectorXd ritz;
    double theta = 0;
    for (int k = 0; k < kMaxIterations; ++k) {
        apply(basis.back(), y);
        if (k > 0) y -= beta.back() * basis[basis.size() - 2];
        alpha.push_back(dot(y, basis.back()));
        y -= alpha.back() * basis.back();
        for (int pass = 0; pass < 2; ++pass)
            for (const Eigen::VectorXd& b : basis) y -= dot(y, b) * b;
        beta.push_back(std::sqrt(dot(y, y)));
        out.iterations = k + 1;
        const bool last = k + 1 == kMaxIterations || !(beta.back() > 0);
        if ((k + 1) % 5 == 0 || last) {
            const Eigen::Index m = Eigen::Index(alpha.size());
            Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> tri;
            Eigen::VectorXd diag = Eigen::Map<const Eigen::VectorXd>(alpha.data(), m);
            Eigen::VectorXd sub = Eigen::Map<const Eigen::VectorXd>(beta.data(), std::max<Eigen::Index>(m - 1, 0));
            tri.computeFromTridiagonal(diag, sub, Eigen::ComputeEigenvectors);
            theta = tri.eigenvalues()[m - 1];
            ritz = tri.eigenvectors().col(m - 1);
            if (last || std::abs(beta.back() * ritz[m - 1]) < 1e-9 * theta) break;
        }
        basis.push_back(y / beta.back());
    }
    // The Ritz vector and its true residual (one more application of K).
    Eigen::VectorXd vec = Eigen::VectorXd::Zero(n);
    for (Eigen::Index i = 0; i < ritz.size(); ++i) vec += ritz[i] * basis[size_t(i)];
    vec /= std::sqrt(dot(vec, vec));
    apply(vec, y);
    out.omega2 = theta;
    out.residual = std::sqrt(dot(y - theta * vec, y - theta * vec));
    out.cpu = threadSeconds() - start;
    out.q0 = q0;
    out.mode = vec;
    out.mass = mass;
    return out;
}

// ---- the linear limit, measured ----

// The hanging ladder of the engine's equilibrium, started with velocity
// s*y along its fastest mode y (s: 1e-4 m/s or rad/s at most), run for
// `horizon` with RK4 at `step`: the mode's amplitude sqrt(omega^2 a^2 + b^2)
// (a, b: the mass-metric components of displacement and velocity along y)
// over its start. RK4 multiplies it by |R(i omega dt)| every step. Infinite
// if the run failed.
double modeGrowth(int blocks, const EngineMode& m, double step, double horizon) {
    Scene scene = ladderScene(blocks, false, step);
    Simulation::Built rest = Simulation::build(scene);
    if (!rest.simulation || m.mode.size() == 0) return INFINITY;
    const World& w0 = rest.simulation->world();
    const double s = 1e-4 / m.mode.cwiseAbs().maxCoeff();
    scene.ladder->initial.kind = InitialState::Kind::Poses;
    for (int i = 0; i < blocks; ++i) {
        const PartId part = rest.simulation->blockPart(i);
        const Pose pose = w0.partPose(part);
        const Eigen::Vector3d v = s * m.mode.segment<3>(3 * w0.part(part).body);
        scene.ladder->initial.poses.push_back(
            {i, {pose.position.x(), pose.position.y()}, pose.angle, {v[0], v[1]}, v[2]});
    }
    Simulation::Built built = Simulation::build(scene);
    if (!built.simulation || !built.simulation->advanceTo(horizon) || !built.simulation->failure().empty())
        return INFINITY;
    const World& w = built.simulation->world();
    if (w.q.size() != m.q0.size()) return INFINITY;
    const double a = (m.mass.array() * (w.q - m.q0).array() * m.mode.array()).sum();
    const double b = (m.mass.array() * w.v.array() * m.mode.array()).sum();
    return std::sqrt(m.omega2 * a * a + b * b) / s;
}

// ---- omega_max from the reduced model ----

double referenceOmega2(int blocks) {
    const Block b = defaultBlock();
    const int n = blocks - 1;  // dynamic rods; hinge 1 (on the held block) is fixed
    // Unknowns: the sideways positions of hinges 2 .. n+1 (the last is the
    // free bottom end). Link j (1..n) joins hinges j and j+1; its centre is
    // their mean, its angle their difference over l, and it carries the
    // tension T_j = (n - j + 1/2) m g of the blocks below its centre.
    std::vector<double> mDiag(size_t(n), 0), mOff(size_t(n), 0), kDiag(size_t(n), 0), kOff(size_t(n), 0);
    const double l = b.diagonal, ml = b.mass / 4, il = b.inertia / (l * l);
    for (int j = 1; j <= n; ++j) {
        const double tension = (n - j + 0.5) * b.mass * b.g;
        const int upper = j - 2, lower = j - 1;  // unknown indices of hinges j, j+1 (-1: fixed)
        if (upper >= 0) {
            mDiag[size_t(upper)] += ml + il;
            kDiag[size_t(upper)] += tension / l;
            mOff[size_t(upper)] += ml - il;
            kOff[size_t(upper)] -= tension / l;
        }
        mDiag[size_t(lower)] += ml + il;
        kDiag[size_t(lower)] += tension / l;
    }
    // How many eigenvalues of K x = lambda M x lie below lambda (Sylvester's
    // inertia of K - lambda M from its LDL^T pivots).
    auto below = [&](double lambda) {
        int negative = 0;
        double d = 1;
        for (int i = 0; i < n; ++i) {
            const double off = i > 0 ? kOff[size_t(i) - 1] - lambda * mOff[size_t(i) - 1] : 0.0;
            d = kDiag[size_t(i)] - lambda * mDiag[size_t(i)] - (i > 0 ? off * off / d : 0.0);
            if (d == 0) d = -1e-300;
            if (d < 0) ++negative;
        }
        return negative;
    };
    // Upper bound: the most loaded link alone (each link's pencil bounds
    // the assembled one), doubled for safety.
    double lo = 0, hi = 2 * 12 * (n + 0.5) * b.g / l;
    while (below(hi) < n) hi *= 2;
    while (hi - lo > 1e-15 * hi) {
        const double mid = (lo + hi) / 2;
        (below(mid) < n ? lo : hi) = mid;
    }
    return (lo + hi) / 2;
}

// ---- the study ----

StabilityStudy stabilityStudy(const BenchPlan& plan) {
    StabilityStudy study;
    study.imaginaryRk4 = imaginaryLimit({{}, {0.5}, {0, 0.5}, {0, 0, 1}}, {1.0 / 6, 1.0 / 3, 1.0 / 3, 1.0 / 6});
    study.imaginaryDopri = imaginaryLimit({{},
                                           {1.0 / 5},
                                           {3.0 / 40, 9.0 / 40},
                                           {44.0 / 45, -56.0 / 15, 32.0 / 9},
                                           {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
                                           {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
                                           {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84}},
                                          {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0});
    std::fprintf(stderr, "  imaginary-axis limits: rk4 %.6f (2 sqrt 2 = %.6f), dormand_prince45 %.6f\n",
                 study.imaginaryRk4, 2 * std::sqrt(2.0), study.imaginaryDopri);

    // Known answers: a 2-block ladder is one physical pendulum (docs/model.md
    // section 14.4: omega^2 = m g r / I_p, r = l/2, I_p = m l^2 / 3); a 3-block
    // ladder is the double pendulum of two uniform rods of length l,
    // omega^2 = (3 +- 6/sqrt 7) g / l.
    const Block b = defaultBlock();
    const double r = b.diagonal / 2;
    study.checks.push_back({"2 blocks: physical pendulum m g r / I_p", engineOmega2(2).omega2, referenceOmega2(2),
                            b.mass * b.g * r / (b.inertia + b.mass * r * r)});
    study.checks.push_back({"3 blocks: double rod pendulum (3 + 6/sqrt 7) g / l", engineOmega2(3).omega2,
                            referenceOmega2(3), (3 + 6 / std::sqrt(7.0)) * b.g / b.diagonal});
    for (const StabilityCheck& c : study.checks)
        std::fprintf(stderr, "  check %-52s engine %.12g  reference %.12g  exact %.12g\n", c.what.c_str(), c.engine,
                     c.reference, c.exact);

    const std::vector<int> sizes =
        plan.quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 1000, 10000};
    for (int blocks : sizes) {
        StabilityRow row;
        row.blocks = blocks;
        row.engine = engineOmega2(blocks);
        row.referenceOmega2 = referenceOmega2(blocks);
        const double n = blocks - 1;
        row.handUpper = std::sqrt(12 * (n - 0.5) * b.g / b.diagonal);
        row.handAiry = std::sqrt(12 * b.g / b.diagonal * std::max(0.0, n - kAiryZero * std::cbrt(0.75 * n)));
        row.omegaMax = std::sqrt(row.engine.omega2);
        row.rk4Limit = study.imaginaryRk4 / row.omegaMax;
        row.symplecticLimit = 2 / row.omegaMax;
        row.dopriLimit = study.imaginaryDopri / row.omegaMax;
        std::fprintf(stderr,
                     "  N=%-6d omega_max %.6g rad/s (engine, %d Lanczos steps, residual %.2e, %.2f s; reference %.6g; "
                     "hand %.6g / Airy %.6g) -> RK4 dt < %.4e s\n",
                     blocks, row.omegaMax, row.engine.iterations, row.engine.residual, row.engine.cpu,
                     std::sqrt(row.referenceOmega2), row.handUpper, row.handAiry, row.rk4Limit);
        // Each run long enough for a growing mode to show: at least 0.1 s
        // (the benchmark's horizon) and at least 100 steps at the limit.
        row.horizon = std::max(0.1, 100 * row.rk4Limit);
        const double start = threadSeconds();
        const double ratio = plan.quick ? 1.02 : 1.005;
        row.handTension = turnTension(row.horizon);
        {
            double lo = 0.9 * row.rk4Limit, hi = 1.1 * row.rk4Limit;
            auto stable = [&](double h) {
                const double growth = modeGrowth(blocks, row.engine, h, row.horizon);
                std::fprintf(stderr, "    N=%-6d seeded   dt=%.5e s: fastest mode x%.4g\n", blocks, h, growth);
                ++row.runs;
                return growth <= 1;
            };
            if (stable(lo) && !stable(hi)) {
                while (hi / lo > 1.001) {
                    const double mid = std::sqrt(lo * hi);
                    (stable(mid) ? lo : hi) = mid;
                }
                row.seededPass = lo;
                row.seededFail = hi;
            } else {
                row.seededPass = row.seededFail = NAN;
            }
        }
        bisect(blocks, false, row.rk4Limit, row.horizon, ratio, row.hangingPass, row.hangingFail, row.hangingCost,
               row.hangingWhy, row.runs);
        bisect(blocks, true, row.rk4Limit, row.horizon, ratio, row.turnedPass, row.turnedFail, row.turnedCost,
               row.turnedWhy, row.runs);
        row.measureCpu = threadSeconds() - start;
        std::fprintf(stderr,
                     "  N=%-6d measured RK4 limit over %.3g s: seeded mode %.5e..%.5e s, hanging %.4e..%.4e s, "
                     "turned %.4e..%.4e s "
                     "(%.1f s)\n",
                     blocks, row.horizon, row.seededPass, row.seededFail, row.hangingPass, row.hangingFail,
                     row.turnedPass, row.turnedFail, row.measureCpu);
        // The adaptive method (its default tolerance) on the turned-over
        // ladder; after every step, the largest pin force (a copy of the
        // world evaluated), over its value at rest.
        {
            Scene scene = ladderScene(blocks, true, row.rk4Limit);
            scene.solver.integrator = Integrator::DormandPrince45;
            Simulation::Built built = Simulation::build(scene);
            Simulation& sim = *built.simulation;
            Dynamics dynamics;
            auto largest = [&] {
                World w = sim.world();
                dynamics.evaluate(w, sim.time());
                const Eigen::VectorXd& f = dynamics.pinForces();
                double top = 0;
                for (Eigen::Index i = 0; i + 1 < f.size(); i += 2) top = std::max(top, std::hypot(f[i], f[i + 1]));
                return top;
            };
            const double rest = largest();
            double peak = rest, cpu = 0;
            while (sim.time() < row.horizon) {
                const double t0 = threadSeconds();
                const bool ok = sim.stepOnce();
                cpu += threadSeconds() - t0;
                if (!ok) break;
                if (const double now = largest(); now > peak) {
                    peak = now;
                    row.peakTime = sim.time();
                }
            }
            row.peakTension = peak / rest;
            row.turnedPeakLimit = row.rk4Limit / std::sqrt(row.peakTension);
            const Frame f = sim.frame();
            row.dopriSteps = f.solver.steps;
            row.dopriRejected = f.solver.rejected;
            row.dopriMeanStep = f.time / double(std::max<long long>(f.solver.steps, 1));
            row.dopriCost = cpu / std::max(f.time, 1e-300);
            row.dopriFailure = f.failure;
            std::fprintf(
                stderr,
                "  N=%-6d dormand_prince45 tol %.0e: %lld steps (mean %.4e s), %lld rejected, %.3g CPU s "
                "per simulated s%s%s; tension x%.3f from the hand, x%.3f at t = %.4f s: RK4 limit there %.4e s\n",
                blocks, scene.solver.tolerance, row.dopriSteps, row.dopriMeanStep, row.dopriRejected, row.dopriCost,
                f.failure.empty() ? "" : "; ", f.failure.c_str(), row.handTension, row.peakTension, row.peakTime,
                row.turnedPeakLimit);
        }
        study.rows.push_back(row);
    }
    return study;
}

}  // namespace jl::bench
