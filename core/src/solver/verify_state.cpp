// Verification of a fixed point and its error estimate (see verify_state.hpp).
#include "verify_state.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv::solver {

Verified verify_fixed_point(const Params& p, const LagModel& m, const Search& found, PeriodRequest rq,
                            double aim, double tol, bool record, int record_samples, int max_periods) {
    const double r = p.rdisp;
    Verified v;
    v.search = found;
    PeriodResult& last = v.last;
    Vec2& last_l0 = v.l0;
    bool& converged = v.converged;
    const char*& failure = v.failure;
    bool& unstable = v.unstable;
    double map_shift = 0, pin = 0;
    // Verification: the final period again at another tolerance, from the same start. Where no period is
    // recorded (ratio, sweep, the map) the second run is 4x looser and the search's own last period is
    // reported: the check costs ~0.8 of a period instead of ~1.26 (Radau IIA's steps go as tol^(-1/6)).
    // Where the period is recorded for a figure the second run is 4x tighter and is the one reported (its
    // samples are the figure's). Either way the two runs' difference d measures the reported run's error
    // with the same margin: with errors e(4a) = k e(a), d / e(reported) = k - 1 for both choices (~3 where
    // the error follows the tolerance linearly). Parts of the error estimate:
    //   integration: the means' difference between the two runs;
    //   map_shift: the search found the fixed point of the period map as integrated at the search's
    //     tolerance, whose end state is off by e(a), taken as d_end: 4/3 of the runs' difference where the
    //     tighter run is reported ((4/3)(1 - 1/k) e(a)), half of it where the looser one checks
    //     ((k - 1)/2 e(a): at least the former for k >= 3; k = 4 where the error follows the tolerance
    //     linearly). The fixed point moves by that through (DPhi - I)^-1: large where the map is nearly
    //     neutral (i > 1 creeping towards the circle, where the integration error may outweigh the drift and
    //     make a fixed point that is not there);
    //   steady: the reported means start dist + map_shift away from l*. To first order that moves them by
    //     G/(2 pi) times the offset (G = int dl/dl0 dtau over the period, from the variational equations):
    //     small where the flow forgets its start quickly. Twice that for safety; beyond the linear regime,
    //     twice the offset (the flow does not expand differences of the force);
    //   pinning onto the circle drops the radial remainder: kPin by construction (i > 0), more only where
    //     an event had to be taken a hair early or late (the tip grazing the circle just as v turns).
    // When the estimate misses the tolerance only because the integrated map is not accurate enough, the
    // search goes on once from where it stopped at a 4x tighter tolerance and is verified again.
    for (int round = 0;; ++round) {
        last = v.search.last;
        last_l0 = v.search.last_l0;
        converged = v.search.converged;
        failure = v.search.failure;
        map_shift = 0;
        const bool check_looser = !record;
        const double factor = check_looser ? 4.0 : 0.25;
        PeriodRequest check{factor * rq.atol, factor * rq.atol_force, false};
        check.max_step = rq.max_step;
        // A period integrated in steps of the longest length throughout (smooth, e.g. the tip on the
        // circle far from any law change) would be integrated in the same steps at the looser tolerance,
        // and the runs' difference would not show the quadrature's error: there the check halves them.
        // Where only most steps are at the cap the looser run takes nearly as many steps as the reported
        // one (a looser tolerance alone takes ~4^(1/5) = 1.3x fewer): then it is run again at half the cap
        // (zeta 50, theta 179.9 deg, rdisp 3000, i 0.5: r_y's estimate 1.0e-12 against an error of 8.9e-11).
        if (static_cast<double>(last.steps) <= kTwoPi / rq.max_step + 2) check.max_step = 0.5 * rq.max_step;
        v.events.clear();
        v.samples.clear();
        if (record) { // the reported period is this run: its samples and events are the figure's
            check.events = &v.events;
            check.samples = &v.samples;
            check.n_samples = std::max(1, record_samples);
            check.params = &p;
            v.samples.reserve(static_cast<std::size_t>(check.n_samples));
        }
        // A periodic state that nearby motions leave (a Floquet multiplier of the period map beyond 1) is a
        // solution of the fixed-point equation but not what the body settles into: there the motion does
        // not settle at all (seen at zeta = 0.075, theta = 30 deg, rdisp = 100, i = 10). Not a result,
        // however accurately it is found: neither verified (unless its period is recorded for a figure)
        // nor refined; its error estimate then covers the search's distance alone.
        unstable = converged &&
                   (Eigen::Matrix2d::Identity() + last.E).eigenvalues().cwiseAbs().maxCoeff() > 1 + 1e-6;
        const bool verify = !unstable || record;
        PeriodResult ti;
        if (verify) {
            ti = solver::run_lag(m, last_l0, 0, kTwoPi, check);
            ++v.periods;
            if (ti.ok && check_looser && check.max_step == rq.max_step && 10 * ti.steps >= 9 * last.steps) {
                check.max_step = 0.5 * rq.max_step;
                ti = solver::run_lag(m, last_l0, 0, kTwoPi, check);
                ++v.periods;
            }
        }
        // The reported run's own pinning (a looser check run's larger drop shows in the runs' difference).
        const double pin_drop = check_looser ? last.pin_drop : std::max(last.pin_drop, ti.pin_drop);
        if (!verify) {
            v.integration_error = 0;
        } else if (ti.ok) {
            v.integration_error = (ti.force_integral - last.force_integral).cwiseAbs().maxCoeff() / kTwoPi;
            const Vec2 d_end = (check_looser ? 0.5 : 4.0 / 3.0) * (ti.dL - last.dL);
            if (converged && d_end.squaredNorm() > 0) {
                const Eigen::JacobiSVD<Eigen::Matrix2d> svd(last.E,
                                                            Eigen::ComputeFullU | Eigen::ComputeFullV);
                const Vec2 sv = svd.singularValues();
                const Vec2 c = svd.matrixU().transpose() * d_end;
                double shift = 0;
                for (int k = 0; k < 2; ++k)
                    shift += c[k] == 0 ? 0 : c[k] * c[k] / std::max(sv[k] * sv[k], 1e-300);
                map_shift = r * std::sqrt(shift);
            }
            if (!check_looser) {
                last.force_integral = ti.force_integral;
                last.steps = ti.steps;
            }
        } else {
            v.integration_error = std::numeric_limits<double>::infinity();
            if (!*failure) failure = ti.failure;
        }
        const double offset = v.search.dist + map_shift;
        const double gain = last.G.norm() / kTwoPi;
        v.steady_error = 2 * offset * (offset <= 1e-3 && std::isfinite(gain) ? gain : std::max(1.0, gain));
        pin = std::max(p.i > 0 && last.visited_circle ? solver::kPin : 0, pin_drop);
        v.error_estimate = v.steady_error + v.integration_error + pin + 1e-14;
        const double from_map = 2 * map_shift * (offset <= 1e-3 ? gain : 1.0) + v.integration_error;
        const bool refine = round == 0 && converged && ti.ok && !unstable && !(v.error_estimate <= tol) &&
                            from_map > 0.5 * v.error_estimate && v.periods < max_periods;
        if (!refine) break;
        rq.atol *= 0.25;
        rq.atol_force *= 0.25;
        // Given up like any search once it makes no progress (the first result is kept then): it had no such
        // rule and could spend the whole budget cycling next to the circle, where the map is a slow
        // translation (zeta 0, theta 90 deg, rdisp 1e-5, i 0.5 from sliding: 60 and more periods).
        Search s = search_from(p, m, last_l0, rq, aim, max_periods - v.periods, kGiveUp);
        v.periods += s.periods;
        if (!s.converged || s.status != SteadyStatus::converged) break; // keep the verified first result
        s.newton_steps += v.search.newton_steps;
        s.plain_steps += v.search.plain_steps;
        s.periods_skipped += v.search.periods_skipped;
        v.search = s;
    }
    return v;
}

} // namespace fv::solver
