// jladder bench: measures cost per block-step against chain length and
// integrator on the falling chain, and writes the table into docs/.
#include "app/jladder/commands.h"
#include "app/jladder/options.h"
#include "core/dynamics.h"
#include "core/energy.h"
#include "core/falling_chain.h"
#include "core/motion.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace jl::cli {

namespace {

struct Integ {
    Integrator kind;
    const char* name;
};
constexpr Integ kIntegrators[] = {{Integrator::ExplicitEuler, "explicit_euler"},
                                  {Integrator::SymplecticEuler, "symplectic_euler"},
                                  {Integrator::RK4, "rk4"},
                                  {Integrator::DormandPrince45, "dormand_prince45"}};

struct ScalingRow {
    std::string integrator;
    int blocks = 0;
    long long steps = 0;
    double simulated = 0, wall = 0;
    double nsPerBlockStep() const { return 1e9 * wall / (double(blocks) * double(steps)); }
    double realTimeFactor() const { return simulated / wall; }
};

// Falling chain of n blocks, dt = 1 ms (the adaptive method: tolerance 1e-6,
// counting its accepted steps); as many steps as fit a work budget so that
// 100,000 blocks stay affordable, at least 20.
ScalingRow scaling(const Integ& in, int n, double blockSteps) {
    World w;
    buildFallingChain(w, n);
    Dynamics d;
    Stepper s(in.kind, 1e-6);
    Ledger ledger;
    const double h = 1e-3;
    const long long steps = std::clamp<long long>((long long)(blockSteps / n), 20, 500);
    ScalingRow r{in.name, n, 0, 0, 0};
    double t = 0;
    const auto start = std::chrono::steady_clock::now();
    for (long long i = 0; i < steps; ++i) {
        const MotionStep m = advanceAndProject(w, d, s, t, h, ledger, 1e-10);
        if (!m.ok()) break;
        t += m.step.taken;
        ++r.steps;
    }
    r.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    r.simulated = t;
    return r;
}

std::string fixed(double x, int digits) {
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(digits);
    s << x;
    return s.str();
}

}  // namespace

int bench(const std::vector<std::string>& args) {
    Options o = parse(args, {"--out"}, {"--quick", "--help"});
    if (o.has("--help")) {
        std::fputs("usage: jladder bench [--quick] [--out DIR]\n"
                   "Measures the engine on the falling chain (N boxes pinned end to end) for\n"
                   "N = 10 .. 100,000 and every integrator, at dt = 1 ms, and writes\n"
                   "DIR/scaling.csv and DIR/scaling.md (default DIR: docs/bench).\n"
                   "--quick: N up to 1,000 and fewer steps, for CI.\n",
                   stdout);
        return 0;
    }
    if (!o.error.empty()) {
        std::fprintf(stderr, "jladder bench: %s\n", o.error.c_str());
        return 2;
    }
    const bool quick = o.has("--quick");
    const std::filesystem::path out = o.get("--out").value_or("docs/bench");
    std::error_code ec;
    std::filesystem::create_directories(out, ec);
    if (ec) {
        std::fprintf(stderr, "jladder bench: cannot create %s: %s\n", out.c_str(), ec.message().c_str());
        return 1;
    }
    const std::vector<int> sizes = quick ? std::vector<int>{10, 100, 1000} : std::vector<int>{10, 100, 1000, 10000, 100000};
    const double budget = quick ? 2e5 : 5e6;
    std::vector<ScalingRow> rows;
    for (const Integ& in : kIntegrators)
        for (int n : sizes) {
            rows.push_back(scaling(in, n, budget));
            const ScalingRow& r = rows.back();
            std::fprintf(stderr, "%-17s N=%-7d %5lld steps  %8.1f ns/block-step  %7.2fx real time\n", r.integrator.c_str(),
                         r.blocks, r.steps, r.nsPerBlockStep(), r.realTimeFactor());
        }
    std::ofstream csv(out / "scaling.csv");
    csv << "integrator,blocks,steps,simulated_s,wall_s,ns_per_block_step,real_time_factor\n";
    for (const ScalingRow& r : rows)
        csv << r.integrator << ',' << r.blocks << ',' << r.steps << ',' << r.simulated << ',' << r.wall << ','
            << r.nsPerBlockStep() << ',' << r.realTimeFactor() << '\n';
    std::ofstream md(out / "scaling.md");
    md << "| integrator | blocks | steps | ns per block-step | real-time factor | flatness (max/min ns) |\n"
          "|---|---:|---:|---:|---:|---:|\n";
    for (const Integ& in : kIntegrators) {
        double lo = 1e300, hi = 0;
        for (const ScalingRow& r : rows)
            if (r.integrator == in.name) {
                lo = std::min(lo, r.nsPerBlockStep());
                hi = std::max(hi, r.nsPerBlockStep());
            }
        for (const ScalingRow& r : rows)
            if (r.integrator == in.name)
                md << "| " << r.integrator << " | " << r.blocks << " | " << r.steps << " | " << fixed(r.nsPerBlockStep(), 1)
                   << " | " << fixed(r.realTimeFactor(), 2) << " | " << (r.blocks == sizes.back() ? fixed(hi / lo, 2) : "")
                   << " |\n";
    }
    std::printf("{\"out\":%s,\"rows\":%zu}\n", jsonString(out.string()).c_str(), rows.size());
    return csv && md ? 0 : 1;
}

}  // namespace jl::cli
