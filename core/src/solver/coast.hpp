// Coasting along a slow approach: projective steps over the periods of a motion that changes little from one
// period to the next (docs/model.md, "Slow approaches").
//
// Where the period map's slowest multiplier is near 1 (0.995 at zeta 0.001, theta 30 deg, rdisp 1e-3, i = 2;
// 0.9994 at zeta 0.001, theta 60 deg, rdisp 0.1, i = 0), the motion from a start takes hundreds to thousands
// of periods to get near its state, each step a little shorter than the last and in nearly the same
// direction. Newton's method finds the state in a few periods, but the evidence that the start's motion
// reaches it (reach.cpp) needs a point of the motion close to it. Coasting gets there without integrating
// every period: from three successive sections a, b, c it projects c + K (c - b), K periods ahead, with K
// such that the step's change per period, kept up over K periods, stays a small part of it (the projection's
// error is then a small part of the distance covered), and lets three true periods from the projected point
// give the next three sections (the first settles a fast direction). A projection that lands where the motion
// turns back (it passed a state, or a law change ahead reversed it) is undone, and following the motion
// period by period goes on from c. On the circle (all three sections there, |l| = 1) the projection is along
// the circle's angle.
#pragma once

#include "reach.hpp"

namespace fv::solver {

struct Coast {
    Vec2 a{0, 0}, b{0, 0}, c{0, 0}; // the last three successive sections (c the latest)
    double skipped = 0;             // periods projected over (not integrated)
    int periods = 0;                // periods integrated
    int jumps = 0;
};

// Coasts from the successive sections a -> b -> c of the motion, over about max_skip periods at most; returns
// them unchanged where the motion is not slow and smooth enough to project.
Coast coast(const ReachSetup& s, const Vec2& a, const Vec2& b, const Vec2& c, double max_skip);

} // namespace fv::solver
