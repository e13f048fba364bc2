// The lumped asperity's motion split into its phases (derivation: docs/model.md, "The lag law and its
// phases"). Units: lengths in x_v, the lag L = P - T, the force l = F/F_c = rdisp L (|l| <= 1).
//   stick    (i = 0, |l| < 1, or |l| = 1 with v < 0): T fixed, L(tau) = L_a + P(tau) - P(tau_a) (Eq. (27)).
//   circle   (|l| = 1 and v = e . P' >= 0, any i): the tip slips at full deflection; only the angle phi of
//            l moves: phi' = rdisp e_perp . P'. Integrated as the arc a = (phi - phi_a)/rdisp (units of x_v).
//   interior (i > 0, |l| < 1): Eq. (16) in the plane, dL/dtau = P' - v (1 - (1 - s rho)^i) e with
//            rho = |l|, e = l/rho, v = e . P', s = sgn v held fixed between velocity events. Integrated as
//            the displacement D = L - L_a.
// Integrated variables are displacements in x_v, so their size (and the tolerance that goes with them)
// does not depend on rdisp: for tiny rdisp the period map is a small perturbation of the identity, and its
// fixed-point equation (L(2 pi) - L(0) = 0) stays well conditioned in these units.
#pragma once

#include "fv/params.hpp"
#include "fv/vec2.hpp"

#include <Eigen/Core>

#include <cmath>
#include <limits>
#include <optional>

namespace fv::solver {

inline constexpr double kTwoPi = 2 * kPi;

// Where an interior state counts as being on the circle (i > 0): 1 - rho <= kPin. Pinning there changes
// |F| by at most kPin, and turns the approach to the circle (finite-time but non-Lipschitz for i < 1,
// exponential for i = 1, algebraic for i > 1) into the exact pursuit motion it tends to.
inline constexpr double kPin = 1e-12;

// (cos x, sin x) within 2 ulp of the library's values, or 1e-30 next to their zeros (fdlibm's kernels on
// |y| <= pi/4 after a three-part Cody-Waite reduction by pi/2), for |x| <= 1e6; beyond, the library's. The
// solver evaluates the circle's angle and P' at every stage of every Newton iteration: the library's sincos
// was a third of its time.
inline Vec2 cos_sin(double x) {
    if (!(std::abs(x) <= 1e6)) return {std::cos(x), std::sin(x)};
    constexpr double inv_pio2 = 6.36619772367581382433e-01;
    constexpr double pio2_1 = 1.57079632673412561417e+00; // first 33 bits of pi/2: k pio2_1 is exact
    constexpr double pio2_2 = 6.07710050630396597660e-11, pio2_3 = 2.02226624871116645580e-21;
    constexpr double round = 6755399441055744.0; // 1.5 * 2^52: adding and subtracting rounds to an integer
    const double k = (x * inv_pio2 + round) - round;
    const double y = ((x - k * pio2_1) - k * pio2_2) - k * pio2_3;
    const double z = y * y;
    const double sp = 8.33333333332248946124e-03 +
                      z * (-1.98412698298579493134e-04 +
                           z * (2.75573137070700676789e-06 +
                                z * (-2.50507602534068634195e-08 + z * 1.58969099521155010221e-10)));
    const double sy = y + y * z * (-1.66666666666666324348e-01 + z * sp);
    const double cp =
        z * (4.16666666666666019037e-02 +
             z * (-1.38888888888741095749e-03 +
                  z * (2.48015872894767294178e-05 +
                       z * (-2.75573143513906633035e-07 +
                            z * (2.08757232129817482790e-09 + z * -1.13596475577881948265e-11)))));
    const double hz = 0.5 * z, w = 1.0 - hz;
    const double cy = w + (((1.0 - w) - hz) + z * cp);
    switch (static_cast<long>(k) & 3) {
    case 0:
        return {cy, sy};
    case 1:
        return {-sy, cy};
    case 2:
        return {-cy, -sy};
    default:
        return {sy, -cy};
    }
}

struct LagModel {
    explicit LagModel(const Params& p)
        : zeta(p.zeta), cth(std::cos(p.theta)), sth(std::sin(p.theta)), r(p.rdisp), zss(p.zss()), i(p.i) {}
    double zeta, cth, sth, r, zss, i;

  private:
    static constexpr int kCache = 8;
    static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
    mutable double cache_tau_[kCache] = {kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN, kNaN};
    mutable double cache_cos_[kCache] = {};
    mutable int next_ = 0;

  public:
    Vec2 u() const { return {cth, sth}; } // vibration direction
    // Eqs. (28)-(29) divided by x_v, their derivatives (Eq. (1) divided by v_v).
    Vec2 P(double tau) const { return {zeta * tau + std::sin(tau) * cth, std::sin(tau) * sth}; }
    Vec2 dP(double tau) const {
        const double c = cos_of(tau);
        return {zeta + c * cth, c * sth};
    }
    // cos(tau), remembered for the last few instants: a Radau step evaluates the law, its Jacobian and the
    // event functions at the same few instants many times (one LagModel per solve: no sharing between
    // threads).
    double cos_of(double tau) const {
        for (int k = 0; k < kCache; ++k)
            if (cache_tau_[k] == tau) return cache_cos_[k];
        const double c = cos_sin(tau).x();
        next_ = (next_ + 1) % kCache;
        cache_tau_[next_] = tau;
        cache_cos_[next_] = c;
        return c;
    }
    Vec2 ddP(double tau) const {
        const double s = std::sin(tau);
        return {-s * cth, -s * sth};
    }
    // P(b) - P(a) without cancellation for b close to a.
    Vec2 dispP(double a, double b) const {
        const double ds = 2 * std::cos(0.5 * (a + b)) * std::sin(0.5 * (b - a));
        return Vec2(zeta * (b - a), 0) + ds * u();
    }
    // int_a^b (P(tau) - P(a)) dtau.
    Vec2 int_dispP(double a, double b) const {
        const double d = b - a;
        return Vec2(0.5 * zeta * d * d, 0) + (std::cos(a) - std::cos(b) - std::sin(a) * d) * u();
    }
};

// Interior law (i > 0) for D = L - L_a, branch s fixed. Problem interface of radau_step (radau_iia.hpp).
struct InteriorProblem {
    static constexpr int N = 2;
    using Vec = Eigen::Matrix<double, 2, 1>;
    using Mat = Eigen::Matrix<double, 2, 2>;
    const LagModel* m;
    Vec2 l_a;    // force at the phase start
    double s;    // sgn v of this piece
    double bmin; // floor of the base 1 - s rho (a stage may stray past the circle)

    int whole_i; // i when it is a whole number up to 16 (powers by multiplication), else 0

    InteriorProblem(const LagModel& model, Vec2 la, double sign)
        : m(&model), l_a(la), s(sign), bmin(0.25 * kPin),
          whole_i(model.i >= 2 && model.i <= 16 && model.i == std::floor(model.i) ? static_cast<int>(model.i)
                                                                                  : 0) {}

    // The law at one state: the rate and what its Jacobian needs.
    struct Point {
        Vec f = Vec::Zero();
        Vec2 l{0, 0}, dp{0, 0}, e{0, 0}; // force, P', l / |l|
        double rho = 0, v = 0, q = 0, dk = 0;
    };

    Vec2 force(const Vec& D) const { return l_a + m->r * D; }
    Vec2 force(const Point& pt) const { return pt.l; }
    // dF/dtau along the law.
    Vec2 force_rate(const Point& pt) const { return m->r * pt.f; }

    // k = 1 - b^i, q = k / rho (bounded as rho -> 0: s i), dk/drho = s i b^(i-1).
    void law(double rho, double& q, double& dk) const {
        const double b = std::max(bmin, 1 - s * rho);
        const double i = m->i;
        if (i == 1) {
            q = rho > 0 ? (1 - b) / rho : s;
            dk = s;
            return;
        }
        if (whole_i > 0) {
            // 1 - b^n = (1 - b)(1 + b + ... + b^(n-1)), and 1 - b = s rho where b is not floored: no
            // cancellation for small rho, no exp/log.
            double sum = 0, pw = 1; // pw = b^k
            for (int k = 0; k < whole_i; ++k) {
                sum += pw;
                if (k + 1 < whole_i) pw *= b;
            }
            // sum = sum_{k<n} b^k, pw = b^(n-1)
            q = b > bmin ? s * sum : (rho > 1e-300 ? (1 - pw * b) / rho : s * i);
            dk = s * i * pw;
            return;
        }
        // -expm1(i log b) / rho: accurate for small rho. b^(i-1) = (1 + expm1(i log b)) / b (b >= bmin > 0).
        // glibc's expm1 costs several exp's (20 % of a period at a non-whole i): exp(x) - 1 where that loses
        // at most two bits (|x| >= 0.35: |e^x - 1| >= 0.3 e^x).
        const double x = i * std::log(b);
        const double em = std::abs(x) < 0.35 ? std::expm1(x) : std::exp(x) - 1;
        q = rho > 1e-300 ? -em / rho : s * i;
        dk = s * i * (1 + em) / b;
    }

    Point eval(double tau, const Vec& D) const {
        Point pt;
        pt.l = force(D);
        pt.dp = m->dP(tau);
        pt.rho = pt.l.norm();
        if (!(pt.rho > 0)) {
            pt.f = pt.dp;
            return pt;
        }
        pt.e = pt.l / pt.rho;
        pt.v = pt.e.dot(pt.dp);
        law(pt.rho, pt.q, pt.dk);
        pt.f = pt.dp - (pt.v * pt.q * pt.rho) * pt.e; // T moves along e at v (1 - b^i)
        return pt;
    }

    Mat jac(const Point& pt) const {
        if (!(pt.rho > 0)) return Mat::Zero();
        const Vec2& e = pt.e;
        const double v = pt.v, q = pt.q;
        const Mat ee = e * e.transpose();
        // d(v k e)/dl = q e (P' - v e)^T + v k' e e^T + v q (I - e e^T); dl/dD = r.
        const Mat J = q * e * (pt.dp - v * e).transpose() + v * pt.dk * ee + v * q * (Mat::Identity() - ee);
        return -m->r * J;
    }
};

// Circle law for the arc a (x_v units) from angle phi_a: phi = phi_a + r a, a' = e_perp . P'. Problem
// interface of radau_step (radau_iia.hpp).
struct CircleProblem {
    static constexpr int N = 1;
    using Vec = Eigen::Matrix<double, 1, 1>;
    using Mat = Eigen::Matrix<double, 1, 1>;
    const LagModel* m;
    double phi_a;

    // The law at one arc: the rate, the force (unit vector at the angle) and P'.
    struct Point {
        Vec f = Vec::Zero();
        Vec2 e{1, 0}, dp{0, 0};
    };

    double phi(double a) const { return phi_a + m->r * a; }
    Vec2 force(const Vec& a) const { return cos_sin(phi(a[0])); }
    Vec2 force(const Point& pt) const { return pt.e; }
    Vec2 force_rate(const Point& pt) const { return m->r * pt.f[0] * Vec2(-pt.e.y(), pt.e.x()); }
    Point eval(double tau, const Vec& a) const {
        Point pt;
        pt.e = force(a);
        pt.dp = m->dP(tau);
        pt.f = Vec(-pt.e.y() * pt.dp.x() + pt.e.x() * pt.dp.y());
        return pt;
    }
    Mat jac(const Point& pt) const {
        return Mat(-m->r * (pt.e.x() * pt.dp.x() + pt.e.y() * pt.dp.y())); // -r v
    }
};

// Stick (i = 0): l(tau) = l_a + r (P(tau) - P(tau_a)). First tau in (tau_a, tau_end] where |l| reaches 1
// moving outwards, or nothing. Rigorous: a cubic upper bound of g = |l|^2 - 1 from its exact value and first
// two derivatives and a bound on g''' never steps over a root; long stick phases far inside are skipped
// with the drift bound |l(tau)| <= |c + r zeta tau e_x| + r (whole stuck periods, analytically).
std::optional<double> stick_slip_time(const LagModel& m, double tau_a, Vec2 l_a, double tau_end);

} // namespace fv::solver
