// Brute-force integration of the steady state; the model, the numerics and the periodicity test are described
// in brute_force.hpp.
#include "brute_force.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace fv::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr int kMaxK = 16;             // periods k = 1..16 are tested
constexpr double kStickSlack = 2e-14; // stick -> circle when rho^2 > 1 + kStickSlack
constexpr double kRadialFrom = 0.5;   // 0 < i < 1, s = +1: (u, phi) representation for rho >= this

// cos and sin of an angle in degrees: exact at 0, 90 and 180, and exactly (c, s) -> (-c, s) under
// theta -> 180 - theta when 180 - theta is exact.
void sincos_deg(double deg, double& c, double& s) {
    const bool flip = deg > 90.0;
    const double d = flip ? 180.0 - deg : deg;
    if (d == 0.0) {
        c = 1.0;
        s = 0.0;
    } else if (d == 90.0) {
        c = 0.0;
        s = 1.0;
    } else {
        c = std::cos(d * (kPi / 180.0));
        s = std::sin(d * (kPi / 180.0));
    }
    if (flip) c = -c;
}

// x^e for x >= 0, with fast paths for small integer and half-integer e.
struct Power {
    double e = 0;
    int n = -1; // e as an integer 0..64, else -1
    bool half = false;
    explicit Power(double ex = 0) : e(ex) {
        if (ex >= 0 && ex <= 64 && ex == std::floor(ex)) n = static_cast<int>(ex);
        half = (ex == 0.5);
    }
    double operator()(double x) const {
        if (n >= 0) {
            double r = 1.0, b = x;
            int m = n;
            while (m) {
                if (m & 1) r *= b;
                b *= b;
                m >>= 1;
            }
            return r;
        }
        if (half) return std::sqrt(x);
        return std::pow(x, e);
    }
};

enum class Mode { stick, cart, radial, circle };

// State: stick, cart: (a, b) = l; radial: (a, b) = (u, phi), rho = 1 - |u|^(1/(1-i)); circle: a = phi.
struct State {
    Mode mode = Mode::cart;
    int s = 1; // sgn v for cart (the law's branch); +1 in radial
    double a = 0, b = 0;
};

struct Model {
    double zeta, ct, st_, r, i; // st_: sin theta
    bool sub_one;               // 0 < i < 1
    Power pow_i, pow_im1;       // x^i, x^(i-1)
    Power pow_p, pow_1mi;       // x^(1/(1-i)), x^(1-i) (radial representation, 0 < i < 1)
    double h = 0;               // grid step (added to |P'| in the stiffness bound)

    Model(double zeta_, double theta_deg, double r_, double i_)
        : zeta(zeta_), r(r_), i(i_), sub_one(i_ > 0 && i_ < 1), pow_i(i_), pow_im1(i_ - 1),
          pow_p(sub_one ? 1.0 / (1.0 - i_) : 1.0), pow_1mi(sub_one ? 1.0 - i_ : 1.0) {
        sincos_deg(theta_deg, ct, st_);
    }

    void pdot(double t, double& px, double& py) const {
        const double c = std::cos(t);
        px = zeta + c * ct;
        py = c * st_;
    }

    // g/rho with g = 1 - (1 - s rho)^i (interior law); -> s i as rho -> 0.
    double q_of(int s, double rho) const {
        if (rho == 0.0) return s * i;
        if (rho < 1e-3) return -std::expm1(i * std::log1p(-s * rho)) / rho;
        const double a = std::max(0.0, 1.0 - s * rho);
        return (1.0 - pow_i(a)) / rho;
    }

    double rho_radial(double u) const { return 1.0 - pow_p(std::fabs(u)); }

    // d = (a', b', Mx', My').
    void rhs(Mode m, int s, double t, double a, double b, double d[4]) const {
        double px, py;
        pdot(t, px, py);
        switch (m) {
        case Mode::stick:
            d[0] = r * px;
            d[1] = r * py;
            d[2] = a;
            d[3] = b;
            return;
        case Mode::cart: {
            const double rho = std::hypot(a, b);
            if (rho == 0.0) {
                d[0] = r * px;
                d[1] = r * py;
            } else {
                const double vq = (a * px + b * py) / rho * q_of(s, rho);
                d[0] = r * (px - vq * a);
                d[1] = r * (py - vq * b);
            }
            d[2] = a;
            d[3] = b;
            return;
        }
        case Mode::radial: {
            const double rho = rho_radial(a);
            const double c = std::cos(b), sn = std::sin(b);
            const double v = c * px + sn * py;
            const double vp = -sn * px + c * py;
            d[0] = -(1.0 - i) * r * v;
            d[1] = r * vp / rho;
            d[2] = rho * c;
            d[3] = rho * sn;
            return;
        }
        case Mode::circle: {
            const double c = std::cos(a), sn = std::sin(a);
            d[0] = r * (-sn * px + c * py);
            d[1] = 0.0;
            d[2] = c;
            d[3] = sn;
            return;
        }
        }
    }

    // One classical RK4 step of length H from (t, a, b), k1 = rhs there: out = (a1, b1, dMx, dMy).
    void rk4(Mode m, int s, double t, double a, double b, const double k1[4], double H, double out[4]) const {
        double k2[4] = {}, k3[4] = {}, k4[4] = {};
        const double h2 = 0.5 * H;
        rhs(m, s, t + h2, a + h2 * k1[0], b + h2 * k1[1], k2);
        rhs(m, s, t + h2, a + h2 * k2[0], b + h2 * k2[1], k3);
        rhs(m, s, t + H, a + H * k3[0], b + H * k3[1], k4);
        const double w = H / 6.0;
        for (int j = 0; j < 4; ++j) out[j] = w * (k1[j] + 2.0 * k2[j] + 2.0 * k3[j] + k4[j]);
        out[0] += a;
        out[1] += b;
        if (m == Mode::cart && i >= 1.0) { // rounding past the circle (the law cannot leave the disc)
            const double rho = std::hypot(out[0], out[1]);
            if (rho > 1.0) {
                out[0] /= rho;
                out[1] /= rho;
            }
        }
    }

    // Stiffness bound at the start of a sub-step.
    double lambda(Mode m, int s, double t, double a, double b) const {
        double px, py;
        pdot(t, px, py);
        const double pm = std::hypot(px, py) + h;
        switch (m) {
        case Mode::stick:
            return 0.0;
        case Mode::circle:
            return r * pm;
        case Mode::radial:
            return r * pm * (1.0 + 1.0 / rho_radial(a));
        case Mode::cart: {
            const double rho = std::hypot(a, b);
            const double q = std::fabs(q_of(s, rho));
            const double base = std::max(0.0, 1.0 - s * rho);
            const double kp = (i == 1.0) ? 1.0 : i * pow_im1(base); // |dg/drho|
            return r * pm * (1.0 + std::max(q, kp));
        }
        }
        return 0.0;
    }

    // Event functions g (the law holds while all are >= 0) and their rates dg/dtau along the flow, at
    // (t, a, b) with f = rhs there; returns their number.
    int events(Mode m, int s, double t, double a, double b, const double f[4], double g[2],
               double gd[2]) const {
        double px, py;
        pdot(t, px, py);
        const double sin_t = std::sin(t);
        const double qx = -sin_t * ct, qy = -sin_t * st_; // P''
        switch (m) {
        case Mode::stick:
            g[0] = 1.0 + kStickSlack - (a * a + b * b);
            gd[0] = -2.0 * (a * f[0] + b * f[1]);
            return 1;
        case Mode::cart:
            g[0] = s * (a * px + b * py);
            gd[0] = s * (f[0] * px + f[1] * py + a * qx + b * qy);
            if (sub_one && s > 0) {
                const double rho = std::hypot(a, b);
                g[1] = kRadialFrom - rho;
                gd[1] = rho > 0 ? -(a * f[0] + b * f[1]) / rho : 0.0;
                return 2;
            }
            return 1;
        case Mode::radial: {
            const double c = std::cos(b), sn = std::sin(b);
            g[0] = c * px + sn * py;
            gd[0] = f[1] * (-sn * px + c * py) + c * qx + sn * qy;
            g[1] = a;
            gd[1] = f[0];
            return 2;
        }
        case Mode::circle: {
            const double c = std::cos(a), sn = std::sin(a);
            g[0] = c * px + sn * py;
            gd[0] = f[0] * (-sn * px + c * py) + c * qx + sn * qy;
            return 1;
        }
        }
        return 0;
    }

    // RK4 over H from (t, a, b) (f0 = rhs there): the end state y, f1 = rhs there, g and gd there.
    int probe(Mode m, int s, double t, double a, double b, const double f0[4], double H, double y[4],
              double f1[4], double g[2], double gd[2]) const {
        rk4(m, s, t, a, b, f0, H, y);
        rhs(m, s, t + H, y[0], y[1], f1);
        return events(m, s, t + H, y[0], y[1], f1, g, gd);
    }

    // The interior state (cart or radial) for l with branch s; the circle if rho = 1 and s = +1.
    State interior(double lx, double ly, int s) const {
        const double rho = std::hypot(lx, ly);
        State st;
        if (i == 0.0) {
            st.mode = Mode::stick;
            st.a = lx;
            st.b = ly;
            return st;
        }
        if (s > 0 && rho >= 1.0) {
            st.mode = Mode::circle;
            st.a = std::atan2(ly, lx);
            return st;
        }
        if (sub_one && s > 0 && rho >= kRadialFrom) {
            st.mode = Mode::radial;
            st.s = 1;
            st.a = pow_1mi(1.0 - rho);
            st.b = std::atan2(ly, lx);
            return st;
        }
        st.mode = Mode::cart;
        st.s = s;
        st.a = lx;
        st.b = ly;
        return st;
    }

    // The state for a starting force l0 at t = 0.
    State start(double lx, double ly) const {
        const double rho = std::hypot(lx, ly);
        double px, py;
        pdot(0.0, px, py);
        if (rho >= 1.0 - 1e-15) { // on the circle
            const double ex = lx / rho, ey = ly / rho;
            const double v = ex * px + ey * py;
            if (v >= 0.0) {
                State st;
                st.mode = Mode::circle;
                st.a = std::atan2(ey, ex);
                return st;
            }
            return interior(ex, ey, -1);
        }
        const double dot = lx * px + ly * py;
        return interior(lx, ly, dot < 0.0 ? -1 : 1);
    }

    // After the event `which` of mode st.mode (the state already at the far side of the switch).
    State switch_law(const State& st, int which) const {
        switch (st.mode) {
        case Mode::stick: { // rho reached 1
            State n;
            n.mode = Mode::circle;
            n.a = std::atan2(st.b, st.a);
            return n;
        }
        case Mode::cart:
            if (which == 0) return interior(st.a, st.b, -st.s); // v changed sign
            {
                // 0 < i < 1, rho reached kRadialFrom while loading
                State n;
                n.mode = Mode::radial;
                n.s = 1;
                n.a = pow_1mi(1.0 - std::hypot(st.a, st.b));
                n.b = std::atan2(st.b, st.a);
                return n;
            }
        case Mode::radial:
            if (which == 0) { // v < 0: unloading
                const double rho = rho_radial(st.a);
                return interior(rho * std::cos(st.b), rho * std::sin(st.b), -1);
            } else { // u = 0: on the circle
                State n;
                n.mode = Mode::circle;
                n.a = st.b;
                return n;
            }
        case Mode::circle: // v < 0: leave
            return interior(std::cos(st.a), std::sin(st.a), -1);
        }
        return st;
    }

    void force(const State& st, double& lx, double& ly) const {
        switch (st.mode) {
        case Mode::stick:
        case Mode::cart:
            lx = st.a;
            ly = st.b;
            return;
        case Mode::radial: {
            const double rho = rho_radial(st.a);
            lx = rho * std::cos(st.b);
            ly = rho * std::sin(st.b);
            return;
        }
        case Mode::circle:
            lx = std::cos(st.a);
            ly = std::sin(st.a);
            return;
        }
    }
};

struct Kahan {
    double sum = 0, c = 0;
    void add(double x) {
        const double y = x - c;
        const double t = sum + y;
        c = (t - sum) - y;
        sum = t;
    }
};

void check_params(double zeta, double theta_deg, double rdisp, double i) {
    if (!std::isfinite(zeta) || zeta < 0) throw std::invalid_argument("brute_force: zeta must be >= 0");
    if (!std::isfinite(theta_deg) || theta_deg < 0 || theta_deg > 180)
        throw std::invalid_argument("brute_force: theta must be in [0, 180] degrees");
    if (!std::isfinite(rdisp) || !(rdisp > 0)) throw std::invalid_argument("brute_force: rdisp must be > 0");
    if (!std::isfinite(i) || i < 0 || i > 50)
        throw std::invalid_argument("brute_force: i must be in [0, 50]");
}

// Illinois (regula falsi with halving) on [lo, hi] with F(lo) >= 0 > F(hi): returns a point within 1e-15 past
// the crossing (F < 0 there). Each evaluation of F is one RK4 sub-step, counted in steps.
template <class Fn> double crossing(Fn&& F, double lo, double hi, double flo, double fhi, double& steps) {
    int side = 0;
    for (int it = 0; it < 200 && hi - lo > 1e-15; ++it) {
        double c = hi - fhi * (hi - lo) / (fhi - flo);
        if (it % 4 == 3 || !(c > lo && c < hi)) c = 0.5 * (lo + hi);
        if (!(c > lo && c < hi)) break;
        const double fc = F(c);
        steps += 1;
        if (fc < 0) {
            hi = c;
            fhi = fc;
            if (side == -1) flo *= 0.5;
            side = -1;
        } else {
            lo = c;
            flo = fc;
            if (side == 1) fhi *= 0.5;
            side = 1;
        }
    }
    return hi;
}

int next_pow2(double x) {
    int n = 1;
    while (n < x && n < (1 << 30)) n *= 2;
    return n;
}

} // namespace

int brute_force_steps(double zeta, double rdisp, const BruteForceOptions& options) {
    const double need = kTwoPi * rdisp * (1.0 + zeta) / options.sigma;
    return next_pow2(std::max({2048.0, need, static_cast<double>(options.steps_per_period)}));
}

BruteForceRun brute_force_run(double zeta, double theta_deg, double rdisp, double i, double l0x, double l0y,
                              int steps_per_period, double sigma, const BruteForceOptions& options) {
    check_params(zeta, theta_deg, rdisp, i);
    if (!(std::hypot(l0x, l0y) <= 1.0 + 1e-12)) throw std::invalid_argument("brute_force: |l0| must be <= 1");
    if (steps_per_period < 1) throw std::invalid_argument("brute_force: steps_per_period must be >= 1");
    Model md(zeta, theta_deg, rdisp, i);
    const int N = steps_per_period;
    const double h = kTwoPi / N;
    md.h = h;

    State st = md.start(l0x, l0y);
    BruteForceRun out;
    out.steps_per_period = N;

    std::vector<double> sec_x{0.0}, sec_y{0.0}; // section states l_n, n = 0..
    md.force(st, sec_x[0], sec_y[0]);
    std::vector<double> mean_x, mean_y; // per-period means, period n at index n-1
    // r_x, r_y as the mean of the per-period means over periods [first, n) (a period-k orbit's last k, or the
    // long-time window).
    auto set_mean = [&](int first, int n_end) {
        double sx = 0, sy = 0;
        for (int m = first; m < n_end; ++m) {
            sx += mean_x[m];
            sy += mean_y[m];
        }
        out.rx = sx / (n_end - first);
        out.ry = sy / (n_end - first);
    };
    std::vector<std::vector<double>> dk(kMaxK + 1); // dk[k][n]
    for (auto& v : dk) v.push_back(0.0);

    double steps = 0;
    long long events = 0;
    bool capped = false;
    int n = 0;
    bool have_start = false; // f0, g0, gd0 hold the rates and events at the sub-step start
    double f0[4] = {0, 0, 0, 0}, g0[2] = {0, 0}, gd0[2] = {0, 0};
    int ne0 = 0;

    const double inf = std::numeric_limits<double>::infinity();
    // Contraction per k periods at section nn. Baselines m = k, 2k, 4k, ... : c_m =
    // (d_k(nn)/d_k(nn-m))^(k/m); a baseline counts if d changed by at least 5% over it (shorter ones only
    // measure rounding noise when the contraction is slow); the largest (slowest) counting c_m is taken, else
    // the longest baseline's. If that is not < 1 while d is near the rounding floor, the last ratio measured
    // with d_k(m-k) >= 1e-12.
    auto contraction_k = [&](int k, int nn) {
        if (dk[k][nn] == 0) return 0.0;
        double best = -1, longest = inf;
        for (int m = k; nn - m >= k; m *= 2) {
            const double dm = dk[k][nn - m];
            if (!(dm > 0) || !std::isfinite(dm)) continue;
            const double lr = std::log(dk[k][nn] / dm);
            const double c = std::exp(lr * k / m);
            longest = c;
            if (std::fabs(lr) >= 0.05) best = std::max(best, c);
        }
        const double c = best >= 0 ? best : longest;
        if (c < 1 || dk[k][nn] >= options.tol / 100) return c;
        for (int m = nn - 1; m >= 2 * k; --m)
            if (dk[k][m - k] >= 1e-12) {
                const double cm = dk[k][m] / dk[k][m - k];
                return cm < 1 ? cm : inf;
            }
        return inf;
    };
    // |mean over periods nn-k+1..nn  -  mean over the k periods before|
    auto mean_diff = [&](int k, int nn) {
        if (nn < 2 * k) return inf;
        double ax = 0, ay = 0;
        for (int m = nn - k; m < nn; ++m) {
            ax += mean_x[m] - mean_x[m - k];
            ay += mean_y[m] - mean_y[m - k];
        }
        return std::hypot(ax, ay) / k;
    };
    // Geometric tail of the section state and of the k-period mean: the distance to the limit estimated as
    // (last change) c/(1 - c); the larger of the two.
    auto tail_of = [&](int k, int nn) {
        const double c = contraction_k(k, nn);
        if (!(c < 1)) return inf;
        return std::max(dk[k][nn], mean_diff(k, nn)) * c / (1 - c);
    };
    // Per-period contraction for the report: the last ratio with both differences above the rounding floor.
    auto record = [&](int k, int nn) {
        for (int m = nn; m >= 2 * k; --m)
            if (dk[k][m - k] >= 1e-12 && dk[k][m] >= 1e-15) return std::pow(dk[k][m] / dk[k][m - k], 1.0 / k);
        return 0.0;
    };

    while (n < options.max_periods) {
        Kahan mx, my;
        for (int j = 0; j < N; ++j) {
            double t = j * h;
            const double t_end = (j + 1) * h;
            int immediate = 0;
            while (t < t_end) {
                if (!have_start) { // after a switch or at a period's start: the rates and events afresh
                    md.rhs(st.mode, st.s, t, st.a, st.b, f0);
                    ne0 = md.events(st.mode, st.s, t, st.a, st.b, f0, g0, gd0);
                    have_start = true;
                    int bad = -1;
                    for (int e = 0; e < ne0 && bad < 0; ++e)
                        if (g0[e] < 0) bad = e;
                    if (bad >= 0) { // already past a switch (rounding at the previous switch)
                        st = md.switch_law(st, bad);
                        ++events;
                        have_start = false;
                        if (++immediate > 20)
                            throw std::runtime_error("brute_force: law switches without progress");
                        continue;
                    }
                }
                const double lam = md.lambda(st.mode, st.s, t, st.a, st.b);
                double H = t_end - t;
                if (lam * H > sigma) H = sigma / lam;
                double y[4], f1[4], g1[2], gd1[2];
                const Mode m = st.mode;
                const int sg = st.s;
                const double a0 = st.a, b0 = st.b;
                const int ne = md.probe(m, sg, t, a0, b0, f0, H, y, f1, g1, gd1);
                steps += 1;
                // events: a sign change of g over the sub-step, or (grazing) a minimum of g inside it that
                // dips below zero although g >= 0 at both ends
                int which = -1;
                double h_event = H;
                for (int e = 0; e < ne; ++e) {
                    auto g_at = [&](double c) {
                        double yy[4], ff[4], gg[2], gg_d[2];
                        md.probe(m, sg, t, a0, b0, f0, c, yy, ff, gg, gg_d);
                        return gg[e];
                    };
                    double hit = -1;
                    if (g1[e] < 0) {
                        hit = crossing(g_at, 0.0, H, std::max(g0[e], 0.0), g1[e], steps);
                    } else if (gd0[e] < 0 && gd1[e] > 0) {
                        auto neg_gd_at = [&](double c) {
                            double yy[4], ff[4], gg[2], gg_d[2];
                            md.probe(m, sg, t, a0, b0, f0, c, yy, ff, gg, gg_d);
                            return -gg_d[e];
                        };
                        const double tm = crossing(neg_gd_at, 0.0, H, -gd0[e], -gd1[e], steps);
                        const double gm = g_at(tm);
                        steps += 1;
                        if (gm < 0) hit = crossing(g_at, 0.0, tm, std::max(g0[e], 0.0), gm, steps);
                    }
                    if (hit >= 0 && (which < 0 || hit < h_event)) {
                        which = e;
                        h_event = hit;
                    }
                }
                if (which >= 0 && h_event < H) {
                    md.probe(m, sg, t, a0, b0, f0, h_event, y, f1, g1, gd1);
                    steps += 1;
                    H = h_event;
                }
                st.a = y[0];
                st.b = y[1];
                mx.add(y[2]);
                my.add(y[3]);
                t = (H == t_end - t) ? t_end : t + H;
                if (which >= 0) {
                    st = md.switch_law(st, which);
                    ++events;
                    have_start = false;
                } else {
                    std::copy(f1, f1 + 4, f0);
                    std::copy(g1, g1 + 2, g0);
                    std::copy(gd1, gd1 + 2, gd0);
                    ne0 = ne;
                }
                if (options.max_steps > 0 && steps > options.max_steps) {
                    capped = true;
                    break;
                }
            }
            if (capped) break;
        }
        if (capped) break;
        have_start = false;
        // section
        ++n;
        if (st.mode == Mode::circle) st.a = std::remainder(st.a, kTwoPi);
        if (st.mode == Mode::radial) st.b = std::remainder(st.b, kTwoPi);
        double lx, ly;
        md.force(st, lx, ly);
        sec_x.push_back(lx);
        sec_y.push_back(ly);
        mean_x.push_back(mx.sum / kTwoPi);
        mean_y.push_back(my.sum / kTwoPi);
        for (int k = 0; k <= kMaxK; ++k)
            dk[k].push_back(k >= 1 && n >= k ? std::hypot(lx - sec_x[n - k], ly - sec_y[n - k])
                                             : std::numeric_limits<double>::infinity());
        bool done = false;
        for (int k = 1; k <= kMaxK && !done; ++k) {
            if (n < k) break;
            double d = dk[k][n];
            if (!(d < options.tol)) continue;
            const double tail = tail_of(k, n);
            if (tail < options.tol) {
                // a multiple of the period can pass first (d_k is smaller than d_{k/m} when the approach
                // oscillates); report the least k' dividing k along which the state also repeats
                for (int kk = 1; kk < k; ++kk)
                    if (k % kk == 0 && dk[kk][n] < 10 * options.tol) {
                        k = kk;
                        d = dk[kk][n];
                        break;
                    }
                out.status = "period_" + std::to_string(k);
                out.k = k;
                out.tail = tail;
                out.last_diff = d;
                out.contraction = record(k, n);
                set_mean(n - k, n);
                done = true;
            }
        }
        if (done) break;
    }
    out.periods = n;
    out.steps = steps;
    out.events = events;
    out.lx = sec_x.back();
    out.ly = sec_y.back();
    if (!out.status.empty()) return out;

    // Not settled within the budget.
    if (n == 0) {
        out.status = "capped";
        out.rx = out.ry = std::numeric_limits<double>::quiet_NaN();
        return out;
    }
    int kbest = 1;
    for (int k = 1; k <= kMaxK && k <= n; ++k)
        if (dk[k][n] < dk[kbest][n]) kbest = k;
    const double dbest = dk[kbest][n];
    // converging, only slowly: d_k < 1e-4 over the whole last quarter of the run, and d_k(n) below its value
    // at every baseline k, 2k, 4k, ... <= n/2 back (a chaotic run can come back close to itself by chance,
    // but not for a quarter of the run)
    bool decreasing = n >= 8 * kbest && dbest < 1e-4;
    for (int m = n - n / 4; decreasing && m <= n; ++m)
        if (!(dk[kbest][m] < 1e-4)) decreasing = false;
    for (int m = kbest; decreasing && m <= n / 2; m *= 2)
        if (!(dbest < dk[kbest][n - m]) && dbest >= options.tol) decreasing = false;
    if (!capped && decreasing) {
        out.status = "unsettled";
        out.k = kbest;
        // the approach may be algebraic (d ~ n^-p, e.g. p = i/(i-1) for the creep towards the circle), where
        // the geometric tail underestimates the rest by a factor ~p/(p-1): also sum a power law fitted over
        // n/2
        out.tail = tail_of(kbest, n);
        const int half = (n / 2 / kbest) * kbest;
        if (dk[kbest][n] > 0 && dk[kbest][n - half] > dk[kbest][n]) {
            const double p = std::log(dk[kbest][n - half] / dk[kbest][n]) / std::log(n / double(n - half));
            const double last = std::max(dk[kbest][n], mean_diff(kbest, n));
            out.tail = std::max(out.tail, p > 1 ? last * (n / double(kbest)) / (p - 1) : inf);
        }
        out.last_diff = dbest;
        out.contraction = std::pow(contraction_k(kbest, n), 1.0 / kbest);
        set_mean(n - kbest, n);
        return out;
    }
    out.status = capped ? "capped" : "not_periodic";
    out.k = 0;
    out.last_diff = dk[1][n];
    out.contraction = n >= 2 && dk[1][n - 1] > 0 ? dk[1][n] / dk[1][n - 1] : 0;
    // long-time mean over the last half, standard error by 20 batch means
    const int first = n / 2;
    const int len = n - first;
    set_mean(first, n);
    const int B = 20;
    if (len >= B) {
        const int bs = len / B;
        std::vector<double> bx(B), by(B);
        for (int b = 0; b < B; ++b) {
            double ax = 0, ay = 0;
            for (int m = 0; m < bs; ++m) {
                ax += mean_x[n - (b + 1) * bs + m];
                ay += mean_y[n - (b + 1) * bs + m];
            }
            bx[b] = ax / bs;
            by[b] = ay / bs;
        }
        double mxb = 0, myb = 0;
        for (int b = 0; b < B; ++b) {
            mxb += bx[b];
            myb += by[b];
        }
        mxb /= B;
        myb /= B;
        double vx = 0, vy = 0;
        for (int b = 0; b < B; ++b) {
            vx += (bx[b] - mxb) * (bx[b] - mxb);
            vy += (by[b] - myb) * (by[b] - myb);
        }
        out.se_x = std::sqrt(vx / (B - 1) / B);
        out.se_y = std::sqrt(vy / (B - 1) / B);
    } else {
        out.se_x = out.se_y = std::numeric_limits<double>::infinity();
    }
    return out;
}

BruteForceResult brute_force(double zeta, double theta_deg, double rdisp, double i, BruteStart start,
                             const BruteForceOptions& options) {
    const double l0x = start == BruteStart::rest ? 0.0 : 1.0;
    const int N = brute_force_steps(zeta, rdisp, options);
    BruteForceResult res;
    res.coarse = brute_force_run(zeta, theta_deg, rdisp, i, l0x, 0.0, N, options.sigma, options);
    res.fine = options.refine
                   ? brute_force_run(zeta, theta_deg, rdisp, i, l0x, 0.0, 2 * N, 0.5 * options.sigma, options)
                   : res.coarse;
    const BruteForceRun& c = res.coarse;
    const BruteForceRun& f = res.fine;
    res.status = f.status;
    res.k = f.k;
    res.periods = f.periods;
    res.rx = f.rx;
    res.ry = f.ry;
    res.lx = f.lx;
    res.ly = f.ly;
    const double dx = std::fabs(f.rx - c.rx), dy = std::fabs(f.ry - c.ry);
    char buf[200];
    if (c.status != f.status) {
        std::snprintf(buf, sizeof buf, "coarse run: %s rx=%.12g; ", c.status.c_str(), c.rx);
        res.note += buf;
    }
    if (f.status.rfind("period_", 0) == 0 && c.status == f.status) {
        res.rx_err = dx + f.tail;
        res.ry_err = dy + f.tail;
    } else if (f.status == "unsettled") {
        res.rx_err = dx + f.tail;
        res.ry_err = dy + f.tail;
        std::snprintf(buf, sizeof buf, "tail estimate %.2g (slow approach); ", f.tail);
        res.note += buf;
    } else if (f.status == "not_periodic" || f.status == "capped") {
        res.rx_err = f.se_x;
        res.ry_err = f.se_y;
        std::snprintf(buf, sizeof buf, "batch-means SE; coarse-fine |drx|=%.2g; ", dx);
        res.note += buf;
    } else {
        res.rx_err = dx;
        res.ry_err = dy;
    }
    if (!options.refine) res.note += "single resolution, no error estimate; ";
    if (!res.note.empty() && res.note.back() == ' ') res.note.resize(res.note.size() - 2);
    return res;
}

} // namespace fv::ref
