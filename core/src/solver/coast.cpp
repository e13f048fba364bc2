// Coasting along a slow approach (see coast.hpp).
#include "coast.hpp"

#include "plane_angles.hpp"

#include <algorithm>
#include <cmath>

namespace fv::solver {
namespace {

// Steps longer than this (force units) are not slow: following the motion takes few periods there anyway.
constexpr double kSlowStep = 0.02;
// Successive steps this well aligned (cosine of 11 deg); a motion that turns more is not projected.
constexpr double kAligned = 0.98;
// Steps that stay this well in proportion are projected as a linear motion: K times the step's relative
// change per period is at most this (the projection's error about half of it, as a part of the distance).
constexpr double kAccuracy = 0.25;
// Steps that shrink by a steady ratio q per period (the approach along the slowest multiplier) are summed as
// a geometric series over K periods, with q^K >= kCover: each projection covers at most 90 % of the rest of
// the way, so an error in q moves the landing point by a part of the 10 % left.
constexpr double kCover = 0.1;
constexpr int kMinJump = 8;       // shorter projections are not worth their three true periods
constexpr double kMaxJump = 1024; // periods per projection
constexpr int kMaxJumps = 64;

// Pinned to the circle (lag_phases.hpp).
bool on_circle(const Vec2& l) {
    return std::abs(l.norm() - 1) <= kPin;
}

// The projection K periods ahead of c, with K from the steps a -> b -> c; K = 0 where the motion is not slow
// and smooth enough. `geometric`: whether the steps' ratio may be taken as steady.
struct Projection {
    double K = 0;
    double q = 1;    // the ratio of successive step lengths used (1: projected as linear)
    Vec2 x{0, 0};    // the projected section
    Vec2 step{0, 0}; // the last step (a tangent vector on the circle), to see whether the motion turns back
};

Projection project(const Vec2& a, const Vec2& b, const Vec2& c, double noise, bool geometric) {
    Projection pj;
    const bool circle = on_circle(a) && on_circle(b) && on_circle(c);
    // On the circle, steps in its angle (the chord would leave the disc).
    const Vec2 d1 = circle ? Vec2(turn_angle(a, b), 0) : Vec2(b - a),
               d2 = circle ? Vec2(turn_angle(b, c), 0) : Vec2(c - b);
    const double n1 = d1.norm(), n2 = d2.norm();
    if (!(n2 > 0 && n1 > 0 && n2 <= kSlowStep && d1.dot(d2) >= kAligned * n1 * n2)) return pj;
    const double q = n2 / n1;
    double K = 0, sum = 0; // sum: the projected displacement in units of the last step
    // Geometric where the series covers most of its way within kMaxJump periods; steps that shrink more
    // slowly than that are as good as linear (and their ratio is mostly the integration's noise).
    const double K_geo = q < 1 ? std::floor(std::log(kCover) / std::log(q)) : kMaxJump;
    if (geometric && K_geo < kMaxJump) {
        if (n2 * q / (1 - q) <= noise) return pj; // the rest of the way is within the noise: nothing to skip
        K = K_geo;
        sum = q * (1 - std::pow(q, K)) / (1 - q);
        pj.q = q;
    } else {
        const double change = (d2 - d1).norm() / n2; // relative change of the step per period
        K = std::floor(std::min(kMaxJump, kAccuracy / std::max(change, 1e-300)));
        sum = K;
    }
    // In the plane at most half way to the circle, where the circle's law takes over.
    if (!circle && sum * n2 > 0.5 * (1 - c.norm())) {
        const double cut = 0.5 * (1 - c.norm()) / (sum * n2);
        K = std::floor(K * cut);
        sum *= cut;
        pj.q = 1;
    }
    if (K < kMinJump) return pj;
    pj.K = K;
    pj.x = circle ? rotated(c, sum * d2.x()) : Vec2(c + sum * d2);
    pj.step = circle ? Vec2(perp(c) * d2.x()) : d2;
    return pj;
}

} // namespace

Coast coast(const ReachSetup& s, const Vec2& a, const Vec2& b, const Vec2& c, double max_skip) {
    Coast out;
    out.a = a;
    out.b = b;
    out.c = c;
    const PeriodRequest rq = state_only(s);
    const double noise = arrival_noise(s);
    bool geometric = true;
    for (int jump = 0; jump < kMaxJumps && out.skipped < max_skip; ++jump) {
        const Projection pj = project(out.a, out.b, out.c, noise, geometric);
        if (pj.K == 0) break;
        Vec2 x = pj.x;
        classify(*s.m, 0, x);
        // Three true periods: the first lets a fast direction settle (the projection is along the slow one
        // only to first order), the other two give the next steps.
        Vec2 z[3] = {x, x, x};
        bool ok = true;
        for (int k = 0; k < 3 && ok; ++k) {
            if (k > 0) z[k] = z[k - 1];
            ok = advance(s, z[k], rq, nullptr);
            out.periods += 1;
        }
        if (!ok) break;
        // Landed where the motion no longer moves (to the noise): at a state, which the evidence takes from
        // here.
        const bool arrived = (z[2] - z[1]).norm() <= noise;
        // Turned back: the projection passed a state or a law change ahead; go on from c by following.
        if (!arrived && !((z[2] - z[1]).dot(pj.step) > 0)) break;
        // A geometric projection after which the steps shrink faster than its ratio (by more than a quarter
        // of 1 - q) went further than the motion goes: undone, and projected linearly from c instead. Steps
        // that shrink more slowly than that say it went less far (two slow directions with close multipliers,
        // or the approach still curving): the motion goes on from there.
        if (pj.q < 1 && !arrived) {
            const double q1 = (z[2] - z[1]).norm() / (z[1] - z[0]).norm();
            if (!(q1 >= pj.q - 0.25 * (1 - pj.q))) {
                geometric = false;
                continue;
            }
        }
        out.a = z[0];
        out.b = z[1];
        out.c = z[2];
        out.skipped += pj.K - 1; // the projected point stands for c's K-th successor
        ++out.jumps;
        geometric = true;
        if (arrived) break;
    }
    return out;
}

} // namespace fv::solver
