// Exact steady state of the lumped Dahl asperity for parallel vibrations (theta = 0), i = 0 and i = 1.
// Independent reference for the tests: no time stepping anywhere; the only numerics are bracketed
// bisection on monotone scalar functions and adaptive Gauss-Legendre quadrature of smooth pieces.
//
// ---------------------------------------------------------------------------------------------------------
// Model (dimensionless, NOTES.md; Eqs. (13)-(16), (25)-(29), (33)-(34) with theta = 0)
//   P(tau) = zeta tau + sin tau,  P' = zeta + cos tau,  z := z_ss = 1/rdisp,  L := P - T,  F/F_c = L/z.
//   i = 1:  dL/dtau = P' (1 - sgn(P') L/z) = P' - |P'| L/z.
//   i = 0:  |L| <= z; L sticks (dL = dP) unless L = +z with P' > 0 or L = -z with P' < 0 (then dL = 0).
//           For monotone P this is exactly L_end = clamp(L_start + dP, -z, z).
//   r_x = (1/2pi) int_0^{2pi} L/z dtau over the periodic steady state (Eq. (33) with dtau -> 0).
//
// zeta >= 1: P' >= 0 (zero only at isolated points), so P moves forward 2 pi zeta per period.
//   i = 1: z - L = (z - L0) exp(-(P - P0)/z) contracts by exp(-2 pi zeta/z) per period -> L == z.
//   i = 0: every period L grows by 2 pi zeta until it reaches z, then stays -> L == z.
//   Hence L == z and r_x = 1 for both (also for zeta = 1 exactly).
//
// 0 <= zeta < 1: write s = sqrt(1 - zeta^2), alpha = atan2(s, zeta) = arccos(zeta) in (0, pi/2].
//   P' < 0 exactly on (tau1, tau2), tau1 = pi - alpha (P max), tau2 = pi + alpha (P min).
//   Back phase,    tau = tau1 + h, h in [0, 2 alpha]:
//     P - P(tau1) = d_b(h) = zeta (h - sin h) - s (1 - cos h) <= 0, decreasing;
//   forward phase, tau = tau2 + h, h in [0, 2 pi - 2 alpha]:
//     P - P(tau2) = d_f(h) = zeta (h - sin h) + s (1 - cos h) >= 0, increasing
//   (expand sin(tau_k + h) with cos tau_k = -zeta, sin tau1 = s, sin tau2 = -s: no cancellation near h = 0).
//   Back travel    B = -d_b(2 alpha) = 2 (s - zeta alpha) = 2 (alpha (1 - cos alpha) - (alpha - sin alpha)),
//   forward travel A = d_f(2 pi - 2 alpha) = 2 pi zeta + B.
//   Antiderivatives: int_0^H d_b = zeta C2(H) - s S1(H),  int_0^H d_f = zeta C2(H) + s S1(H),
//   with S1(H) = H - sin H and C2(H) = H^2/2 - (1 - cos H) (series for small H).
//
// i = 1 (exponential phases). While P is monotone, dL/dP = 1 -+ L/z, so L is a function of P:
//   back:    z + L = (z + L1) exp(d_b(h)/z),   L1 = L(tau1)
//   forward: z - L = (z - L2) exp(-d_f(h)/z),  L2 = L(tau2)
//   Periodicity: z + L2 = (z + L1) b and z - L1 = (z - L2) a, a = exp(-A/z), b = exp(-B/z); linear in L1, L2:
//     u := z - L1 = 2 z a (1 - b) / (1 - a b),  K_b := z + L1 = 2 z - u,  K_f := z - L2 = 2 z - K_b b.
//   a b = exp(-(A + B)/z) < 1 (B > 0 for zeta < 1): the period map is a contraction, so this periodic
//   state is unique and is reached from any start.
//   r_x = (1/2pi) [ (2 pi - 4 alpha) + (K_b/z) I_b - (K_f/z) I_f ],
//     I_b = int_0^{2 alpha} exp(d_b(h)/z) dh,  I_f = int_0^{2 pi - 2 alpha} exp(-d_f(h)/z) dh,
//   where (2 pi - 4 alpha)/(2 pi) = (2/pi) asin(zeta) is the rigid value, Eq. (10). I_b and I_f by adaptive
//   Gauss-Legendre on panels split where |d|/z = 1, 2, ..., 48 (roots by bisection): each panel is smooth and
//   the integrand drops by at most a factor e on it.
//
// i = 0 (elastic-Coulomb). For zeta > 0 the net forward slip per period must equal 2 pi zeta > 0, so the tip
//   slips forward in every period and L(tau1) = z. The back phase then sticks, L = z + d_b(h), until L = -z.
//   Case B <= 2z (sticks during the whole back travel), L2 = z - B:
//     back:    L = z + d_b(h) on [0, 2 alpha]
//     forward: L = z - B + d_f(h) on [0, h_f], L = z after; d_f(h_f) = B
//     r_x = 1 + (int_0^{2 alpha} d_b + int_0^{h_f} d_f - B h_f) / (2 pi z)          (linear in rdisp)
//   Case B > 2z (slips backwards too), L2 = -z:
//     back:    L = z + d_b(h) on [0, h_s], L = -z after; d_b(h_s) = -2z
//     forward: L = -z + d_f(h) on [0, h_f], L = z after; d_f(h_f) = 2z
//     r_x = (1/2pi) [ 2 pi - 4 alpha + 2 h_s - 2 h_f + (int_0^{h_s} d_b + int_0^{h_f} d_f) / z ]
//   The cases coincide at B = 2z (h_s = 2 alpha): r_x is continuous there. L is continuous at h_s, h_f, so
//   r_x is insensitive to first order in them. The periodic state is unique and reached from any start.
//
// Limits: rdisp -> infinity gives (2/pi) asin(zeta) for both i (Eq. (10)). rdisp -> 0 gives r_x -> 1 for
//   i = 0 and r_x -> 2 pi zeta / (2 pi zeta + 2 B) = 2 pi zeta / int_0^{2pi} |P'| dtau for i = 1.
//
// zeta = 0 (no drift). i = 1: unique, symmetric, r_x = 0. i = 0 with rdisp >= 1 (B = 2 >= 2z): unique,
//   symmetric, r_x = 0. i = 0 with rdisp < 1: every L = c + sin tau with |c| <= z - 1 is periodic, so the
//   steady state depends on the start. These functions return the limit zeta -> 0+ (c = z - 1,
//   r_x = 1 - rdisp), the only choice continuous in zeta; a start from rest (T(0) = P(0)) instead stays at
//   L = sin tau, r_x = 0.
//
// Arguments: zeta finite and >= 0, rdisp finite and > 0, tau finite; otherwise std::invalid_argument.
// Accuracy: about 1e-15 absolute in r_x and in L/z (lag: plus the rounding of reducing tau modulo 2 pi).
// ---------------------------------------------------------------------------------------------------------
#pragma once

namespace fv::ref {

// Steady-state friction ratio r_x for theta = 0: i = 0 (stiction, Eq. (27)) and i = 1 (Eq. (20)).
double rx_theta0_i0(double zeta, double rdisp);
double rx_theta0_i1(double zeta, double rdisp);

// Steady-state lag L(tau) = P(tau) - T(tau) in units of x_v (so F/F_c = L * rdisp); periodic, period 2 pi.
double lag_theta0_i0(double zeta, double rdisp, double tau);
double lag_theta0_i1(double zeta, double rdisp, double tau);

// Back travel per period B = P(tau1) - P(tau2) for zeta < 1 (0 for zeta >= 1). The i = 0 cases switch at
// rdisp = 2/B (B < 2 z_ss: the tip only sticks during the back travel).
double back_travel_theta0(double zeta);

} // namespace fv::ref
