// Steady state on the circle |L| = z_ss (pursuit curve); the derivation is in circle_pursuit.hpp.
#include "circle_pursuit.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fv::ref {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kStiff = 0.5; // max rdisp (1 + zeta) dtau: RK4 is stable to 2.78 on the relaxation

struct Run {
    double rx = 0, ry = 0, min_v = 0;
    int periods = 0;
};

Run run(double zeta, double theta, double rdisp, int n) {
    const double ct = std::cos(theta);
    const double st = std::sin(theta);
    const double h = kTwoPi / n;
    // e' = rdisp (P' - (P' . e) e) with P' = (zeta + c ct, c st), c = cos tau.
    const auto rate = [&](double c, double ex, double ey, double& dx, double& dy) {
        const double px = zeta + c * ct;
        const double py = c * st;
        const double v = px * ex + py * ey;
        dx = rdisp * (px - v * ex);
        dy = rdisp * (py - v * ey);
    };
    const double n0 = std::hypot(zeta + ct, st);
    double ex = (zeta + ct) / n0;
    double ey = st / n0;
    Run out;
    for (int period = 1; period <= 60; ++period) {
        const double sx = ex, sy = ey;
        double sum_x = 0.0, sum_y = 0.0, min_v = INFINITY;
        double c0 = 1.0; // cos(0)
        for (int k = 0; k < n; ++k) {
            const double t = k * h;
            const double ch = std::cos(t + 0.5 * h);
            const double c1 = std::cos(t + h);
            double k1x, k1y, k2x, k2y, k3x, k3y, k4x, k4y;
            rate(c0, ex, ey, k1x, k1y);
            rate(ch, ex + 0.5 * h * k1x, ey + 0.5 * h * k1y, k2x, k2y);
            rate(ch, ex + 0.5 * h * k2x, ey + 0.5 * h * k2y, k3x, k3y);
            rate(c1, ex + h * k3x, ey + h * k3y, k4x, k4y);
            ex += h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
            ey += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
            sum_x += ex;
            sum_y += ey;
            min_v = std::min(min_v, (zeta + c1 * ct) * ex + c1 * st * ey);
            c0 = c1;
        }
        out.rx = sum_x / n;
        out.ry = sum_y / n;
        out.min_v = min_v;
        out.periods = period;
        if (period >= 2 && std::hypot(ex - sx, ey - sy) < 1e-14) break;
    }
    return out;
}

} // namespace

CirclePursuit circle_pursuit(double zeta, double theta, double rdisp) {
    if (!std::isfinite(zeta) || !(zeta > 0.0))
        throw std::invalid_argument("circle_pursuit: zeta must be > 0");
    if (!std::isfinite(theta) || !(theta > 0.0 && theta < kPi))
        throw std::invalid_argument("circle_pursuit: theta must be in (0, pi)");
    if (!std::isfinite(rdisp) || !(rdisp > 0.0))
        throw std::invalid_argument("circle_pursuit: rdisp must be > 0");
    int n = 1 << 12;
    while (rdisp * (1.0 + zeta) * (kTwoPi / n) > kStiff && n < (1 << 26)) n *= 2;
    const Run coarse = run(zeta, theta, rdisp, n);
    const Run fine = run(zeta, theta, rdisp, 2 * n);
    CirclePursuit r;
    r.rx = fine.rx;
    r.ry = fine.ry;
    r.min_v = std::min(coarse.min_v, fine.min_v);
    r.error_estimate = std::max(std::fabs(fine.rx - coarse.rx), std::fabs(fine.ry - coarse.ry));
    r.steps_per_period = 2 * n;
    r.periods = fine.periods;
    return r;
}

} // namespace fv::ref
