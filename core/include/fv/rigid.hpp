// Rigid Coulomb model of Matunaga and Onoda (paper Section 2, Eqs. (1)-(11)).
#pragma once

namespace fv {

struct Ratio {
    double rx = 0; // time-averaged friction along v_b over F_c, Eq. (9)
    double ry = 0; // the same across v_b (the paper defines it via Eq. (4) but never shows it)
};

// r_x and r_y by adaptive Gauss-Kronrod quadrature of Eq. (9) (and its y-twin from Eq. (4)),
// with break points where the integrand has kinks, absolute accuracy better than 1e-12.
// zeta >= 0, theta in radians (any angle).
Ratio rigid_ratio(double zeta, double theta);

// Closed form Eq. (10): theta = 0.
double rigid_rx_parallel(double zeta);

// Closed form Eq. (11): theta = pi/2, with K(m) of parameter m = 1/(1+zeta^2).
double rigid_rx_perpendicular(double zeta);

} // namespace fv
