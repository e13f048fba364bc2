// Speed and robustness of fv::steady_ratio (the Dahl model at default options: what users get) over the
// whole parameter domain, one point at a time on one thread:
//   zeta  in {0} + 9 values log-spaced over [1e-3, 100]
//   theta in {0, 30, ..., 180 deg}
//   rdisp in {1e-9, 1e-8, ..., 1e4} (one per decade)
//   i     in {0, 0.5, 1, 2, 5, 10}
// Each point: the median CPU time of its thread over `repeats` calls (3 by default; CPU time, so that other
// work on a shared machine does not count, though it still slows the caches). Tables of median / p95 / max ms
// per point by rdisp decade, by i, by theta and by zeta, overall; the failures (status not ok, or a
// non-finite r_x, r_y or error estimate); the slowest points. Then the (zeta, theta) map figure
// (fv::map_figure: 200 zeta x 91 theta) at rdisp = 1, 100, 1e4: wall time and the process's CPU time (user +
// system, all threads; on a shared machine the CPU time is the figure to compare). This prints figures; it
// asserts nothing (timings are not tests).
//   usage: fv_domain_speed [--quick] [--repeats N] [--worst K] [--map-i I] [--no-map | --map-only]
//                          [--tolerance T] [--map-threads N] [--map-rdisp R]... [--dump FILE]
//                          [--start rest|sliding] [--random N [--seed S]]
//     --quick   every other zeta, theta in {0, 60, 90, 150 deg}, every other rdisp decade plus 1e4, one call
//               per point (about 1/6 of the grid)
//     --map-threads N  threads of the map (default 0: all cores; 1 gives the one-core figure directly)
//     --map-rdisp R    the map's r_disp (repeatable; default 1, 100, 1e4)
//     --start S        the start whose state is solved for (default rest)
//     --random N       instead of the grid, N points drawn at random (fixed seed; --seed S for another):
//                      zeta = 0 for 1 in 20, else log-uniform over [1e-3, 100]; theta uniform over
//                      [0, 180 deg]; rdisp log-uniform over [1e-9, 1e4]; i uniform over [0, 10] for half of
//                      them, else one of the grid's values (the tables by i, theta and zeta are left out)
//     --dump FILE      every grid point's parameters, status, r_x, r_y, error estimate, periods and ms, one
//                      line each (to compare two builds point by point: only the timings should differ)
#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/steady_state.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

constexpr double kDeg = fv::kPi / 180;

struct Point {
    fv::Params p;
    double ms = 0; // median over the repeats
    fv::SteadyResult r;
    bool failed() const {
        return !fv::ok(r.status) || !std::isfinite(r.rx) || !std::isfinite(r.ry) ||
               !std::isfinite(r.error_estimate);
    }
};

double quantile(std::vector<double> v, double q) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    const double x = q * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(std::floor(x));
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (x - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

struct Stats {
    int n = 0, failures = 0;
    double median = 0, p95 = 0, max = 0, total = 0;
};

template <class Pred> Stats stats(const std::vector<Point>& pts, Pred&& in) {
    Stats s;
    std::vector<double> t;
    for (const Point& q : pts)
        if (in(q)) {
            t.push_back(q.ms);
            s.total += q.ms;
            if (q.failed()) ++s.failures;
        }
    s.n = static_cast<int>(t.size());
    s.median = quantile(t, 0.5);
    s.p95 = quantile(t, 0.95);
    s.max = t.empty() ? 0 : *std::max_element(t.begin(), t.end());
    return s;
}

void header(const char* key) {
    std::printf("  %-12s %6s %10s %10s %11s %11s %9s\n", key, "points", "median ms", "p95 ms", "max ms",
                "total s", "failures");
}

void row(const std::string& key, const Stats& s) {
    std::printf("  %-12s %6d %10.3f %10.3f %11.3f %11.3f %9d\n", key.c_str(), s.n, s.median, s.p95, s.max,
                s.total / 1e3, s.failures);
}

std::string num(const char* f, double v) {
    char b[64];
    std::snprintf(b, sizeof b, f, v);
    return b;
}

// CPU time of the whole process (all threads), seconds.
double process_cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// CPU time of the calling thread, seconds.
double thread_cpu_s() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

std::string describe(const Point& q) {
    char b[200];
    std::snprintf(b, sizeof b, "zeta=%-9.4g theta=%5.1f rdisp=%-7.0e i=%-4g", q.p.zeta, q.p.theta / kDeg,
                  q.p.rdisp, q.p.i);
    return b;
}

} // namespace

int main(int argc, char** argv) {
    bool quick = false, map = true, grid = true;
    int repeats = 3, worst = 15, map_threads = 0, random_points = 0;
    unsigned seed = 1;
    std::vector<double> map_rdisps;
    double map_i = 1;
    std::string dump;
    fv::SteadyOptions opt; // --tolerance: the solver's target (default 1e-8; the targets are at 1e-6)
    for (int a = 1; a < argc; ++a) {
        const std::string k = argv[a];
        if (k == "--quick")
            quick = true;
        else if (k == "--no-map")
            map = false;
        else if (k == "--map-only")
            grid = false;
        else if (k == "--repeats" && a + 1 < argc)
            repeats = std::max(1, std::atoi(argv[++a]));
        else if (k == "--worst" && a + 1 < argc)
            worst = std::max(0, std::atoi(argv[++a]));
        else if (k == "--map-i" && a + 1 < argc)
            map_i = std::atof(argv[++a]);
        else if (k == "--map-threads" && a + 1 < argc)
            map_threads = std::max(0, std::atoi(argv[++a]));
        else if (k == "--map-rdisp" && a + 1 < argc)
            map_rdisps.push_back(std::atof(argv[++a]));
        else if (k == "--tolerance" && a + 1 < argc)
            opt.ode_tolerance = std::atof(argv[++a]);
        else if (k == "--random" && a + 1 < argc)
            random_points = std::max(1, std::atoi(argv[++a]));
        else if (k == "--seed" && a + 1 < argc)
            seed = static_cast<unsigned>(std::strtoul(argv[++a], nullptr, 10));
        else if (k == "--dump" && a + 1 < argc)
            dump = argv[++a];
        else if (k == "--start" && a + 1 < argc && std::string(argv[a + 1]) == "sliding" && ++a)
            opt.start = fv::Start::sliding;
        else if (k == "--start" && a + 1 < argc && std::string(argv[a + 1]) == "rest" && ++a)
            opt.start = fv::Start::rest;
        else {
            std::fprintf(stderr,
                         "usage: %s [--quick] [--repeats N] [--worst K] [--map-i I] [--no-map | --map-only] "
                         "[--tolerance T] [--map-threads N] [--map-rdisp R]... [--dump FILE] [--start "
                         "rest|sliding] [--random N [--seed S]]\n",
                         argv[0]);
            return 2;
        }
    }
    if (quick &&
        !std::any_of(argv + 1, argv + argc, [](const char* s) { return std::string(s) == "--repeats"; }))
        repeats = 1;

    std::vector<double> zetas{0.0};
    for (int k = 0; k <= 8; ++k) zetas.push_back(std::pow(10.0, -3.0 + 5.0 * k / 8));
    std::vector<double> thetas;
    for (int d = 0; d <= 180; d += 30) thetas.push_back(d * kDeg);
    std::vector<int> decades;
    for (int e = -9; e <= 4; ++e) decades.push_back(e);
    const std::vector<double> is{0, 0.5, 1, 2, 5, 10};
    if (quick) {
        std::vector<double> z;
        for (std::size_t k = 0; k < zetas.size(); k += 2) z.push_back(zetas[k]);
        zetas = z;
        thetas = {0, 60 * kDeg, 90 * kDeg, 150 * kDeg};
        std::vector<int> d;
        for (std::size_t k = 0; k < decades.size(); k += 2) d.push_back(decades[k]);
        if (d.back() != 4) d.push_back(4);
        decades = d;
    }

    std::vector<Point> pts;
    if (random_points > 0) {
        // The grid's values are where the solver was tuned; points between them test the claims.
        std::mt19937_64 rng(seed);
        std::uniform_real_distribution<double> u01(0, 1);
        for (int n = 0; n < random_points; ++n) {
            Point q;
            q.p.zeta = u01(rng) < 0.05 ? 0 : std::pow(10.0, -3 + 5 * u01(rng));
            q.p.theta = 180 * u01(rng) * kDeg;
            q.p.rdisp = std::pow(10.0, -9 + 13 * u01(rng));
            q.p.i = u01(rng) < 0.5 ? 10 * u01(rng) : is[static_cast<std::size_t>(u01(rng) * 6) % is.size()];
            pts.push_back(q);
        }
    } else {
        for (double i : is)
            for (int e : decades)
                for (double th : thetas)
                    for (double z : zetas) {
                        Point q;
                        q.p = {z, th, std::pow(10.0, e), i};
                        pts.push_back(q);
                    }
    }
    if (grid) {
        if (random_points > 0)
            std::printf("fv::steady_ratio (Dahl, tolerance %g) at %zu random points of the domain (seed %u), "
                        "median CPU time of %d call(s) per point, one thread\n",
                        opt.ode_tolerance, pts.size(), seed, repeats);
        else
            std::printf("fv::steady_ratio (Dahl, tolerance %g) over the domain: %zu points (%zu zeta x %zu "
                        "theta x %zu "
                        "rdisp x %zu i)%s, median CPU time of %d call(s) per point, one thread\n",
                        opt.ode_tolerance, pts.size(), zetas.size(), thetas.size(), decades.size(), is.size(),
                        quick ? " [--quick]" : "", repeats);
        std::fflush(stdout);

        const auto t_start = std::chrono::steady_clock::now();
        for (Point& q : pts) {
            std::vector<double> t;
            for (int k = 0; k < repeats; ++k) {
                const double a = thread_cpu_s();
                q.r = fv::steady_ratio(fv::Model::dahl, q.p, opt);
                t.push_back(1e3 * (thread_cpu_s() - a));
            }
            q.ms = quantile(t, 0.5);
        }
        const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
        if (!dump.empty()) {
            std::FILE* f = std::fopen(dump.c_str(), "w");
            if (!f) {
                std::fprintf(stderr, "fv_domain_speed: cannot write %s\n", dump.c_str());
                return 1;
            }
            for (const Point& q : pts)
                std::fprintf(f, "%.9g %.9g %.9g %.9g %s %.12g %.12g %.3g %d %.3f\n", q.p.zeta,
                             q.p.theta / kDeg, q.p.rdisp, q.p.i, fv::status_word(q.r).c_str(), q.r.rx, q.r.ry,
                             q.r.error_estimate, q.r.periods, q.ms);
            std::fclose(f);
        }

        std::printf("\nBy rdisp decade\n");
        header("rdisp");
        for (int e : decades)
            row(num("1e%+03.0f", e),
                stats(pts, [&](const Point& q) { return std::lround(std::log10(q.p.rdisp)) == e; }));
        if (random_points == 0) {
            std::printf("\nBy i\n");
            header("i");
            for (double i : is) row(num("%g", i), stats(pts, [&](const Point& q) { return q.p.i == i; }));
            std::printf("\nBy theta\n");
            header("theta deg");
            for (double th : thetas)
                row(num("%.0f", th / kDeg), stats(pts, [&](const Point& q) { return q.p.theta == th; }));
            std::printf("\nBy zeta\n");
            header("zeta");
            for (double z : zetas)
                row(num("%.4g", z), stats(pts, [&](const Point& q) { return q.p.zeta == z; }));
        }
        std::printf("\nOverall\n");
        header("");
        const Stats all = stats(pts, [](const Point&) { return true; });
        row("all", all);
        std::printf("  wall time of the whole grid (all repeats): %.1f s\n", wall);
        // Issue #24's target: every answer (exit 0: periodic or period-k) within 2 ms.
        int answers = 0, above = 0;
        const Point* slowest = nullptr;
        for (const Point& q : pts) {
            if (q.failed()) continue;
            ++answers;
            if (q.ms > 2) ++above;
            if (!slowest || q.ms > slowest->ms) slowest = &q;
        }
        std::printf("  answers (exit 0) above 2 ms: %d of %d", above, answers);
        if (slowest)
            std::printf("; the slowest %.3f ms (%s, %s)", slowest->ms, fv::to_string(slowest->r.status),
                        describe(*slowest).c_str());
        std::printf("\n");

        // Failures by kind.
        std::map<std::string, int> kinds;
        std::vector<const Point*> failed;
        for (const Point& q : pts)
            if (q.failed()) {
                failed.push_back(&q);
                const bool finite =
                    std::isfinite(q.r.rx) && std::isfinite(q.r.ry) && std::isfinite(q.r.error_estimate);
                ++kinds[finite ? fv::to_string(q.r.status)
                               : std::string("non-finite (status ") + fv::to_string(q.r.status) + ")"];
            }
        std::printf("\nFailures (status not ok or non-finite): %zu of %zu\n", failed.size(), pts.size());
        for (const auto& [k, n] : kinds) std::printf("  %-36s %6d\n", k.c_str(), n);
        // Worst failures: non-finite values first, then by error estimate.
        const auto badness = [](const Point* q) {
            if (!std::isfinite(q->r.rx) || !std::isfinite(q->r.ry)) return 2.0;
            const double e = q->r.error_estimate;
            return std::isfinite(e) ? std::min(1.0, e) : 1.0;
        };
        std::stable_sort(failed.begin(), failed.end(),
                         [&](const Point* a, const Point* b) { return badness(a) > badness(b); });
        for (std::size_t k = 0; k < failed.size() && k < static_cast<std::size_t>(worst); ++k) {
            const Point& q = *failed[k];
            std::printf("  %s  %-18s r_x=%-14.8g est=%-10.2e %8.3f ms\n", describe(q).c_str(),
                        fv::to_string(q.r.status), q.r.rx, q.r.error_estimate, q.ms);
        }

        // Slowest points.
        std::vector<const Point*> slow;
        for (const Point& q : pts) slow.push_back(&q);
        std::sort(slow.begin(), slow.end(), [](const Point* a, const Point* b) { return a->ms > b->ms; });
        std::printf("\nSlowest points\n");
        for (std::size_t k = 0; k < slow.size() && k < static_cast<std::size_t>(worst); ++k) {
            const Point& q = *slow[k];
            std::printf("  %s  %8.3f ms  %-14s r_x=%-14.8g est=%.2e periods=%d\n", describe(q).c_str(), q.ms,
                        fv::to_string(q.r.status), q.r.rx, q.r.error_estimate, q.r.periods);
        }
    }

    // The (zeta, theta) map (fv::map_figure: 200 zeta in [0.02, 3] x 91 theta in [0, 90 deg]).
    if (map) {
        if (map_rdisps.empty()) map_rdisps = {1.0, 100.0, 1e4};
        const unsigned nth = map_threads > 0 ? static_cast<unsigned>(map_threads)
                                             : std::max(1u, std::thread::hardware_concurrency());
        std::printf("\n(zeta, theta) map, fv::compute_figure(fv::map_figure(rdisp, i = %g)), %u thread(s)\n",
                    map_i, nth);
        std::printf("  %8s %10s %10s %8s %12s %10s\n", "rdisp", "wall s", "CPU s", "cells", "non-finite",
                    "not ok");
        for (double rd : map_rdisps) {
            const double c0 = process_cpu_s();
            const auto a = std::chrono::steady_clock::now();
            const fv::FigureData fig = fv::compute_figure(fv::map_figure(rd, map_i), map_threads);
            const double t = std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
            const double cpu = process_cpu_s() - c0;
            int cells = 0, bad = 0, not_ok = 0;
            for (const auto& panel : fig.panels)
                if (panel.heatmap)
                    for (double v : panel.heatmap->values) {
                        ++cells;
                        if (!std::isfinite(v)) ++bad;
                    }
            for (const auto& table : fig.tables)
                for (const auto& row : table.ratios)
                    if (!fv::ok(row.result.status)) ++not_ok;
            std::printf("  %8g %10.3f %10.3f %8d %12d %10d\n", rd, t, cpu, cells, bad, not_ok);
            std::fflush(stdout);
        }
    }
    return 0;
}
