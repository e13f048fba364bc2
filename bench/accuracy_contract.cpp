// Checks the accuracy contract of the default `ratio` result: within 1e-5 of the dtau -> 0 limit
// of the paper's scheme for zeta in [0.02, 3], theta in [0, 90 deg], rdisp in [0.2, 100], i in {0, 1}.
// The limit is estimated independently of the default's step choice: Richardson extrapolation of three runs
// at 8x, 16x and 32x finer steps with a 100x tighter steady-state tolerance. Prints every point and the
// worst.
#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <vector>

namespace {

double limit_rx(const fv::Params& p, double* est) {
    const int n0 = fv::default_steps_per_period(p) * 8;
    fv::SteadyOptions o;
    o.tolerance = 1e-11;
    o.max_steps = 4e9;
    double r[3];
    for (int l = 0; l < 3; ++l) {
        o.steps_per_period = n0 << l;
        r[l] = fv::dahl_steady(p, o).rx;
    }
    const double x12 = 2 * r[1] - r[0], x23 = 2 * r[2] - r[1];
    *est = std::abs(x23 - x12);
    return x23;
}

} // namespace

int main(int argc, char** argv) {
    const bool quick = argc > 1 && std::string(argv[1]) == "--quick";
    const std::vector<double> zetas =
        quick ? std::vector<double>{0.02, 0.3, 1.0, 3.0}
              : std::vector<double>{0.02, 0.05, 0.1, 0.2, 0.5, 0.8, 1.0, 1.5, 3.0};
    const std::vector<double> thetas =
        quick ? std::vector<double>{0, 45, 90} : std::vector<double>{0, 20, 45, 70, 90};
    const std::vector<double> rdisps =
        quick ? std::vector<double>{0.2, 2, 100} : std::vector<double>{0.2, 0.5, 2, 10, 100};
    struct Row {
        fv::Params p;
        double def, lim, lim_est, claimed;
    };
    std::vector<Row> rows;
    for (double i : {0.0, 1.0})
        for (double th : thetas)
            for (double rd : rdisps)
                for (double z : zetas) rows.push_back({{z, th * fv::kPi / 180, rd, i}, 0, 0, 0, 0});
    fv::parallel_for(static_cast<int>(rows.size()), [&](int k) {
        Row& r = rows[static_cast<std::size_t>(k)];
        const auto res = fv::dahl_steady(r.p);
        r.def = res.rx;
        r.claimed = res.error_estimate;
        r.lim = limit_rx(r.p, &r.lim_est);
    });
    double worst = 0;
    int under_claimed = 0;
    std::printf("%4s %6s %7s %6s %14s %14s %10s %10s %10s\n", "i", "theta", "rdisp", "zeta", "default",
                "limit", "|diff|", "claimed", "limit_err");
    for (const Row& r : rows) {
        const double diff = std::abs(r.def - r.lim);
        worst = std::max(worst, diff);
        if (diff > r.claimed + r.lim_est) ++under_claimed;
        std::printf("%4g %6.1f %7g %6g %14.10f %14.10f %10.2e %10.2e %10.2e%s\n", r.p.i,
                    r.p.theta * 180 / fv::kPi, r.p.rdisp, r.p.zeta, r.def, r.lim, diff, r.claimed, r.lim_est,
                    diff > 1e-5 ? "  <-- over 1e-5" : "");
    }
    std::printf("points %zu, worst |default - limit| = %.3e (contract 1e-5), error estimate below the actual "
                "error at %d points\n",
                rows.size(), worst, under_claimed);
    return worst <= 1e-5 ? 0 : 1;
}
