// Verification of a fixed point of the period map found by the search, and the error estimate of the
// means reported from it (docs/model.md, "Error estimate").
#pragma once

#include "newton_search.hpp"

#include <vector>

namespace fv::solver {

struct Verified {
    Search search;          // the search's outcome (after a refinement at a tighter tolerance, if one ran)
    PeriodResult last;      // the reported period: its force integral gives r_x, r_y
    Vec2 l0{0, 0};          // where it starts (force units)
    bool converged = false; // the search converged (the error estimate then says how well)
    bool unstable = false;  // a multiplier of the period map beyond 1: not verified, not a result
    const char* failure = "";
    double integration_error = 0, steady_error = 0, error_estimate = 0;
    std::vector<OdeEvent> events; // of the reported period, when recorded
    std::vector<Sample> samples;  // of the reported period, when recorded
    int periods = 0;              // periods integrated by the verification (and a refinement)
};

// The search's last period again at another tolerance; the error estimate from the two; a refinement of
// the search at a 4x tighter tolerance where the integrated map's accuracy alone misses `tol`. `record`:
// the reported period is sampled (record_samples samples) and its events kept, for figures.
Verified verify_fixed_point(const Params& p, const LagModel& m, const Search& found, PeriodRequest rq,
                            double aim, double tol, bool record, int record_samples, int max_periods);

} // namespace fv::solver
