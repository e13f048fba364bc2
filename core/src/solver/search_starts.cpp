// Where the search for the periodic steady state starts (see search_starts.hpp).
#include "search_starts.hpp"

#include "closed_forms.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv::solver {

// Where the search starts, in order. First, the unstretched asperity (rest's own start) where the vibration
// across the motion turns the tip's force more than the nearby limit allows: a transverse displacement
// r sin(theta) turns a force of size rho by r sin(theta) / rho, which adds ~ (r sin^2 theta / 2 rho)
// sin(2 tau) to v = e . P'; where that exceeds v's own swing (|cos theta|, or 2 zeta where |cos theta| <=
// zeta and the limit is the circle, rho = 1), the limit's premise (l hardly moves in a period) fails and
// the state lies at the scale of r (zeta 0.001, theta 90 deg, rdisp 0.01, i 0.5: |l| = 0.005, 43 -> 26
// periods; zeta 0.0086, theta 87.9 deg, rdisp 0.0062, i 5.8: the limit says 0.065, the state is at 0.0046,
// 34 -> 26). Then where the steady state is in a limit that is close by:
//   i = 0, rdisp <= 1, zeta < 1: the zeta -> 0 limit (lens_center), so no transient of stuck periods;
//   i > 0, rdisp < 0.1: the small-amplitude limit;
//   otherwise on the circle along P'(0) (the rigid model's direction), where the tip slips at once, and for
//   i > 1 the only place that is not approached algebraically.
// Then the others, for where the first leads nowhere (the limits assume zeta >> rdisp, the map may be far
// from linear between the start and the fixed point): on the circle along P'(0), on the circle along the
// mean motion e_x, and the unstretched asperity (zero force), where the zeta = 0 steady state is centred.
std::vector<Vec2> other_starts(const LagModel& m) {
    // Along P'(0); where the body momentarily stands still at tau = 0 (zeta = 1, theta = 180 deg), along
    // its mean velocity e_x.
    const Vec2 dp = m.dP(0);
    const Vec2 along = dp.norm() > 1e-6 * (1 + m.zeta) ? Vec2(dp / dp.norm()) : Vec2(1, 0);
    std::vector<Vec2> s;
    const double rho = m.i > 0 && m.r < 0.1 ? small_amplitude_rho(m) : 1.0;
    if (m.i > 0 && m.r < 1 && m.r * m.sth * m.sth > 2 * rho * std::max(std::abs(m.cth), 2 * m.zeta))
        s.push_back(Vec2(0, 0));
    if (m.i == 0 && m.r <= 1 && m.zeta < 1)
        s.push_back(lens_center(m));
    else if (m.i > 0 && m.r < 0.1)
        s.push_back(Vec2(rho, 0));
    s.push_back(along);
    s.push_back(Vec2(1, 0));
    s.push_back(Vec2(0, 0));
    return s;
}

// A start on the circle already settled: the tip on the circle forgets its angle at the rate r v
// (d(phi')/d(phi) = -r v, v = e . P' ~ |P'| while it tracks P'). So the circle's law integrated from the
// direction of P' at tau0 = 2 pi - T, with r int |P'| dtau >= kPrerollDecay over [tau0, 2 pi], ends within
// e^-kPrerollDecay of its initial error from the periodic state, if the tip stays on the circle all along
// (no event) and the state there is the attracting one. Taken only where T <= pi (rdisp >~ 5): a fraction of
// a period, with the state control alone (no sensitivity, no quadrature), in place of a whole Newton period
// from a cold start that is O(1/rdisp^2) off (on the i = 1 map at rdisp = 10: 3.07 -> 2.2 periods per cell,
// CPU -12%; at rdisp >= 1e3 the cold start is good enough already and T is tiny). Nothing otherwise.
constexpr double kPrerollDecay = 15;
std::optional<Vec2> prerolled_start(const LagModel& m, const PeriodRequest& rq) {
    double decay = 0, T = 0;
    constexpr double dt = 0.02;
    while (decay < kPrerollDecay) {
        if (T >= kPi) return std::nullopt;
        decay += m.r * m.dP(kTwoPi - T - 0.5 * dt).norm() * dt;
        T += dt;
    }
    const double tau0 = kTwoPi - T;
    const Vec2 dp = m.dP(tau0);
    if (!(dp.norm() > 0)) return std::nullopt;
    const PeriodRequest state_only{rq.atol, std::numeric_limits<double>::infinity(), false};
    const PeriodResult pr = solver::run_lag(m, Vec2(dp / dp.norm()), tau0, kTwoPi, state_only);
    if (!pr.ok || pr.start != Phase::circle || pr.end != Phase::circle || pr.events != 0) return std::nullopt;
    return Vec2(pr.l_end / pr.l_end.norm());
}

bool near_any(const std::vector<Vec2>& starts, const Vec2& l, double within) {
    return std::any_of(starts.begin(), starts.end(), [&](const Vec2& x) { return (x - l).norm() < within; });
}

} // namespace fv::solver
