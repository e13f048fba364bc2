// A test hook, not a feature: makes results fail on purpose so that the tests of exit status 3 do not
// depend on finding parameters where the solver happens to fail (it is meant never to).
//
//   FV_TEST_FORCE_STATUS=REASON        every result computed by ratio, sweep, trace, render (ratio and trace
//                                      tables) and fit gets status REASON after it was computed
//   FV_TEST_FORCE_STATUS=REASON@ZETA   only results at this zeta (within 1e-9; fit: every candidate)
//
// REASON is not_converged, integration_failed or non_finite (the last also sets r_x and r_y to NaN, as a
// real non-finite result would show). Unset or empty: nothing happens. Any other value is a usage error,
// so that a typo in a test cannot pass silently. Not in --help or the README on purpose; tests/test_cli.cpp
// uses it.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/fit.hpp"
#include "fv/sweep.hpp"

#include <vector>

namespace fv::cli {

void apply_test_hook(SweepPoint& row);
void apply_test_hook(std::vector<SweepPoint>& rows);
// A figure's table: its ratio rows, or the status of its steady period (trace tables, which keep no zeta:
// only without @ZETA).
void apply_test_hook(TableData& table);
// Marks every model evaluation of every candidate as not steady (FitCandidate::unsteady = evaluations).
void apply_test_hook(FitResult& fit);

} // namespace fv::cli
