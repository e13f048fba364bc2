// Steady state of the lumped Dahl asperity riding on the circle |P - T| = z_ss (full deflection, the tip
// slipping all the time): the pursuit curve of a tip on a leash of length z_ss. Independent reference for the
// solver tests at large rdisp and any vibration angle 0 < theta < pi, for EVERY shape exponent i. It does not
// use fv:: code.
//
// ---------------------------------------------------------------------------------------------------------
// Model (dimensionless as in docs/model.md, "Parameters"): P(tau) = (zeta tau + sin tau cos theta,
// sin tau sin theta), L = P - T, z = |L|, e = L/z, F/F_c = L/z_ss. The scheme's dtau -> 0 limit
// (Eqs. (18)-(22)): T moves on the line TP, T' = k e, so the part of L' across e is the part of P' across
// e, and the deflection follows Eq. (16) with v = e . P' (Eq. (19) in the limit):
//     z e' = P' - (P' . e) e,      z' = v (1 - sgn(v) z/z_ss)^i
// (i = 0: Eq. (25), z' = 0 at z = z_ss while v >= 0).
// On z = z_ss with v >= 0 the deflection law gives z' = 0 for every i >= 0, so z = z_ss is kept and only the
// direction moves: with e = (cos phi, sin phi),
//     z_ss phi' = -P'_x sin phi + P'_y cos phi,   i.e.   e' = rdisp (P' - (P' . e) e).
// If this angle equation has a periodic solution along which v = P' . e > 0 at every instant, then
// (z = z_ss, phi) is a periodic steady state of the full law for every i, and it attracts: across the circle
// the angle error obeys delta' = -rdisp v delta, and a deflection deficit d = 1 - z/z_ss obeys
// d' = -rdisp v d^i <= 0 (finite time for i < 1, exponential for i = 1, algebraic for i > 1: for i > 1 a
// time-stepping solver approaches it only like n^(-1/(i-1)) in the number of periods n, but the limit is this
// state). Then r_x = mean cos phi and r_y = mean sin phi do not depend on i.
// For zeta > 0 and 0 < theta < pi, P' = (zeta, 0) + cos tau (cos theta, sin theta) never vanishes and runs
// back and forth on a segment that misses the origin: e has no net winding, phi is 2 pi periodic.
// rdisp -> infinity: e -> P'/|P'| (the rigid model, Eq. (9)); e = t - (z_ss/|P'|) dt/dtau + O(z_ss^2) with
// t = P'/|P'|. The first-order term is odd in tau (P' is even in tau) and averages to zero, so
// r - r_rigid = O(1/rdisp^2).
//
// Numerics: the unit vector e (no trigonometry of phi) by the classical Runge-Kutta method with N steps per
// period, N a power of two with rdisp (1 + zeta) (2 pi / N) <= 1/2 (well inside the stability interval of the
// stiff relaxation across the circle) and at least 2^12; started at e = t(0), run period after period until e
// repeats to 1e-14; r by the trapezoidal rule on the steps (spectrally accurate for a smooth periodic
// integrand). The same at 2N gives the error estimate |r(2N) - r(N)| (fourth order: the true error of r(2N)
// is ~1/16 of it); the finer value is returned.
// Validity: min_v = min over the period of P' . e must be > 0 (else the tip would leave the circle and the
// state is not this one); callers check it.
// ---------------------------------------------------------------------------------------------------------
#pragma once

namespace fv::ref {

struct CirclePursuit {
    double rx = 0, ry = 0;
    double min_v = 0;          // min over the steady period of v = e . P'; the result is valid only if > 0
    double error_estimate = 0; // |r(2N) - r(N)| over rx, ry
    int steps_per_period = 0;  // the finer N
    int periods = 0;           // periods run at the finer N
};

// zeta > 0, 0 < theta < pi (radians), rdisp > 0; otherwise std::invalid_argument.
CirclePursuit circle_pursuit(double zeta, double theta, double rdisp);

} // namespace fv::ref
