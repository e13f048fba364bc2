// Speed of the continuous-time steady-state solver (fv::ode_sweep_zeta) against the paper's scheme
// (fv::sweep with the automatic mode of fv::dahl_steady, which is what users get today), on the data of
// Fig. 10: rdisp in {0.5, 1, 2, 5, 20} x 200 zeta in [0.02, 3], theta = 90 deg, i = 1. Also times a
// 200 x 91 (zeta, theta) map at rdisp = 2, i = 1. Median wall time of a few runs, all cores.
//   usage: fv_solver_speed [--runs N] [--paper-runs N]
#include "fv/ode_solver.hpp"
#include "fv/sweep.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>
#include <vector>

namespace {

template <class F> double median_seconds(int runs, F&& f) {
    std::vector<double> t;
    for (int k = 0; k < runs; ++k) {
        const auto a = std::chrono::steady_clock::now();
        f();
        const auto b = std::chrono::steady_clock::now();
        t.push_back(std::chrono::duration<double>(b - a).count());
    }
    std::sort(t.begin(), t.end());
    return t[t.size() / 2];
}

struct Summary {
    double worst_err_est = 0;
    int not_converged = 0;
    long periods = 0;
};

Summary summarize(const std::vector<fv::SweepPoint>& pts) {
    Summary s;
    for (const auto& p : pts) {
        s.worst_err_est = std::max(s.worst_err_est, p.result.error_estimate);
        if (p.result.status != fv::SteadyStatus::converged) ++s.not_converged;
        s.periods += p.result.periods;
    }
    return s;
}

} // namespace

int main(int argc, char** argv) {
    int runs = 5, paper_runs = 3;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string k = argv[a];
        if (k == "--runs") runs = std::atoi(argv[a + 1]);
        if (k == "--paper-runs") paper_runs = std::atoi(argv[a + 1]);
    }
    const auto zetas = fv::linspace(0.02, 3, 200);
    const std::vector<double> rdisps{0.5, 1, 2, 5, 20};
    const std::vector<double> theta{fv::kPi / 2};
    const std::vector<double> i1{1};
    std::printf("threads: %u\n", std::thread::hardware_concurrency());

    // Fig. 10 sweep: ODE solver at its default tolerance and at a looser one, and the paper's scheme.
    std::vector<fv::SweepPoint> ode, ode_loose, paper;
    fv::OdeOptions loose;
    loose.tolerance = 1e-6;
    const double t_ode = median_seconds(runs, [&] { ode = fv::ode_sweep_zeta(zetas, theta, rdisps, i1); });
    const double t_loose =
        median_seconds(runs, [&] { ode_loose = fv::ode_sweep_zeta(zetas, theta, rdisps, i1, loose); });
    const double t_paper =
        median_seconds(paper_runs, [&] { paper = fv::sweep(fv::Model::dahl, zetas, theta, rdisps, i1); });

    double worst_diff = 0, worst_loose = 0;
    for (std::size_t k = 0; k < ode.size(); ++k) {
        worst_diff = std::max(worst_diff, std::abs(ode[k].result.rx - paper[k].result.rx));
        worst_loose = std::max(worst_loose, std::abs(ode_loose[k].result.rx - ode[k].result.rx));
    }
    const Summary so = summarize(ode), sl = summarize(ode_loose), sp = summarize(paper);
    std::printf("\nFig. 10 sweep (5 rdisp x 200 zeta, theta = 90 deg, i = 1), median of %d / %d runs\n", runs,
                paper_runs);
    std::printf("  %-34s %10s %12s %12s %8s\n", "solver", "time [s]", "max err est", "periods", "not conv");
    std::printf("  %-34s %10.4f %12.2e %12ld %8d\n", "ode (tolerance 1e-8, default)", t_ode, so.worst_err_est,
                so.periods, so.not_converged);
    std::printf("  %-34s %10.4f %12.2e %12ld %8d\n", "ode (tolerance 1e-6)", t_loose, sl.worst_err_est,
                sl.periods, sl.not_converged);
    std::printf("  %-34s %10.4f %12.2e %12ld %8d\n", "paper scheme (automatic, extrap.)", t_paper,
                sp.worst_err_est, sp.periods, sp.not_converged);
    std::printf("  speed-up paper/ode: %.1fx (default tolerance), %.1fx (tolerance 1e-6)\n", t_paper / t_ode,
                t_paper / t_loose);
    std::printf("  max |r_x(ode) - r_x(paper)| = %.2e (the paper's automatic mode promises 1e-5)\n",
                worst_diff);
    std::printf("  max |r_x(ode 1e-6) - r_x(ode 1e-8)| = %.2e\n", worst_loose);

    // (zeta, theta) map at rdisp = 2, i = 1: 200 x 91 points, theta = 0, 2, ..., 180 deg.
    std::vector<double> thetas;
    for (int k = 0; k <= 90; ++k) thetas.push_back(2.0 * k * fv::kPi / 180);
    std::vector<fv::SweepPoint> map;
    const double t_map =
        median_seconds(std::max(1, runs / 2), [&] { map = fv::ode_sweep_zeta(zetas, thetas, {2.0}, i1); });
    const Summary sm = summarize(map);
    std::printf(
        "\nMap 200 zeta x 91 theta, rdisp = 2, i = 1 (ode, default tolerance): %.3f s (target <= 10 s), "
        "max err est %.2e, not converged %d, periods %ld\n",
        t_map, sm.worst_err_est, sm.not_converged, sm.periods);
    return 0;
}
