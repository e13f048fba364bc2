// Steady states known in closed form or from a limit, where the period map cannot or need not be searched
// (docs/model.md, "zeta = 0" and "Small amplitude"):
//   zeta = 0, i = 0, rdisp <= 1: the lens centre, never slipping;
//   rdisp < kTinyR: the small-amplitude limit, corrected to first order by the solver at two anchors.
#pragma once

#include "lag_phases.hpp"

#include "fv/ode_solver.hpp"

namespace fv::solver {

// zeta = 0, i = 0, rdisp <= 1: the point of the lens of never-slipping offsets farthest along +x.
Vec2 lens_center(const LagModel& m);
OdeSolution lens_solution(const Params& p, const LagModel& m, const OdeOptions& opt);

// The small-amplitude limit's |F| (rdisp -> 0, i > 0): the root rho of the period's force balance, 1 when the
// tip stays on the circle.
double small_amplitude_rho(const LagModel& m);

// Below this rdisp one period moves the force l = rdisp L by less than ~1e-9 of its size: the period map,
// integrated in force units at |l| ~ 1, then drowns in rounding (at rdisp < 1e-16 the motion of a period
// is below the last bit of l, and 1/rdisp overflows below 5.6e-309). There the result is the
// small-amplitude limit, checked against and corrected by the solver itself at two anchors.
inline constexpr double kTinyR = 1e-9;
OdeSolution small_amplitude_solution(const Params& p, const LagModel& m, const OdeOptions& opt);

} // namespace fv::solver
