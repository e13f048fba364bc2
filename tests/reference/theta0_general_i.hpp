// Exact steady state of the lumped Dahl asperity for parallel vibrations (theta = 0) and ANY real shape
// exponent i >= 0. Independent reference for the solver tests (tests/test_solver_references.cpp): no time
// stepping anywhere. The only numerics are bisection of monotone scalar functions (to adjacent doubles) and
// adaptive Gauss-Kronrod quadrature of smooth pieces. It does not use fv:: code, nor theta0_exact.cpp (which
// it must reproduce at i = 0 and i = 1: checked by the tests to 1e-12).
//
// ---------------------------------------------------------------------------------------------------------
// Model (dimensionless as in docs/model.md, "Parameters"; Eqs. (14)-(16), (18)-(22), (25)-(29), theta = 0)
//   P(tau) = zeta tau + sin tau, P' = zeta + cos tau, z := z_ss = 1/rdisp, L := P - T (signed lag),
//   F/F_c = L/z. The scheme's dtau -> 0 limit: v = d|TP|/dt at fixed T = sgn(L) P', the deflection |L|
//   obeys Eq. (16), and L keeps its sign (T moves on the line TP). Writing s = sgn(P'):
//       d|L| = sgn(L) P' (1 - sgn(sgn(L) P') |L|/z)^i dtau   =>   dL/dtau = P' (1 - s L/z)^i,
//   one scalar law on -z <= L <= z (the interval is invariant: the bracket vanishes at L = s z).
//   i = 0 is the stiction law of Eq. (25)/(27): dL = dP while |L| < z, and L stays at +-z while P pulls
//   it outwards; that is exactly the i -> 0 limit of the formulas below (std::pow(0, 0) = 1 is never used).
//
// Separation of variables. While P is monotone, s is constant and L is a function of P alone. With the
// distance to the edge the lag is pulled to, u = 1 - s L/z in [0, 2], and the travel x = |dP|/z >= 0:
//       du/dx = -u^i   =>   int_{u}^{u0} du'/u'^i = x.
//   i = 1:      u = u0 exp(-x)
//   i != 1:     u^(1-i) = u0^(1-i) - (1-i) x, i.e. u = u0 (1 + c x u0^c)^(-1/c) with c = i - 1;
//               for i < 1 (c < 0) u reaches 0 after x* = u0^(1-i)/(1-i) and then stays 0 (L = s z: the
//               tip slips at full deflection); i = 0 gives u = max(u0 - x, 0), the clamp of Eq. (27);
//               for i > 1 (c > 0) u > 0 for ever and decays only algebraically, u ~ ((i-1) x)^(-1/(i-1)).
//   The drop u0 - u = u0 (1 - exp(-log1p(c x u0^c)/c)) is evaluated with log1p/expm1 (no cancellation for
//   small x, i.e. small rdisp). transfer(u0, x) is increasing in u0 with slope (u/u0)^i <= 1.
//
// zeta >= 1: P' >= 0, zero only at isolated instants, so P advances monotonically by 2 pi zeta per period
//   and u only ever decreases: u_(n+1) = transfer(u_n, 2 pi zeta/z) < u_n for u_n > 0, whose only fixed
//   point is u = 0 (for i > 1 reached only as n -> infinity, u_n^(1-i) = u_0^(1-i) + n (i-1) 2 pi zeta/z,
//   but the steady state is the limit). So L == z, F == F_c and r_x = 1 exactly, for every i >= 0.
//
// 0 <= zeta < 1 (the geometry of theta0_exact.hpp): s_ = sqrt(1 - zeta^2), alpha = arccos(zeta);
//   back phase:    tau = tau1 + h, tau1 = pi - alpha (P max), h in [0, 2 alpha],
//                  P - P(tau1) = d_b(h) = zeta (h - sin h) - s_ (1 - cos h) <= 0;
//   forward phase: tau = tau2 + h, tau2 = pi + alpha (P min), h in [0, 2 pi - 2 alpha],
//                  P - P(tau2) = d_f(h) = zeta (h - sin h) + s_ (1 - cos h) >= 0;
//   back travel B = 2 (s_ - zeta alpha), forward travel A = 2 pi zeta + B; b = B/z, a = A/z.
//   Unknown u1 = 1 - L(tau1)/z.
//   Back phase (s = -1, w = 1 + L/z):  w1 = 2 - u1, w2 = transfer(w1, b).
//   Forward phase (s = +1):            u2 = 2 - w2 = u1 + drop(w1, b), u1' = transfer(u2, a).
//   Periodicity u1' = u1 is the root on [0, 2] of
//       f(u1) = drop(2 - u1, b) - drop(u1 + drop(2 - u1, b), a)   (= period map - u1);
//   f has slope (u1'/u2)^i (w2/w1)^i - 1 <= 0 and f(0) >= 0 >= f(2), so bisection finds the root; for i > 0
//   the slope is < 0 (the period map is a contraction): the periodic state is unique and reached from any
//   start. f is a difference of two drops, each accurate to rounding relative to itself, so the root stays
//   accurate when a, b -> 0 (rdisp -> 0), where forming L1 = z (1 - u1) first would lose everything (z up
//   to 1e9). For i = 0 and zeta > 0, f(0) = 0 and f < 0 beyond: u1 = 0 (L(tau1) = z: the tip slips forward
//   in every period), as in theta0_exact.hpp.
//   r_x = (1/2pi) int L/z dtau
//       = (1/2pi) [ int_0^{2 alpha} (w(h) - 1) dh + int_0^{2pi - 2alpha} (1 - u(h)) dh ]
//       = (2/pi) asin(zeta) + (I_b - I_f)/(2 pi),
//   I_b = int_0^{2 alpha} transfer(w1, -d_b(h)/z) dh,
//   I_f = int_0^{2 pi - 2 alpha} transfer(u2, d_f(h)/z) dh,
//   where (2/pi) asin(zeta) = 1 - 2 alpha/pi is the rigid result, Eq. (10). The integrands are smooth in h
//   (analytic in the travel) except where u reaches 0 for i < 1: that instant is found by bisection and the
//   integral ends there. Panels are split where the travel x = 1/8, 1/4, ..., 2^17 so that each panel is
//   smooth on its own scale (quadratic start x ~ s_ h^2/(2z) after a reversal, algebraic tails for i > 1).
//
// zeta = 0 (no drift): i > 0: unique and symmetric, r_x = 0. i = 0: f == 0 on a whole interval when
//   rdisp < 1 (every L = c + sin tau with |c| <= z - 1 is periodic); the root u1 = 0 is taken, the limit
//   zeta -> 0+ (c = z - 1, r_x = 1 - rdisp), the convention of theta0_exact.hpp and of fv::ode_solve.
//
// Limits.
//   rdisp -> infinity: r_x -> (2/pi) asin(zeta) (Eq. (10)) for every i; the approach is slow for large i
//     (the lag after a reversal is still short of the edge by ~((i-1) |dP|/z)^(-1/(i-1))).
//   rdisp -> 0 (a, b -> 0, z >> amplitude): drop(u, x) = u^i x + O(x^2), so f = 0 becomes
//     (2 - u)^i B = u^i A: u = 2q/(1+q), q = (B/A)^(1/i), and L/z -> 1 - u everywhere, so
//     r_x -> (1 - q)/(1 + q) for i > 0 (i = 1: (A - B)/(A + B) = 2 pi zeta / int_0^{2pi}|P'| dtau), and
//     r_x -> 1 for i = 0 (q -> 0). compliant_limit_theta0() returns this.
//   int_0^{2pi}|P'| dtau = A + B = 4 (s_ + zeta asin zeta) for zeta < 1 (2 pi zeta for zeta >= 1):
//     mean|zeta + cos tau| = (2/pi)(zeta asin(zeta) + sqrt(1 - zeta^2)).
//
// Arguments: zeta finite >= 0, rdisp finite > 0, i finite >= 0, tau finite; otherwise std::invalid_argument.
// Accuracy: about 1e-14 absolute in r_x and in L/z; worse only as i -> 0+ at zeta = 0 (the slope of f is
// O(i) there, approaching the non-unique i = 0 case): ~1e-8 at i = 1e-8.
// ---------------------------------------------------------------------------------------------------------
#pragma once

namespace fv::ref {

// The periodic steady state for one (zeta, rdisp, i), computed once (the periodic state by bisection);
// lag() and rx() then cost one transfer / one quadrature.
class Theta0Steady {
  public:
    Theta0Steady(double zeta, double rdisp, double i);
    // Steady-state friction ratio r_x.
    double rx() const;
    // Lag L(tau) = P(tau) - T(tau) in units of x_v (F/F_c = L * rdisp); periodic with period 2 pi.
    double lag(double tau) const;
    // L(tau1)/z_ss (tau1 = pi - arccos(zeta): P at its maximum); 1 for zeta >= 1.
    double lag_at_back_start() const { return saturated_ ? 1.0 : w1_ - 1.0; }

  private:
    double zeta_, rdisp_, i_;
    bool saturated_ = false; // zeta >= 1: L == z_ss
    double w1_ = 2, u2_ = 0; // 1 + L(tau1)/z, 1 - L(tau2)/z
};

// Steady-state friction ratio r_x at theta = 0 for any shape exponent i >= 0.
double rx_theta0_general(double zeta, double rdisp, double i);

// Steady-state lag L(tau) in units of x_v (F/F_c = L * rdisp); periodic with period 2 pi.
double lag_theta0_general(double zeta, double rdisp, double i, double tau);

// The limit rdisp -> 0 of rx_theta0_general: 1 for i = 0 or zeta >= 1, else (1 - q)/(1 + q), q = (B/A)^(1/i).
double compliant_limit_theta0(double zeta, double i);

// mean over a period of |zeta + cos tau| = |P'|, closed form.
double mean_abs_velocity_theta0(double zeta);

} // namespace fv::ref
