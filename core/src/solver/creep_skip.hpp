// The slow creep towards the circle (i > 1), skipped by projective steps (docs/model.md, "Slow creeps").
//
// Inside the circle with v = e . P' > 0 all period long, the deficit d = 1 - rho obeys d' = -r v d^i
// (Eq. (16) with s = +1), so u = d^(1-i) grows by (i - 1) r times the period's integral of v, nearly the same
// amount every period, while the angle settles onto a slow curve within a few periods. For i = 10 the motion
// from rest can creep like this for tens of thousands of periods (zeta 0.285, theta 90 deg, rdisp 2: about
// 14100) before v first dips below zero in a period and the motion settles within a few more. There is no
// fixed point on the way (rho grows every period), so nothing is lost by skipping ahead: the skip projects u
// linearly in the periods and the angle linearly in ln u, lets two true periods settle the projected point,
// and takes longer projections while those periods still creep, shorter ones once they do not. It stops a
// few periods before the motion leaves the creep, where following the motion goes on.
#pragma once

#include "reach.hpp"

namespace fv::solver {

// Whether the period from l0 (result pr) was a creep period: inside all along with no law change and v > 0 at
// its start, so that rho grew all period (i > 1 only, where the approach to the circle is algebraic).
bool creep_period(const LagModel& m, const Vec2& l0, const PeriodResult& pr);

struct CreepSkip {
    // Where the motion goes on: just past the creep's end where a law change was found ahead, else the last
    // settled point of the creep (next to the circle, or where the jumps' cap stopped it).
    Vec2 x{0, 0};
    double skipped = 0; // periods projected over (not integrated)
    int periods = 0;    // periods integrated
};

// Skips the creep through prev -> x (two successive sections of the motion, both creep periods).
CreepSkip skip_creep(const ReachSetup& s, Vec2 prev, Vec2 x);

} // namespace fv::solver
