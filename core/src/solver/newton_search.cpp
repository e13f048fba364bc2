// Newton's method for a fixed point of the period map (see newton_search.hpp, docs/model.md).
#include "newton_search.hpp"

#include "closed_forms.hpp"
#include "plane_angles.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>
#include <vector>

namespace fv::solver {
namespace {

constexpr int kMaxIterations = 100;

// What one search is asked, fixed while it runs.
struct SearchProblem {
    const Params& p;
    const LagModel& m;
    const PeriodRequest& rq;
    double aim;        // target distance of the means (force units)
    double r;          // p.rdisp: x_v units to force units
    double tol_newton; // force units
    int max_periods;
    int give_up; // > 0: periods without the residual halving before the start is given up
};

// Damped Newton in the plane (Deuflhard's natural monotonicity test): a trial point l_ref + lambda step is
// accepted when the correction it needs, measured with the reference point's inverse Jacobian, has shrunk;
// else lambda is halved. The reference point is the last point whose full Newton correction was computed.
struct NewtonRef {
    bool valid = false;
    Vec2 l{0, 0}, delta{0, 0}, l_end{0, 0}; // point, its Newton correction (x_v), Phi(point) (force)
    int events = 0;                         // law changes in its period
    Eigen::Matrix2d Jinv = Eigen::Matrix2d::Zero();
};

// What the search carries from one period to the next.
struct SearchState {
    Search out;
    Vec2 l0{0, 0}; // the start of the next period (force units)
    // The give-up test: the smallest residual so far and the periods since it halved.
    double best_residual = std::numeric_limits<double>::infinity();
    int since_best = 0;
    NewtonRef ref;
    double lambda = 1;
    // Trials taken as the reference for their side of a law change (retreat_from_trial): twice at most, for
    // the laws' sides can send Newton's steps round a cycle (zeta 0.144, theta 34 deg, rdisp 32, i 5: periods
    // with 0, 2 and 4 law changes in turn).
    int law_switches = 0;
    // The previous plane correction, for Aitken's acceleration.
    Vec2 prev_delta{0, 0};
    bool have_prev_delta = false;
    // The noise-floor test: the smallest correction so far, the tries since it halved, the previous one.
    double best_corr = std::numeric_limits<double>::infinity();
    int stalled = 0;
    double prev_corr = std::numeric_limits<double>::infinity();
    // Switching between the circle's angle and the plane.
    int circle_retries = 0;
    bool allow_snap = true;
    bool creep_snapped = false;
    // Circle starts whose period left the circle for the interior: a snap onto the circle from the plane must
    // not go back to one of them (it would repeat the same two periods, the circle's and the plane's: seen
    // at zeta = 0.0042, theta = 90 deg, rdisp = 1e4, i = 10).
    std::vector<Vec2> circle_left;
};

// Whether a step leaves the search running (the next period from the new start) or ends it.
enum class After { next_period, stop };

// One integrated period and the phase it started in.
struct Period {
    Phase start;
    PeriodResult result;
};

SearchState start_state(Vec2 l0) {
    SearchState s;
    s.l0 = l0;
    s.out.last_l0 = l0;
    return s;
}

// The means reported are those of a period started `dist` from the fixed point l*: to first order they are
// off by gain * dist (gain = |G| / 2 pi, G = int dl(tau)/dl(0) dtau from the variational equations: small
// where the flow forgets its start quickly, a stiff tip on the circle). So a search on the circle may stop
// once gain * dist is a small part of the aim (0.15 aim; the error estimate counts it twice), while dist^2
// stays below 0.1 aim (the linearisation), but only where the period keeps to one law with a margin: on the
// circle all along, v = e . P' >= 0.05 (1 + zeta) at every step's points. A start dist away turns the force
// by at most dist (the circle's angle map contracts), so v moves by at most (1 + zeta) dist there: the
// period from l* keeps the same law. Without that margin the fixed point may lie across a law change (the
// true period leaves the circle: zeta = 0.933, theta = 13 deg, rdisp = 1, i = 1 was 6e-6 off with this rule
// everywhere), and the search goes on to tol_newton.
double stop_at(const SearchProblem& pb, const PeriodResult& pr) {
    const double gain = pr.G.norm() / kTwoPi;
    const bool one_law = pr.start == Phase::circle && pr.end == Phase::circle && pr.events == 0 &&
                         pr.v_min_circle >= 0.05 * (1 + pb.p.zeta);
    if (!one_law || !(gain > 0) || !std::isfinite(gain)) return pb.tol_newton;
    return std::max(pb.tol_newton, std::min(std::sqrt(0.1 * pb.aim), 0.15 * pb.aim / gain));
}

bool left_before(const SearchState& s, const Vec2& l, double within = 1e-9) {
    return std::any_of(s.circle_left.begin(), s.circle_left.end(),
                       [&](const Vec2& c) { return (c - l).norm() <= within; });
}

// Near the fixed point the periods' integration noise limits what the corrections can show: when they stop
// shrinking, the search stops and its last correction (`corr`, corrected for a slow linear rate) is the
// distance it reports.
bool stalled_at_noise(const SearchProblem& pb, SearchState& s, double& corr) {
    // Small corrections that stop shrinking (by 2x within 3 tries) are rounding and integration noise.
    // Unless they shrink steadily (a slow linear rate q, which noise does not show): then the distance
    // is corr / (1 - q), and with q near 1 the search is not done.
    const double q = s.prev_corr > 0 ? corr / s.prev_corr : 1;
    s.prev_corr = corr;
    if (corr < 0.5 * s.best_corr) {
        s.best_corr = corr;
        s.stalled = 0;
        return false;
    }
    if (!(corr <= 1e3 * pb.aim && ++s.stalled >= 3)) return false;
    if (q < 1) corr /= 1 - std::min(q, 0.999);
    return true;
}

// The next period from s.l0 (pulled onto the circle when outside), recorded as the search's last; none when
// the budget is spent or the period could not be integrated.
std::optional<Period> integrate_period(const SearchProblem& pb, SearchState& s, [[maybe_unused]] int iter) {
    if (s.out.periods >= pb.max_periods) {
        s.out.failure = "period budget exhausted";
        return std::nullopt;
    }
    Vec2 ls = s.l0;
    const Phase start = solver::classify(pb.m, 0, ls);
    s.l0 = ls;
    Period period{start, solver::run_lag(pb.m, s.l0, 0, kTwoPi, pb.rq)};
    const PeriodResult& pr = period.result;
    ++s.out.periods;
#ifdef FV_SOLVER_TRACE
    std::fprintf(
        stderr,
        "iter %d start=%d end=%d l0=(%.12g,%.12g) |l0|=%.15g dL=(%.3e,%.3e) steps=%ld ev=%d lambda=%g\n",
        iter, (int)start, (int)pr.end, s.l0.x(), s.l0.y(), s.l0.norm(), pr.dL.x(), pr.dL.y(), pr.steps,
        pr.events, s.lambda);
#endif
    if (!pr.ok) {
        s.out.failure = pr.failure;
        s.out.status = SteadyStatus::integration_failed;
        return std::nullopt;
    }
    s.out.last = pr;
    s.out.last_l0 = s.l0;
    s.out.have_last = true;
    return period;
}

// Whether this start leads nowhere: the residual has not halved for give_up periods in a row.
bool gives_up(const SearchProblem& pb, SearchState& s, const PeriodResult& pr) {
    if (pb.give_up <= 0) return false;
    const double residual = pb.r * pr.dL.norm();
    if (residual < 0.5 * s.best_residual) {
        s.best_residual = residual;
        s.since_best = 0;
        return false;
    }
    if (++s.since_best < pb.give_up) return false;
    s.out.gave_up = true;
    s.out.failure = "no progress from this start";
    return true;
}

// Whether the period came back where it started, to the rounding of a period's displacements (e.g. zeta = 0
// with i = 0: the tip reaches the circle just at the period's end), whatever the law at the section. The
// distance is that residual through F' (pseudo-inverse): where F' is nearly singular too (a degenerate fixed
// point, i > 1 next to the circle) this is no evidence, and the search goes on.
bool back_at_start(const SearchProblem& pb, SearchState& s, const PeriodResult& pr) {
    if (!(pr.dL.norm() <= 64 * std::numeric_limits<double>::epsilon() * (1 + kTwoPi * (1 + pb.p.zeta))))
        return false;
    const Eigen::JacobiSVD<Eigen::Matrix2d> svd(pr.E);
    const double smin = svd.singularValues()[1], smax = svd.singularValues()[0];
    const double d = smax > 0 && smin > 1e-9 * smax ? pb.r * pr.dL.norm() / smin : pb.r * pr.dL.norm();
    if (!(smax == 0 || smin > 1e-9 * smax || d <= pb.tol_newton)) return false;
    s.out.converged = true;
    s.out.dist = d;
    return true;
}

// Stuck for the whole period (i = 0): the map is a translation by 2 pi zeta e_x (DPhi = I, no Newton). Skip
// to the first slip in closed form, then to the end of that period.
After skip_stuck_periods(const SearchProblem& pb, SearchState& s) {
    const auto ts = solver::stick_slip_time(pb.m, 0, s.l0, std::numeric_limits<double>::max());
    if (!ts) { // zeta = 0 and no slip: every start is periodic (handled above for r <= 1)
        s.out.converged = true;
        s.out.dist = 0;
        return After::stop;
    }
    const double k = std::floor(*ts / kTwoPi);
    s.out.periods_skipped += static_cast<long>(k);
    const Vec2 ls2 = s.l0 + pb.r * pb.m.dispP(0, *ts);
    const PeriodRequest plain{pb.rq.atol, pb.rq.atol_force, false};
    const PeriodResult rest = solver::run_lag(pb.m, ls2, *ts - k * kTwoPi, kTwoPi, plain);
    if (!rest.ok) {
        s.out.failure = rest.failure;
        s.out.status = SteadyStatus::integration_failed;
        return After::stop;
    }
    s.l0 = rest.l_end;
    ++s.out.plain_steps;
    s.ref.valid = false;
    return After::next_period;
}

// The next period starts where this one ended, as a plain step of the map.
void plain_step_to_end(SearchState& s, const PeriodResult& pr) {
    s.l0 = pr.l_end;
    ++s.out.plain_steps;
    s.ref.valid = false;
}

// The derivative of the circle's angle map minus 1 over a period from l0 on the circle (radians per radian).
double circle_J(const PeriodResult& pr, const Vec2& l0) {
    const Vec2 le = pr.l_end / pr.l_end.norm();
    return perp(le).dot((Eigen::Matrix2d::Identity() + pr.E) * perp(l0)) / pr.l_end.norm() - 1;
}

// A period that started on the circle: Newton on the circle's angle.
After circle_step(const SearchProblem& pb, SearchState& s, const PeriodResult& pr) {
    const double r = pb.r;
    const Vec2 l0 = s.l0;
    // A period that leaves the circle only briefly ends just inside (for i >= 1 the state never gets back
    // exactly): the steady state may still be on the circle at an angle where v never turns negative.
    // Newton on the angle first (a few times), the plane after.
    // The angle's map: |J| ~ 0 where the angle does not contract over this period (v ~ 0 all along).
    const double J = circle_J(pr, l0);
    const bool flat = !(std::abs(J) > 1e-12);
    // Not where the angle's map is flat: a retry would repeat the same period (zeta 0, theta 30 deg, rdisp
    // 1e-8, i 10 from sliding: 8 such periods). (A J that is not a number counts as flat for the step below
    // but does not stop the retries.)
    const bool near_circle =
        pb.p.i > 0 && s.circle_retries < 8 && pr.l_end.norm() > 1 - 1e-3 && !(std::abs(J) <= 1e-12);
    if (pr.end != Phase::circle && near_circle) ++s.circle_retries;
    if (pr.end != Phase::circle && !near_circle) {
        // The period leaves the circle and ends inside: the steady state does not start on the circle.
        // Continue in the plane from where this period ended.
        s.circle_left.push_back(l0);
        plain_step_to_end(s, pr);
        return After::next_period;
    }
    // Residual and derivative in the arc a = angle / r (x_v units): a well-conditioned scalar equation for
    // every r. The circle map contracts (DPhi = exp(-int v) <= 1 on the circle), so plain Newton steps are
    // safe; the largest is capped at a radian.
    const Vec2 d = r * pr.dL; // l_end - l0
    const double dphi = std::atan2(l0.x() * d.y() - l0.y() * d.x(), 1 + l0.dot(d));
    const double arc = dphi / r;
    // Flat: a plain step, which says nothing about the distance to the fixed point.
    double da = flat ? -arc : -arc / J;
    if (!std::isfinite(da)) da = -arc;
    double step = r * da; // radians = force units
    if (std::abs(step) > 1) step = std::copysign(1.0, step);
    ++s.out.newton_steps;
    s.out.dist = flat ? std::numeric_limits<double>::infinity() : std::abs(step);
    if ((s.out.dist <= pb.tol_newton || stalled_at_noise(pb, s, s.out.dist)) && pr.end != Phase::circle) {
        // The best angle still leaves the circle: the steady state is inside, next to it.
        plain_step_to_end(s, pr);
        s.circle_retries = 8;
        s.allow_snap = false;
        s.best_corr = std::numeric_limits<double>::infinity();
        return After::next_period;
    }
    if (s.out.dist <= stop_at(pb, pr) || stalled_at_noise(pb, s, s.out.dist)) {
        s.out.converged = true; // at the noise floor: the error estimate below decides
        s.out.on_circle = true;
        return After::stop;
    }
    s.l0 = rotated(l0, step);
    s.ref.valid = false;
    return After::next_period;
}

// A whole period inside with v > 0 throughout (no law change, s = +1): rho grows all along
// (drho/dtau = r v (1 - rho)^i), so there is no fixed point inside; for i > 1 it creeps towards the circle
// so slowly that the integrated map may show a fixed point that is not there. The steady state is on the
// circle: search on the angle from where this period ended. Once: should that circle period leave the
// circle, the steady state is elsewhere after all. Whether it snapped.
// Nor next to a circle start that left the circle (within 0.1 rad): the period from there leaves it too,
// and the search would only repeat the circle's period and the plane's (zeta 0.036, theta 97 deg, rdisp
// 139, i 7.05: the snap landed 8e-7 from the first start; zeta 0.246, theta 84.5 deg, rdisp 2, i 7.9:
// 0.047 rad from it; two periods lost each).
constexpr double kSnapNearLeft = 0.1;
bool snap_creep_to_circle(const SearchProblem& pb, SearchState& s, Phase start, const PeriodResult& pr) {
    if (!(s.allow_snap && !s.creep_snapped && pb.p.i > 1 && start == Phase::interior && pr.events == 0 &&
          s.l0.dot(pb.m.dP(0)) > 0 && pr.l_end.norm() > 0 &&
          !left_before(s, Vec2(pr.l_end / pr.l_end.norm()), kSnapNearLeft)))
        return false;
    s.creep_snapped = true;
    s.l0 = pr.l_end / pr.l_end.norm();
    s.ref.valid = false;
    ++s.out.plain_steps;
    return true;
}

// The natural monotonicity test of the trial point (its residual F) against the reference point. Failed:
// lambda is halved and the next trial point set (or, with lambda too small, a plain period); returns whether
// it failed.
bool retreat_from_trial(const SearchProblem& pb, SearchState& s, const PeriodResult& pr) {
    if (!s.ref.valid) return false;
    const Vec2& F = pr.dL;
    const Eigen::Matrix2d& E = pr.E;
    const Vec2 simplified = -s.ref.Jinv * F;
    if (simplified.norm() <= (1 - s.lambda / 4) * s.ref.delta.norm()) {
        s.lambda = std::min(1.0, 2 * s.lambda);
        return false;
    }
    // Across a law change (the trial's period changes law a different number of times) the reference's
    // derivative says little about the trial's side: where the trial's own Newton correction is shorter by
    // the same margin, it becomes the reference (zeta 0.0095, theta 116 deg, rdisp 2800, i 10: the reference
    // on a creep's side, where DPhi ~ I and the step is long, the trials on the other, where DPhi ~ 0.1 and
    // the state is; lambda halved to 1/64 over and over, 255 -> 18 periods). Twice at most (law_switches).
    const double det = E.determinant();
    if (pr.events != s.ref.events && s.law_switches < 2 && std::isfinite(det) &&
        std::abs(det) > 1e-13 * std::max(1.0, E.cwiseAbs().maxCoeff()) &&
        Vec2(E.inverse() * F).norm() <= (1 - s.lambda / 4) * s.ref.delta.norm()) {
        s.lambda = 1;
        ++s.law_switches;
        return false;
    }
    s.lambda *= 0.5;
    if (s.lambda < 1.0 / 64) {
        // Newton makes no headway from here: a plain period instead (always admissible).
        s.l0 = s.ref.l_end;
        s.ref.valid = false;
        s.lambda = 1;
        ++s.out.plain_steps;
    } else {
        s.l0 = s.ref.l + s.lambda * pb.r * s.ref.delta;
        if (s.l0.norm() > 1) s.l0 /= s.l0.norm();
    }
    return true;
}

// The Newton correction (x_v) of F(L0) = L(2 pi) - L0 = F with F' = DPhi - I = J, and the inverse used.
struct Correction {
    Vec2 delta;
    Eigen::Matrix2d Jinv;
};

Correction newton_correction(SearchState& s, const Vec2& F, const Eigen::Matrix2d& J) {
    const double det = J.determinant();
    const double scale = J.cwiseAbs().maxCoeff();
    const bool singular = !(std::abs(det) > 1e-13 * scale * scale) || !std::isfinite(det);
    // A rank-deficient F' (the period passes the circle twice and forgets both directions, or the tip is
    // stuck: F' = 0) gets the pseudo-inverse for its range and a plain step for the rest.
    Eigen::Matrix2d Jinv;
    if (singular) {
        const Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
        const Vec2 sv = svd.singularValues();
        Eigen::Matrix2d Sinv = Eigen::Matrix2d::Zero();
        for (int k = 0; k < 2; ++k)
            if (sv[k] > 1e-9 * std::max(sv[0], 1e-300)) Sinv(k, k) = 1 / sv[k];
        Jinv = svd.matrixV() * Sinv * svd.matrixU().transpose();
        ++s.out.plain_steps;
    } else {
        Jinv = J.inverse();
        ++s.out.newton_steps;
    }
    Vec2 delta = -Jinv * F;
    if (singular) delta += F + J * delta; // the part of F that F' cannot see: a plain step
    return {delta, Jinv};
}

// A Newton step that converges only linearly (a degenerate fixed point, e.g. i > 1 next to the circle) is
// accelerated by Aitken's rule: successive steps in one direction, shrinking by q, sum to step / (1 - q); the
// distance to the fixed point is the same sum. Returns q (0: no steady linear rate).
double aitken_rate(SearchState& s, const Vec2& delta) {
    double q = 0;
    if (s.have_prev_delta && s.prev_delta.norm() > 0 && s.lambda == 1) {
        q = delta.norm() / s.prev_delta.norm();
        const bool aligned = delta.dot(s.prev_delta) > 0.9 * delta.norm() * s.prev_delta.norm();
        if (!(aligned && q > 0.2 && q < 0.98)) q = 0;
    }
    s.prev_delta = delta;
    s.have_prev_delta = true;
    return q;
}

// Moves s.l0 by the plane step dl (force units), kept inside the disc, or onto the circle where the steady
// period starts there.
void move_in_plane(const SearchProblem& pb, SearchState& s, Vec2 dl) {
    Vec2& l0 = s.l0;
    // A step out of the disc is cut to go at most halfway to the circle: projecting onto the circle would
    // start the next period in another law (the circle's), and near a fixed point just inside the circle
    // (i > 1) the iteration would cycle between the two. A step that stays inside is taken whole (it used to
    // be cut as well wherever it went past halfway: the distance to a state at 1 - 1e-4 then only halved
    // per period).
    // For i < 1 (the deficit closes in finite time: for i = 0 at once, for 0 < i < 1 within part of a period)
    // a full step out of the disc where the tip would slip at tau = 0 says that the steady period starts on
    // the circle (its law at the section is the circle's, the plane's Newton could only creep towards it,
    // halving the distance each period: 20 periods at zeta 0.075, theta 90 deg, rdisp 0.1, i = 0.5): search
    // on the circle's angle from there. Should the best angle leave the circle, the search comes back to the
    // plane with snapping off.
    if (s.allow_snap && pb.p.i < 1 && (l0 + dl).norm() >= 1) {
        const Vec2 lc = (l0 + dl).normalized();
        if (lc.dot(pb.m.dP(0)) > 0) {
            l0 = lc;
            s.ref.valid = false;
            return;
        }
    }
    const double R = 1 - 0.5 * (1 - std::min(1.0, l0.norm()));
    if ((l0 + dl).norm() >= 1 && dl.squaredNorm() > 0) {
        const double a = dl.squaredNorm(), b = 2 * l0.dot(dl), c = l0.squaredNorm() - R * R;
        const double t = (-b + std::sqrt(std::max(0.0, b * b - 4 * a * c))) / (2 * a);
        dl *= std::clamp(t, 0.0, 1.0);
    }
    l0 = l0 + dl;
    if (l0.norm() > 1) l0 /= l0.norm();
    // Within 1e-6 of the circle and slipping outwards (i > 0): the steady state is on the circle or the
    // approach to it is too flat for the plane's Newton (exponential for i = 1, algebraic for i > 1, with the
    // pinning switching laws in between): search on the circle's angle instead.
    if (s.allow_snap && pb.p.i > 0 && l0.norm() > 1 - 1e-6 && l0.dot(pb.m.dP(0)) > 0 &&
        !left_before(s, Vec2(l0 / l0.norm()))) {
        l0 /= l0.norm();
        s.ref.valid = false;
    }
}

// In the plane: damped Newton on F(L0) = L(2 pi) - L0 (x_v units) with F' = DPhi - I = E.
After plane_step(const SearchProblem& pb, SearchState& s, const PeriodResult& pr) {
    const Vec2 F = pr.dL;
    if (retreat_from_trial(pb, s, pr)) return After::next_period;
    const Correction c = newton_correction(s, F, pr.E);
    const double q = aitken_rate(s, c.delta);
    s.out.dist = pb.r * c.delta.norm() / (1 - q);
    if (s.out.dist <= pb.tol_newton || stalled_at_noise(pb, s, s.out.dist)) {
        s.out.converged = true; // at the noise floor: the error estimate below decides
        return After::stop;
    }
    s.ref.valid = true;
    s.ref.l = s.l0;
    s.ref.delta = q > 0 ? Vec2(c.delta / (1 - q)) : c.delta;
    // Aitken's sum leaving the disc where Newton's own step stays inside: the rate q came from steps cut at
    // the circle (halving the distance to it each time: q ~ 0.5), not from a degenerate fixed point; Newton's
    // step it is (zeta 0.018, theta 120 deg, rdisp 10, i 1 from sliding, DPhi ~ 0: Newton's step is the
    // period's end, the state; the doubled step was cut, 10 periods lost).
    if (q > 0 && (s.l0 + s.lambda * pb.r * s.ref.delta).norm() >= 1 &&
        (s.l0 + s.lambda * pb.r * c.delta).norm() < 1)
        s.ref.delta = c.delta;
    s.ref.l_end = pr.l_end;
    s.ref.events = pr.events;
    s.ref.Jinv = c.Jinv;
    Vec2 dl = s.lambda * pb.r * s.ref.delta;
#ifdef FV_SOLVER_TRACE
    std::fprintf(stderr, "  plane: newton (%.3e,%.3e) q %.3g lambda %g -> dl (%.3e,%.3e)\n",
                 pb.r * c.delta.x(), pb.r * c.delta.y(), q, s.lambda, dl.x(), dl.y());
#endif
    const double n = dl.norm();
    if (n > 1) dl /= n;
    move_in_plane(pb, s, dl);
    return After::next_period;
}

// What a period tells the search: done (converged, given up), or the next start.
After step_after(const SearchProblem& pb, SearchState& s, const Period& period) {
    const PeriodResult& pr = period.result;
    if (gives_up(pb, s, pr) || back_at_start(pb, s, pr)) return After::stop;
    if (pb.p.i == 0 && !pr.visited_circle) return skip_stuck_periods(pb, s);
    if (period.start == Phase::circle) return circle_step(pb, s, pr);
    if (snap_creep_to_circle(pb, s, period.start, pr)) return After::next_period;
    return plane_step(pb, s, pr);
}

} // namespace

Search search_from(const Params& p, const LagModel& m, Vec2 l0, const PeriodRequest& rq, double aim,
                   int max_periods, int give_up) {
    const SearchProblem pb{p, m, rq, aim, p.rdisp, 0.1 * aim, max_periods, give_up};
    SearchState s = start_state(l0);
    for (int iter = 0; iter < kMaxIterations; ++iter) {
        const std::optional<Period> period = integrate_period(pb, s, iter);
        if (!period || step_after(pb, s, *period) == After::stop) break;
    }
    if (!s.out.converged && !*s.out.failure)
        s.out.failure = "the search did not settle within its update limit";
    return s.out;
}

} // namespace fv::solver
