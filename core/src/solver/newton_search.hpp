// Newton's method for a fixed point of the period map from one starting force (docs/model.md, "The periodic
// steady state"): on the circle's angle where the period starts on the circle, damped Newton in the plane
// elsewhere, stuck periods skipped in closed form (i = 0).
#pragma once

#include "period_map.hpp"

#include <limits>

namespace fv::solver {

// A start (other than the last) is given up when the residual has not halved for this many periods (12
// before: 8 changed no status over the domain grids and 9000 random points from both starts, and made 458 of
// them faster, two slower).
inline constexpr int kGiveUp = 8;

// What one search did and where it stopped.
struct Search {
    PeriodResult last; // the last period integrated, from last_l0
    Vec2 last_l0{0, 0};
    bool have_last = false;
    bool converged = false;
    bool gave_up = false;
    double dist = std::numeric_limits<double>::infinity(); // estimated |l0 - l*| (force units)
    const char* failure = "";
    SteadyStatus status = SteadyStatus::converged; // integration_failed when a period could not be integrated
    int periods = 0, newton_steps = 0, plain_steps = 0;
    long periods_skipped = 0;
    bool on_circle = false;
};

// One search for the fixed point of the period map from the force l0. Gives up after `max_periods`
// integrated periods, after kMaxIterations updates, and, when `give_up` > 0, as soon as the residual
// |Phi(l) - l| has not halved for `give_up` periods in a row (this start leads nowhere: Newton cycles
// between the laws, or creeps along a direction the map hardly changes). `aim` is the target distance of
// the means (force units).
Search search_from(const Params& p, const LagModel& m, Vec2 l0, const PeriodRequest& rq, double aim,
                   int max_periods, int give_up);

} // namespace fv::solver
