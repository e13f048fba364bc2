// Where the search for the periodic steady state starts (docs/model.md, "Start").
#pragma once

#include "period_map.hpp"

#include <optional>
#include <vector>

namespace fv::solver {

// Where the search starts, in order. First the unstretched asperity where the vibration across the motion
// turns the force more than the small-amplitude limit allows (search_starts.cpp). Then where the steady state
// is in a limit that is close by:
//   i = 0, rdisp <= 1, zeta < 1: the zeta -> 0 limit (lens_center), so no transient of stuck periods;
//   i > 0, rdisp < 0.1: the small-amplitude limit;
//   otherwise on the circle along P'(0) (the rigid model's direction), where the tip slips at once, and for
//   i > 1 the only place that is not approached algebraically.
// Then the others, for where the first leads nowhere (the limits assume zeta >> rdisp, the map may be far
// from linear between the start and the fixed point): on the circle along P'(0), on the circle along the
// mean motion e_x, and the unstretched asperity (zero force), where the zeta = 0 steady state is centred.
std::vector<Vec2> other_starts(const LagModel& m);

// A start on the circle already settled: the tip on the circle forgets its angle at the rate r v
// (d(phi')/d(phi) = -r v, v = e . P' ~ |P'| while it tracks P'). So the circle's law integrated from the
// direction of P' at tau0 = 2 pi - T, with r int |P'| dtau >= kPrerollDecay over [tau0, 2 pi], ends within
// e^-kPrerollDecay of its initial error from the periodic state, if the tip stays on the circle all along
// (no event) and the state there is the attracting one. Taken only where T <= pi (rdisp >~ 5): a fraction of
// a period, with the state control alone (no sensitivity, no quadrature), in place of a whole Newton period
// from a cold start that is O(1/rdisp^2) off (on the i = 1 map at rdisp = 10: 3.07 -> 2.2 periods per cell,
// CPU -12%; at rdisp >= 1e3 the cold start is good enough already and T is tiny). Nothing otherwise.
std::optional<Vec2> prerolled_start(const LagModel& m, const PeriodRequest& rq);

// Whether l is closer than `within` (force units) to one of the starts: the same start, searched or listed
// once.
bool near_any(const std::vector<Vec2>& starts, const Vec2& l, double within);

} // namespace fv::solver
