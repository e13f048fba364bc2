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
    bool full = false;
    for (int a = 1; a < argc; ++a) {
        const std::string k = argv[a];
        if (k == "--full") full = true;
        if (k == "--runs" && a + 1 < argc) runs = std::atoi(argv[++a]);
        if (k == "--paper-runs" && a + 1 < argc) paper_runs = std::atoi(argv[++a]);
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
    fv::SteadyOptions paper_opt;
    paper_opt.scheme = fv::Scheme::paper; // the sweep's default is the ODE solver
    const double t_paper = median_seconds(
        paper_runs, [&] { paper = fv::sweep(fv::Model::dahl, zetas, theta, rdisps, i1, paper_opt); });

    double worst_diff = 0, worst_loose = 0;
    for (std::size_t k = 0; k < ode.size(); ++k) {
        worst_diff = std::max(worst_diff, std::abs(ode[k].result.rx - paper[k].result.rx));
        worst_loose = std::max(worst_loose, std::abs(ode_loose[k].result.rx - ode[k].result.rx));
    }
    const Summary so = summarize(ode), sl = summarize(ode_loose), sp = summarize(paper);
    std::printf("\nFig. 10 sweep (5 rdisp x 200 zeta, theta = 90 deg, i = 1), median of %d / %d runs\n", runs,
                paper_runs);
    std::printf("  %-34s %10s %12s %12s %8s\n", "solver", "time [s]", "max err est", "periods", "not conv");
    std::printf("  %-34s %10.4f %12.2e %12ld %8d\n", "ode (tolerance 1e-8, the default)", t_ode,
                so.worst_err_est, so.periods, so.not_converged);
    std::printf("  %-34s %10.4f %12.2e %12ld %8d\n", "ode (tolerance 1e-6)", t_loose, sl.worst_err_est,
                sl.periods, sl.not_converged);
    std::printf("  %-34s %10.4f %12.2e %12ld %8d\n", "paper scheme (automatic, extrap.)", t_paper,
                sp.worst_err_est, sp.periods, sp.not_converged);
    std::printf("  speed-up paper/ode: %.1fx (default tolerance), %.1fx (tolerance 1e-6)\n", t_paper / t_ode,
                t_paper / t_loose);
    std::printf("  max |r_x(ode) - r_x(paper)| = %.2e (the paper's automatic mode promises 1e-5)\n",
                worst_diff);
    std::printf("  max |r_x(ode 1e-6) - r_x(ode 1e-8)| = %.2e\n", worst_loose);

    // Equal accuracy: the paper's scheme run as the paper does it (one resolution, no extrapolation) needs
    // n steps per period for |r - r(dtau -> 0)| <= 1e-6. Find the smallest power of two that gets there
    // (against the ODE result at tolerance 1e-10) for a few zeta per rdisp, and time single points.
    std::printf("\nEqual accuracy (1e-6), single points, one thread; paper = fixed n, no extrapolation\n");
    std::printf("  %6s %6s %10s %12s %12s %12s %9s\n", "rdisp", "zeta", "n needed", "paper [ms]", "ode [ms]",
                "ode 1e-6[ms]", "ratio");
    std::vector<double> ratios;
    double sum_paper = 0, sum_ode = 0, sum_loose = 0; // the 15 points as one small sweep
    for (double rd : rdisps)
        for (double z : {0.1, 0.5, 2.0}) {
            const fv::Params p{z, fv::kPi / 2, rd, 1};
            fv::OdeOptions tight;
            tight.tolerance = 1e-10;
            const double exact = fv::ode_steady(p, tight).rx;
            fv::SteadyOptions fixed;
            fixed.tolerance = 1e-9;
            int n = 1024;
            double t_p = 0;
            for (; n <= (1 << 22); n *= 2) {
                fixed.steps_per_period = n;
                double rx = 0;
                t_p = median_seconds(1, [&] { rx = fv::dahl_steady(p, fixed).rx; });
                if (std::abs(rx - exact) <= 1e-6) break;
            }
            const double t_o = median_seconds(5, [&] { (void)fv::ode_steady(p); });
            const double t_l = median_seconds(5, [&] { (void)fv::ode_steady(p, loose); });
            const bool found = n <= (1 << 22);
            std::printf("  %6g %6g %10s %12.3f %12.3f %12.3f %8.0fx%s\n", rd, z,
                        found ? std::to_string(n).c_str() : "> 4194304", 1e3 * t_p, 1e3 * t_o, 1e3 * t_l,
                        t_p / t_l, found ? "" : " (lower bound)");
            ratios.push_back(t_p / t_l);
            sum_paper += t_p, sum_ode += t_o, sum_loose += t_l;
        }
    std::sort(ratios.begin(), ratios.end());
    std::printf("  ratio paper(n for 1e-6) / ode(tolerance 1e-6): min %.0fx, median %.0fx\n", ratios.front(),
                ratios[ratios.size() / 2]);
    std::printf("  all 15 points as one sweep: paper %.1f ms, ode default %.2f ms (%.0fx), ode 1e-6 %.2f ms "
                "(%.0fx)\n",
                1e3 * sum_paper, 1e3 * sum_ode, sum_paper / sum_ode, 1e3 * sum_loose, sum_paper / sum_loose);

    // The whole Fig. 10 sweep with the paper's scheme as printed at one step count that reaches 1e-6 at
    // every point (the table above needs up to 2^20): slow (about a minute), so only with --full.
    if (full) {
        fv::SteadyOptions fixed;
        fixed.scheme = fv::Scheme::paper;
        fixed.steps_per_period = 1 << 20;
        std::vector<fv::SweepPoint> slow;
        const double t_slow =
            median_seconds(1, [&] { slow = fv::sweep(fv::Model::dahl, zetas, theta, rdisps, i1, fixed); });
        double worst = 0;
        for (std::size_t k = 0; k < slow.size(); ++k)
            worst = std::max(worst, std::abs(slow[k].result.rx - ode[k].result.rx));
        std::printf(
            "\nFig. 10 sweep, paper's scheme at n = 2^20 for every point: %.1f s, max |r_x - ode| = %.2e; "
            "ratio to the default solver (%.3f s): %.0fx, to the solver at tolerance 1e-6 (%.3f s, equal "
            "accuracy): %.0fx\n",
            t_slow, worst, t_ode, t_slow / t_ode, t_loose, t_slow / t_loose);
    }

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
