// Command-line front end of the brute-force steady-state reference (tests/reference/brute_force.hpp).
//
//   g++ -O2 -std=c++17 -I tests/reference tests/tools/brute_force_ref.cpp tests/reference/brute_force.cpp
//       -o brute_force_ref
//
//   brute_force_ref [options] ZETA THETA_DEG RDISP I            one point
//   brute_force_ref [options] --point ZETA,THETA,RDISP,I[,START[,MAX_PERIODS]]   points (repeatable; an
//                                                               empty START means --start)
//   brute_force_ref [options] --file FILE                       lines "ZETA THETA RDISP I [rest|sliding]"
//   brute_force_ref [options] --random COUNT --seed SEED        random points (ranges below)
//   brute_force_ref --self-test                                 closed forms and symmetry; exit 1 on failure
// The sources can be combined; points are run in the order given (--point/positional, --file, --random).
// Options:
//   --start rest|sliding|both   (default both; a file line may name its own start)
//   --max-periods N             (default 20000)
//   --steps N                   coarse steps per period, at least (default: automatic, see brute_force.hpp)
//   --sigma S                   stiffness budget at the coarse resolution (default 0.1)
//   --tol T                     periodicity tolerance on |l_n - l_{n-k}| (default 1e-11)
//   --max-steps S               RK4 steps per run before giving up ("capped"); default 0 = no limit
//   --no-refine                 one resolution only (no error estimate)
//   --output FILE               write the CSV there (default stdout)
// Random points: zeta = 0.01 * 300^U (log-uniform in [0.01, 3]), theta = 180 U, rdisp = 0.05 * 2000^U
// (log-uniform in [0.05, 100]), i uniform in {0, 0.5, 1, 2, 5, 10}; U from std::mt19937_64(SEED) as
// (x >> 11) * 2^-53, drawn in that order per point; zeta and rdisp rounded to 4 significant digits, theta
// to 0.01 degree.
// Output (CSV, '#' comment lines first): one row per point and start; the columns are listed in the header.
// Timing goes to stderr ("# time ..."), so the CSV is reproducible.
#include "brute_force.hpp"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

using fv::ref::brute_force;
using fv::ref::BruteForceOptions;
using fv::ref::BruteForceResult;
using fv::ref::BruteStart;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;

struct Point {
    double zeta, theta, rdisp, i;
    int start;           // 0 rest, 1 sliding, 2 both
    int max_periods = 0; // 0: the --max-periods value
};

[[noreturn]] void usage(const char* msg) {
    std::fprintf(stderr,
                 "brute_force_ref: %s\n(see the comment at the top of tests/tools/brute_force_ref.cpp)\n",
                 msg);
    std::exit(2);
}

double parse_double(const std::string& s, const char* what) {
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || *end != '\0' || !std::isfinite(v))
        usage((std::string("bad number for ") + what).c_str());
    return v;
}

int parse_start(const std::string& s) {
    if (s == "rest") return 0;
    if (s == "sliding") return 1;
    if (s == "both") return 2;
    usage("start must be rest, sliding or both");
}

// Rounds x > 0 to `digits` significant decimal digits (the nearest double to that decimal).
double round_sig(double x, int digits) {
    const int e = static_cast<int>(std::floor(std::log10(x)));
    const int k = digits - 1 - e;
    if (k >= 0) {
        const double scale = std::pow(10.0, k);
        return std::round(x * scale) / scale;
    }
    const double scale = std::pow(10.0, -k);
    return std::round(x / scale) * scale;
}

std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

std::string row(const Point& p, const char* start, const BruteForceResult& r) {
    std::ostringstream o;
    o << fmt("%.10g", p.zeta) << ',' << fmt("%.10g", p.theta) << ',' << fmt("%.10g", p.rdisp) << ','
      << fmt("%.10g", p.i) << ',' << start << ',' << r.status << ',' << r.k << ',' << r.periods << ','
      << fmt("%.15g", r.rx) << ',' << fmt("%.15g", r.ry) << ',' << fmt("%.2e", r.rx_err) << ','
      << fmt("%.15g", r.lx) << ',' << fmt("%.15g", r.ly) << ',' << fmt("%.2e", r.ry_err) << ','
      << fmt("%.6g", r.fine.contraction) << ',' << r.fine.steps_per_period << ',' << fmt("%.4g", r.fine.steps)
      << ',' << '"' << r.note << '"';
    return o.str();
}

const char* kColumns = "zeta,theta_deg,rdisp,i,start,status,k,periods,rx,ry,rx_err_estimate,l_end_x,l_end_y,"
                       "ry_err_estimate,contraction_per_period,steps_per_period_fine,rk4_steps_fine,note";

// ------------------------------------------------------------------------------------------------------------
// Self-test.
//
// (a) theta = 0, i = 0: 1-D stick-slip, u = F/F_c in [-1, 1], u' = r P' while |u| < 1, u = +-1 held while P'
// pushes outwards. P = zeta tau + sin tau, P' = zeta + cos tau. For zeta >= 1, P' >= 0: u -> 1, r_x = 1.
// For 0 < zeta < 1: P' < 0 exactly on (t1, t2) = (pi - a, pi + a), a = acos zeta; back travel
// B = P(t1) - P(t2) = 2 (sqrt(1 - zeta^2) - zeta a), forward travel A = 2 pi zeta + B > B. In the steady
// state u(t1) = 1 (the forward phase always ends slipping forward: it travels r A > r B, and > 2 if r B >=
// 2).
//   r B >= 2: back: u = 1 + r (P - P(t1)) until it reaches -1 at ta (P(ta) = P(t1) - 2/r), then -1 to t2;
//             forward: u = -1 + r (P - P(t2)) until +1 at tb (P(tb) = P(t2) + 2/r), then 1 to t1 + 2 pi.
//   r B < 2:  back: u = 1 + r (P - P(t1)) on all of [t1, t2] (ends at 1 - r B);
//             forward: u = 1 - r B + r (P - P(t2)) until +1 at tb (P(tb) = P(t2) + B), then 1.
// r_x = (1/2 pi) times the integral over [t1, t1 + 2 pi], with int P = zeta tau^2 / 2 - cos tau; ta and tb
// by bisection on the monotone P. r_y = 0.
double P1(double zeta, double t) {
    return zeta * t + std::sin(t);
}
double intP(double zeta, double a, double b) {
    return zeta * (b * b - a * a) / 2 - (std::cos(b) - std::cos(a));
}
// t in [lo, hi] with P(t) = target, P monotone (increasing if up) on [lo, hi].
double solveP(double zeta, double lo, double hi, double target, bool up) {
    for (int it = 0; it < 200; ++it) {
        const double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi) break;
        const bool below = P1(zeta, m) < target;
        if (below == up)
            lo = m;
        else
            hi = m;
    }
    return 0.5 * (lo + hi);
}
double exact_theta0_i0(double zeta, double r) {
    if (zeta >= 1) return 1.0;
    const double a = std::acos(zeta);
    const double t1 = kPi - a, t2 = kPi + a, t3 = t1 + kTwoPi;
    const double B = P1(zeta, t1) - P1(zeta, t2);
    double I = 0;
    if (r * B >= 2) {
        const double ta = solveP(zeta, t1, t2, P1(zeta, t1) - 2 / r, false);
        const double tb = solveP(zeta, t2, t3, P1(zeta, t2) + 2 / r, true);
        I += (ta - t1) * (1 - r * P1(zeta, t1)) + r * intP(zeta, t1, ta);
        I += -(t2 - ta);
        I += (tb - t2) * (-1 - r * P1(zeta, t2)) + r * intP(zeta, t2, tb);
        I += t3 - tb;
    } else {
        const double tb = solveP(zeta, t2, t3, P1(zeta, t2) + B, true);
        I += (t2 - t1) * (1 - r * P1(zeta, t1)) + r * intP(zeta, t1, t2);
        I += (tb - t2) * (1 - r * B - r * P1(zeta, t2)) + r * intP(zeta, t2, tb);
        I += t3 - tb;
    }
    return I / kTwoPi;
}

int self_test(const BruteForceOptions& opt) {
    int failures = 0;
    std::printf("# self-test (a): theta = 0, i = 0 against the exact 1-D stick-slip r_x\n");
    const double pts_a[][2] = {{0.1, 0.5}, {0.3, 2.0}, {0.05, 5.0}, {0.5, 10.0},
                               {0.8, 1.0}, {0.2, 0.3}, {1.5, 2.0}};
    for (const auto& p : pts_a) {
        const double ex = exact_theta0_i0(p[0], p[1]);
        for (int s = 0; s < 2; ++s) {
            const BruteForceResult r =
                brute_force(p[0], 0.0, p[1], 0.0, s ? BruteStart::sliding : BruteStart::rest, opt);
            const double err = std::fabs(r.rx - ex);
            const bool ok = r.status.rfind("period_", 0) == 0 && err <= std::max(1e-10, 10 * r.rx_err) &&
                            std::fabs(r.ry) <= 1e-14;
            failures += !ok;
            std::printf("%s zeta=%g rdisp=%g %s: %s rx=%.15g exact=%.15g |diff|=%.2e est=%.2e ry=%.1e\n",
                        ok ? "ok  " : "FAIL", p[0], p[1], s ? "sliding" : "rest", r.status.c_str(), r.rx, ex,
                        err, r.rx_err, r.ry);
        }
    }
    // (b) theta -> 180 - theta: P(tau + pi; theta) = mirror_y(P(tau; 180 - theta)) + const, and the law is
    // isotropic and translation invariant, so the steady states are mirror images shifted by half a period:
    // r_x equal, r_y opposite (for theta = 90: r_y = 0). The starts are not mapped onto each other, so this
    // holds where the steady state is unique; the agreement is to the discretisation error of both runs.
    std::printf("# self-test (b): theta -> 180 - theta (r_x equal, r_y opposite)\n");
    const double pts_b[][4] = {{0.3, 30, 2, 1}, {0.5, 60, 1, 0},   {0.2, 45, 5, 0.5}, {0.4, 120, 0.5, 2},
                               {0.3, 90, 2, 1}, {0.15, 20, 3, 10}, {0.6, 75, 0.2, 0}};
    for (const auto& p : pts_b) {
        const BruteForceResult a = brute_force(p[0], p[1], p[2], p[3], BruteStart::rest, opt);
        const BruteForceResult b = brute_force(p[0], 180.0 - p[1], p[2], p[3], BruteStart::rest, opt);
        const double tol = std::max(1e-10, 10 * (a.rx_err + b.rx_err + a.ry_err + b.ry_err));
        const bool ok = a.status.rfind("period_", 0) == 0 && b.status.rfind("period_", 0) == 0 &&
                        std::fabs(a.rx - b.rx) <= tol && std::fabs(a.ry + b.ry) <= tol;
        failures += !ok;
        std::printf("%s zeta=%g theta=%g/%g rdisp=%g i=%g: %s/%s rx=%.15g/%.15g ry=%.15g/%.15g tol=%.1e\n",
                    ok ? "ok  " : "FAIL", p[0], p[1], 180.0 - p[1], p[2], p[3], a.status.c_str(),
                    b.status.c_str(), a.rx, b.rx, a.ry, b.ry, tol);
    }
    std::printf("# self-test: %d failure(s)\n", failures);
    return failures ? 1 : 0;
}

} // namespace

int main(int argc, char** argv) {
    BruteForceOptions opt;
    std::vector<Point> points;
    int start = 2;
    std::string file, output;
    int random_count = 0;
    bool have_seed = false;
    std::uint64_t seed = 0;
    bool selftest = false;
    std::vector<std::string> positional;
    std::vector<std::string> point_args;

    std::string command = "brute_force_ref";
    for (int a = 1; a < argc; ++a) command += std::string(" ") + argv[a];

    for (int a = 1; a < argc; ++a) {
        const std::string arg = argv[a];
        auto next = [&]() -> std::string {
            if (a + 1 >= argc) usage(("missing value after " + arg).c_str());
            return argv[++a];
        };
        if (arg == "--start")
            start = parse_start(next());
        else if (arg == "--max-periods")
            opt.max_periods = static_cast<int>(parse_double(next(), "--max-periods"));
        else if (arg == "--steps")
            opt.steps_per_period = static_cast<int>(parse_double(next(), "--steps"));
        else if (arg == "--sigma")
            opt.sigma = parse_double(next(), "--sigma");
        else if (arg == "--tol")
            opt.tol = parse_double(next(), "--tol");
        else if (arg == "--max-steps")
            opt.max_steps = parse_double(next(), "--max-steps");
        else if (arg == "--no-refine")
            opt.refine = false;
        else if (arg == "--output")
            output = next();
        else if (arg == "--file")
            file = next();
        else if (arg == "--random")
            random_count = static_cast<int>(parse_double(next(), "--random"));
        else if (arg == "--seed") {
            seed = static_cast<std::uint64_t>(parse_double(next(), "--seed"));
            have_seed = true;
        } else if (arg == "--point")
            point_args.push_back(next());
        else if (arg == "--self-test")
            selftest = true;
        else if (arg.size() > 1 && arg[0] == '-' && !(arg[1] >= '0' && arg[1] <= '9') && arg[1] != '.')
            usage(("unknown option " + arg).c_str());
        else
            positional.push_back(arg);
    }
    if (selftest) return self_test(opt);
    if (!positional.empty()) {
        if (positional.size() != 4) usage("a positional point is ZETA THETA RDISP I");
        points.push_back({parse_double(positional[0], "zeta"), parse_double(positional[1], "theta"),
                          parse_double(positional[2], "rdisp"), parse_double(positional[3], "i"), start});
    }
    for (const std::string& s : point_args) {
        std::vector<std::string> f;
        std::stringstream ss(s);
        std::string item;
        while (std::getline(ss, item, ',')) f.push_back(item);
        if (f.size() < 4 || f.size() > 6) usage("--point wants ZETA,THETA,RDISP,I[,START[,MAX_PERIODS]]");
        Point p{parse_double(f[0], "zeta"), parse_double(f[1], "theta"), parse_double(f[2], "rdisp"),
                parse_double(f[3], "i"), f.size() >= 5 && !f[4].empty() ? parse_start(f[4]) : start};
        if (f.size() == 6) p.max_periods = static_cast<int>(parse_double(f[5], "max periods"));
        points.push_back(p);
    }
    if (!file.empty()) {
        std::ifstream in(file);
        if (!in) usage(("cannot read " + file).c_str());
        std::string line;
        while (std::getline(in, line)) {
            const auto hash = line.find('#');
            if (hash != std::string::npos) line.resize(hash);
            std::istringstream ls(line);
            std::vector<std::string> f;
            std::string w;
            while (ls >> w) f.push_back(w);
            if (f.empty()) continue;
            if (f.size() != 4 && f.size() != 5) usage(("bad line in " + file + ": " + line).c_str());
            points.push_back({parse_double(f[0], "zeta"), parse_double(f[1], "theta"),
                              parse_double(f[2], "rdisp"), parse_double(f[3], "i"),
                              f.size() == 5 ? parse_start(f[4]) : start});
        }
    }
    if (random_count > 0) {
        if (!have_seed) usage("--random needs --seed");
        std::mt19937_64 gen(seed);
        auto U = [&]() { return static_cast<double>(gen() >> 11) * 0x1p-53; };
        const double exps[] = {0, 0.5, 1, 2, 5, 10};
        for (int n = 0; n < random_count; ++n) {
            const double z = round_sig(0.01 * std::pow(300.0, U()), 4);
            const double th = std::round(180.0 * U() * 100.0) / 100.0;
            const double rd = round_sig(0.05 * std::pow(2000.0, U()), 4);
            const int ki = std::min(5, static_cast<int>(6.0 * U()));
            points.push_back({z, th, rd, exps[ki], start});
        }
    }
    if (points.empty()) usage("no points");

    std::FILE* out = stdout;
    if (!output.empty()) {
        out = std::fopen(output.c_str(), "w");
        if (!out) usage(("cannot write " + output).c_str());
    }
    std::fprintf(out, "# produced by: %s\n", command.c_str());
    std::fprintf(
        out, "# brute-force RK4 reference, tests/reference/brute_force.hpp (model and numerics there); "
             "values from the fine run (2N steps per period); rx_err_estimate, ry_err_estimate = "
             "|fine - coarse| + geometric tail (period_k, unsettled), batch-means standard error "
             "(not_periodic, capped); theta in degrees; l_end = force at the last section tau = 2 pi n\n");
    std::fprintf(out, "# build: g++ -O2 -std=c++17 -I tests/reference tests/tools/brute_force_ref.cpp "
                      "tests/reference/brute_force.cpp -o brute_force_ref\n");
    if (random_count > 0)
        std::fprintf(
            out,
            "# random points: %d from seed %llu: zeta = 0.01*300^U, theta = 180 U, rdisp = 0.05*2000^U, "
            "i = {0,0.5,1,2,5,10}[floor(6U)], U = (mt19937_64() >> 11) * 2^-53 in that order; zeta, "
            "rdisp to 4 significant digits, theta to 0.01\n",
            random_count, static_cast<unsigned long long>(seed));
    std::fprintf(out, "# options: max_periods=%d tol=%g sigma=%g max_steps=%g steps_min=%d\n",
                 opt.max_periods, opt.tol, opt.sigma, opt.max_steps, opt.steps_per_period);
    std::fprintf(out, "%s\n", kColumns);
    std::fflush(out);
    std::vector<std::string> capped;
    for (const Point& p : points) {
        for (int s = 0; s < 2; ++s) {
            if (p.start != 2 && p.start != s) continue;
            const auto t0 = std::chrono::steady_clock::now();
            BruteForceResult r;
            BruteForceOptions po = opt;
            if (p.max_periods > 0) po.max_periods = p.max_periods;
            try {
                r = brute_force(p.zeta, p.theta, p.rdisp, p.i, s ? BruteStart::sliding : BruteStart::rest,
                                po);
            } catch (const std::exception& e) {
                r.status = "error";
                r.note = e.what();
                r.rx = r.ry = NAN;
            }
            const double sec = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
            const std::string line = row(p, s ? "sliding" : "rest", r);
            std::fprintf(out, "%s\n", line.c_str());
            std::fflush(out);
            std::fprintf(stderr, "# time %.2f s: %s\n", sec, line.c_str());
            if (r.status == "capped" || r.coarse.status == "capped")
                capped.push_back(line.substr(0, line.find(",", 0)));
        }
    }
    if (!capped.empty()) {
        std::fprintf(out,
                     "# capped by --max-steps (step budget ran out before settling): %zu run(s), marked "
                     "status=capped above\n",
                     capped.size());
    }
    if (out != stdout) std::fclose(out);
    return 0;
}
