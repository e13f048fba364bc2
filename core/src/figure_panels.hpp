// Panels of the figures that are not r_x(zeta) curves or steady periods of the Dahl model: the mechanism of
// the rigid model (Fig. 4) and the friction-displacement curves of the Dahl law (Fig. 6). Internal to
// compute_figure (figure_data.cpp).
#pragma once

#include "fv/figure_data.hpp"

namespace fv {

// Friction on the body over F_c, Eq. (2): opposite to the velocity, magnitude 1 (0 where v = 0).
Vec2 coulomb(const Vec2& v);

// Fig. 4: the rigid model over one period at spec.zeta, spec.theta (Eqs. 1-4, 9): (left) the velocity
// v(tau)/v_v and the friction F(tau)/F_c = -v/|v| at tau = k pi/4, with their loci and the mean friction (in
// the plane; or, where the vibration runs along v_b, their components along it up a time axis);
// (right) the friction against v_b, -F_x/F_c (Eq. 3), over the period with its mean r_x (Eq. 9).
// Table: tau, v_x, v_y, F_x, F_y at 1024 instants.
void mechanism_panels(const MechanismFigure& spec, FigureData& fig);

// Where the vibration runs along v_b (mechanism_parallel) the left panel draws each instant tau = k pi/4 as a
// row up a time axis: the velocity's arrow this far (in tau) above the row, the friction's as far below.
inline constexpr double kMechanismRowGap = 0.14;

// Fig. 6: F/F_c against x/z_ss for each exponent of spec.exponents, from the model's update (Eqs. 17-27,
// dahl_update) stepped along x in steps of kDahlCurveStep z_ss: (a) loading from rest, v > 0 (the paper's
// Fig. 6); (b) the cycle 0 -> +3 -> -3 -> +3 z_ss (unloading, reversal, reloading).
// Table: i, leg (1: 0 -> 3, 2: 3 -> -3, 3: -3 -> 3), x/z_ss, F/F_c.
void dahl_curve_panels(const DahlCurvesFigure& spec, FigureData& fig);

inline constexpr double kDahlCurveStep = 1e-4; // in units of z_ss
inline constexpr double kDahlCurveTurn = 3;    // turning points of the cycle, +-3 z_ss

} // namespace fv
