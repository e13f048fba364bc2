// A seam for tests, not a feature: functions applied to every result the command line computed, before it is
// written. The shipped executable installs none (and reads no test variable). The test build's
// `frictionviz_forced` (tests/tools/force_status_hook.cpp) installs ones that make results fail on purpose,
// so that the tests of exit status 3 do not depend on finding parameters where the solver happens to fail
// (it is meant never to):
//
//   FV_TEST_FORCE_STATUS=REASON        every result computed by ratio, sweep, trace, render (ratio and trace
//                                      tables) and fit gets status REASON after it was computed
//   FV_TEST_FORCE_STATUS=REASON@ZETA   only results at this zeta (within 1e-9; fit: every candidate)
#pragma once

#include "fv/figure_data.hpp"
#include "fv/fit.hpp"
#include "fv/sweep.hpp"

#include <vector>

namespace fv::cli {

struct ResultHooks {
    void (*row)(SweepPoint&) = nullptr;
    // A figure's table: its ratio rows, or the status of its steady period (trace tables, which keep no
    // zeta).
    void (*table)(TableData&) = nullptr;
    void (*fit)(FitResult&) = nullptr;
};

// The hooks in effect (none unless a test executable installed them before run_cli).
ResultHooks& result_hooks();

inline void apply_test_hook(SweepPoint& row) {
    if (const auto f = result_hooks().row) f(row);
}
inline void apply_test_hook(std::vector<SweepPoint>& rows) {
    if (const auto f = result_hooks().row)
        for (SweepPoint& r : rows) f(r);
}
inline void apply_test_hook(TableData& table) {
    if (const auto f = result_hooks().table) f(table);
}
inline void apply_test_hook(FitResult& fit) {
    if (const auto f = result_hooks().fit) f(fit);
}

} // namespace fv::cli
