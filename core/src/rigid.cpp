#include "fv/rigid.hpp"

#include "fv/params.hpp"
#include "fv/quadrature.hpp"

#include <cmath>
#include <vector>

namespace fv {

Ratio rigid_ratio(double zeta, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    // Body velocity over v_v from Eq. (1): (zeta + cos(theta) cos(tau), sin(theta) cos(tau)). Friction is
    // opposite to it with unit magnitude, Eq. (2); the ratios of Eqs. (8)-(9) take the magnitudes along
    // x and y. Both integrands depend on tau through cos(tau) only, so the mean over [0, 2 pi] equals the
    // mean over [0, pi].
    auto speed = [&](double u) { return std::hypot(zeta + c * u, s * u); };
    auto fx = [&](double tau) {
        const double u = std::cos(tau), w = speed(u);
        return w > 0 ? (zeta + c * u) / w : 0.0; // |v| = 0 only at isolated instants: no contribution
    };
    auto fy = [&](double tau) {
        const double u = std::cos(tau), w = speed(u);
        return w > 0 ? s * u / w : 0.0;
    };
    // Kinks: the speed is smallest where cos(tau) = -zeta cos(theta), and the x-velocity changes sign where
    // cos(tau) = -zeta / cos(theta). For theta = 0 the two coincide and Eq. (9)'s integrand jumps there.
    std::vector<double> breaks{kPi / 2};
    if (std::abs(zeta * c) <= 1) breaks.push_back(std::acos(-zeta * c));
    if (std::abs(c) > 0 && std::abs(zeta / c) <= 1) breaks.push_back(std::acos(-zeta / c));
    const QuadResult rx = integrate(fx, 0, kPi, breaks);
    const QuadResult ry = integrate(fy, 0, kPi, breaks);
    return {rx.value / kPi, ry.value / kPi};
}

double rigid_rx_parallel(double zeta) {
    // Eq. (10)
    return zeta <= 1 ? 2 / kPi * std::asin(zeta) : 1.0;
}

double rigid_rx_perpendicular(double zeta) {
    // Eq. (11): r_x = (2/pi) zeta/sqrt(1+zeta^2) K(m), m = k^2 = 1/(1+zeta^2). K is evaluated through the
    // arithmetic-geometric mean, K(k) = pi / (2 AGM(1, k')), with the complementary modulus
    // k' = sqrt(1 - k^2) = zeta/sqrt(1+zeta^2) formed directly: std::comp_ellint_1(k) would need k itself,
    // which rounds to 1 (K = inf) for zeta below ~1e-8. With both, Eq. (11) collapses to k'/AGM(1, k').
    if (zeta == 0) return 0.0;
    const double kc = zeta / std::sqrt(1 + zeta * zeta);
    double a = 1, b = kc;
    for (int it = 0; it < 64 && std::abs(a - b) > 1e-16 * a; ++it) {
        const double an = 0.5 * (a + b);
        b = std::sqrt(a * b);
        a = an;
    }
    return kc / (0.5 * (a + b));
}

} // namespace fv
