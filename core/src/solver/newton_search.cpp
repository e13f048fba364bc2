// Newton's method for a fixed point of the period map (see newton_search.hpp, docs/model.md).
#include "newton_search.hpp"

#include "closed_forms.hpp"

#include <Eigen/LU>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <vector>

namespace fv::solver {
namespace {

Vec2 perp(const Vec2& e) {
    return {-e.y(), e.x()};
}

Vec2 rotate(const Vec2& v, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

constexpr int kMaxIterations = 100;

} // namespace

Search search_from(const Params& p, const LagModel& m, Vec2 l0, const PeriodRequest& rq, double aim,
                   int max_periods, int give_up) {
    const double r = p.rdisp;
    const double tol_newton = 0.1 * aim; // force units
    // The means reported are those of a period started `dist` from the fixed point l*: to first order they
    // are off by gain * dist (gain = |G| / 2 pi, G = int dl(tau)/dl(0) dtau from the variational equations:
    // small where the flow forgets its start quickly, a stiff tip on the circle). So a search on the circle
    // may stop once gain * dist is a small part of the aim (0.15 aim; the error estimate counts it twice),
    // while dist^2 stays below 0.1 aim (the linearisation), but only where the period keeps to one law with
    // a margin: on the circle all along, v = e . P' >= 0.05 (1 + zeta) at every step's points. A start dist
    // away turns the force by at most dist (the circle's angle map contracts), so v moves by at most
    // (1 + zeta) dist there: the period from l* keeps the same law. Without that margin the fixed point may
    // lie across a law change (the true period leaves the circle: zeta = 0.933, theta = 13 deg, rdisp = 1,
    // i = 1 was 6e-6 off with this rule everywhere), and the search goes on to tol_newton.
    auto stop_at = [&](const PeriodResult& pr) {
        const double gain = pr.G.norm() / kTwoPi;
        const bool one_law = pr.start == Phase::circle && pr.end == Phase::circle && pr.events == 0 &&
                             pr.v_min_circle >= 0.05 * (1 + p.zeta);
        if (!one_law || !(gain > 0) || !std::isfinite(gain)) return tol_newton;
        return std::max(tol_newton, std::min(std::sqrt(0.1 * aim), 0.15 * aim / gain));
    };
    Search out;
    out.last_l0 = l0;
    double best_residual = std::numeric_limits<double>::infinity();
    int since_best = 0;
    // Damped Newton in the plane (Deuflhard's natural monotonicity test): a trial point l_ref + lambda step
    // is accepted when the correction it needs, measured with the reference point's inverse Jacobian, has
    // shrunk; else lambda is halved. Near the fixed point the periods' integration noise limits what the
    // corrections can show: when they stop shrinking, the search stops and its last correction is the
    // distance it reports.
    struct Ref {
        bool valid = false;
        Vec2 l{0, 0}, delta{0, 0}, l_end{0, 0}; // point, its Newton correction (x_v), Phi(point) (force)
        Eigen::Matrix2d Jinv = Eigen::Matrix2d::Zero();
    } ref;
    double lambda = 1;
    Vec2 prev_delta(0, 0);
    bool have_prev_delta = false;
    double best = std::numeric_limits<double>::infinity();
    int stalled = 0;
    int circle_retries = 0;
    bool allow_snap = true;
    bool creep_snapped = false;
    // Circle starts whose period left the circle for the interior: a snap onto the circle from the plane must
    // not go back to one of them (it would repeat the same two periods, the circle's and the plane's: seen
    // at zeta = 0.0042, theta = 90 deg, rdisp = 1e4, i = 10).
    std::vector<Vec2> circle_left;
    auto left_before = [&](const Vec2& l) {
        return std::any_of(circle_left.begin(), circle_left.end(),
                           [&](const Vec2& c) { return (c - l).norm() <= 1e-9; });
    };
    double prev_corr = std::numeric_limits<double>::infinity();
    auto stalled_at_noise = [&](double& corr) {
        // Small corrections that stop shrinking (by 2x within 3 tries) are rounding and integration noise.
        // Unless they shrink steadily (a slow linear rate q, which noise does not show): then the distance
        // is corr / (1 - q), and with q near 1 the search is not done.
        const double q = prev_corr > 0 ? corr / prev_corr : 1;
        prev_corr = corr;
        if (corr < 0.5 * best) {
            best = corr;
            stalled = 0;
            return false;
        }
        if (!(corr <= 1e3 * aim && ++stalled >= 3)) return false;
        if (q < 1) corr /= 1 - std::min(q, 0.999);
        return true;
    };

    for (int iter = 0; iter < kMaxIterations; ++iter) {
        if (out.periods >= max_periods) {
            out.failure = "period budget exhausted";
            break;
        }
        Vec2 ls = l0;
        const Phase start = solver::classify(m, 0, ls);
        l0 = ls;
        const PeriodResult pr = solver::run_lag(m, l0, 0, kTwoPi, rq);
        ++out.periods;
#ifdef FV_SOLVER_TRACE
        std::fprintf(
            stderr,
            "iter %d start=%d end=%d l0=(%.12g,%.12g) |l0|=%.15g dL=(%.3e,%.3e) steps=%ld ev=%d lambda=%g\n",
            iter, (int)start, (int)pr.end, l0.x(), l0.y(), l0.norm(), pr.dL.x(), pr.dL.y(), pr.steps,
            pr.events, lambda);
#endif
        if (!pr.ok) {
            out.failure = pr.failure;
            out.status = SteadyStatus::integration_failed;
            break;
        }
        out.last = pr;
        out.last_l0 = l0;
        out.have_last = true;
        if (give_up > 0) {
            const double residual = r * pr.dL.norm();
            if (residual < 0.5 * best_residual) {
                best_residual = residual;
                since_best = 0;
            } else if (++since_best >= give_up) {
                out.gave_up = true;
                out.failure = "no progress from this start";
                break;
            }
        }
        if (pr.dL.norm() <= 64 * std::numeric_limits<double>::epsilon() * (1 + kTwoPi * (1 + p.zeta))) {
            // Back where it started, to the rounding of a period's displacements (e.g. zeta = 0 with i = 0:
            // the tip reaches the circle just at the period's end), whatever the law at the section. The
            // distance is that residual through F' (pseudo-inverse): where F' is nearly singular too (a
            // degenerate fixed point, i > 1 next to the circle) this is no evidence, and the search goes on.
            const Eigen::JacobiSVD<Eigen::Matrix2d> svd(pr.E);
            const double smin = svd.singularValues()[1], smax = svd.singularValues()[0];
            const double d = smax > 0 && smin > 1e-9 * smax ? r * pr.dL.norm() / smin : r * pr.dL.norm();
            if (smax == 0 || smin > 1e-9 * smax || d <= tol_newton) {
                out.converged = true;
                out.dist = d;
                break;
            }
        }

        if (p.i == 0 && !pr.visited_circle) {
            // Stuck for the whole period: the map is a translation by 2 pi zeta e_x (DPhi = I, no Newton).
            // Skip to the first slip in closed form, then to the end of that period.
            const auto ts = solver::stick_slip_time(m, 0, l0, std::numeric_limits<double>::max());
            if (!ts) { // zeta = 0 and no slip: every start is periodic (handled above for r <= 1)
                out.converged = true;
                out.dist = 0;
                break;
            }
            const double k = std::floor(*ts / kTwoPi);
            out.periods_skipped += static_cast<long>(k);
            const Vec2 ls2 = l0 + r * m.dispP(0, *ts);
            const PeriodRequest plain{rq.atol, rq.atol_force, false};
            const PeriodResult rest = solver::run_lag(m, ls2, *ts - k * kTwoPi, kTwoPi, plain);
            if (!rest.ok) {
                out.failure = rest.failure;
                out.status = SteadyStatus::integration_failed;
                break;
            }
            l0 = rest.l_end;
            ++out.plain_steps;
            ref.valid = false;
            continue;
        }

        if (start == Phase::circle) {
            // A period that leaves the circle only briefly ends just inside (for i >= 1 the state never
            // gets back exactly): the steady state may still be on the circle at an angle where v never
            // turns negative. Newton on the angle first (a few times), the plane after.
            const bool near_circle = p.i > 0 && circle_retries < 8 && pr.l_end.norm() > 1 - 1e-3;
            if (pr.end != Phase::circle && near_circle) ++circle_retries;
            if (pr.end != Phase::circle && !near_circle) {
                // The period leaves the circle and ends inside: the steady state does not start on the
                // circle. Continue in the plane from where this period ended.
                circle_left.push_back(l0);
                l0 = pr.l_end;
                ++out.plain_steps;
                ref.valid = false;
                continue;
            }
            // Residual and derivative in the arc a = angle / r (x_v units): a well-conditioned scalar
            // equation for every r. The circle map contracts (DPhi = exp(-int v) <= 1 on the circle), so
            // plain Newton steps are safe; the largest is capped at a radian.
            const Vec2 d = r * pr.dL; // l_end - l0
            const double dphi = std::atan2(l0.x() * d.y() - l0.y() * d.x(), 1 + l0.dot(d));
            const double arc = dphi / r;
            const Vec2 le = pr.l_end / pr.l_end.norm();
            const double J =
                perp(le).dot((Eigen::Matrix2d::Identity() + pr.E) * perp(l0)) / pr.l_end.norm() - 1;
            // |J| ~ 0: the angle does not contract over this period (v ~ 0 all along): a plain step, which
            // says nothing about the distance to the fixed point.
            const bool flat = !(std::abs(J) > 1e-12);
            double da = flat ? -arc : -arc / J;
            if (!std::isfinite(da)) da = -arc;
            double step = r * da; // radians = force units
            if (std::abs(step) > 1) step = std::copysign(1.0, step);
            ++out.newton_steps;
            out.dist = flat ? std::numeric_limits<double>::infinity() : std::abs(step);
            if ((out.dist <= tol_newton || stalled_at_noise(out.dist)) && pr.end != Phase::circle) {
                // The best angle still leaves the circle: the steady state is inside, next to it.
                l0 = pr.l_end;
                circle_retries = 8;
                allow_snap = false;
                ++out.plain_steps;
                ref.valid = false;
                best = std::numeric_limits<double>::infinity();
                continue;
            }
            if (out.dist <= stop_at(pr) || stalled_at_noise(out.dist)) {
                out.converged = true; // at the noise floor: the error estimate below decides
                out.on_circle = true;
                break;
            }
            l0 = rotate(l0, step);
            ref.valid = false;
            continue;
        }

        // A whole period inside with v > 0 throughout (no law change, s = +1): rho grows all along
        // (drho/dtau = r v (1 - rho)^i), so there is no fixed point inside; for i > 1 it creeps towards the
        // circle so slowly that the integrated map may show a fixed point that is not there. The steady state
        // is on the circle: search on the angle from where this period ended.
        // Once: should that circle period leave the circle, the steady state is elsewhere after all.
        if (allow_snap && !creep_snapped && p.i > 1 && start == Phase::interior && pr.events == 0 &&
            l0.dot(m.dP(0)) > 0 && pr.l_end.norm() > 0 && !left_before(Vec2(pr.l_end / pr.l_end.norm()))) {
            creep_snapped = true;
            l0 = pr.l_end / pr.l_end.norm();
            ref.valid = false;
            ++out.plain_steps;
            continue;
        }
        // In the plane: Newton on F(L0) = L(2 pi) - L0 (x_v units) with F' = DPhi - I = E.
        const Vec2 F = pr.dL;
        const Eigen::Matrix2d& J = pr.E;
        const double det = J.determinant();
        const double scale = J.cwiseAbs().maxCoeff();
        const bool singular = !(std::abs(det) > 1e-13 * scale * scale) || !std::isfinite(det);
        if (ref.valid) {
            // Natural monotonicity test of the trial point against the reference point.
            const Vec2 simplified = -ref.Jinv * F;
            if (!(simplified.norm() <= (1 - lambda / 4) * ref.delta.norm())) {
                lambda *= 0.5;
                if (lambda < 1.0 / 64) {
                    // Newton makes no headway from here: a plain period instead (always admissible).
                    l0 = ref.l_end;
                    ref.valid = false;
                    lambda = 1;
                    ++out.plain_steps;
                } else {
                    l0 = ref.l + lambda * r * ref.delta;
                    if (l0.norm() > 1) l0 /= l0.norm();
                }
                continue;
            }
            lambda = std::min(1.0, 2 * lambda);
        }
        // A rank-deficient F' (the period passes the circle twice and forgets both directions, or the tip
        // is stuck: F' = 0) gets the pseudo-inverse for its range and a plain step for the rest.
        Eigen::Matrix2d Jinv;
        if (singular) {
            const Eigen::JacobiSVD<Eigen::Matrix2d> svd(J, Eigen::ComputeFullU | Eigen::ComputeFullV);
            const Vec2 sv = svd.singularValues();
            Eigen::Matrix2d Sinv = Eigen::Matrix2d::Zero();
            for (int k = 0; k < 2; ++k)
                if (sv[k] > 1e-9 * std::max(sv[0], 1e-300)) Sinv(k, k) = 1 / sv[k];
            Jinv = svd.matrixV() * Sinv * svd.matrixU().transpose();
            ++out.plain_steps;
        } else {
            Jinv = J.inverse();
            ++out.newton_steps;
        }
        Vec2 delta = -Jinv * F;
        if (singular) delta += F + J * delta; // the part of F that F' cannot see: a plain step
        // A Newton step that converges only linearly (a degenerate fixed point, e.g. i > 1 next to the
        // circle) is accelerated by Aitken's rule: successive steps in one direction, shrinking by q, sum to
        // step / (1 - q); the distance to the fixed point is the same sum.
        double q = 0;
        if (have_prev_delta && prev_delta.norm() > 0 && lambda == 1) {
            q = delta.norm() / prev_delta.norm();
            const bool aligned = delta.dot(prev_delta) > 0.9 * delta.norm() * prev_delta.norm();
            if (!(aligned && q > 0.2 && q < 0.98)) q = 0;
        }
        prev_delta = delta;
        have_prev_delta = true;
        out.dist = r * delta.norm() / (1 - q);
        if (out.dist <= tol_newton || stalled_at_noise(out.dist)) {
            out.converged = true; // at the noise floor: the error estimate below decides
            break;
        }
        ref.valid = true;
        ref.l = l0;
        ref.delta = q > 0 ? Vec2(delta / (1 - q)) : delta;
        ref.l_end = pr.l_end;
        ref.Jinv = Jinv;
        Vec2 dl = lambda * r * ref.delta;
        const double n = dl.norm();
        if (n > 1) dl /= n;
        // A step out of the disc is cut to go at most halfway to the circle: projecting onto the circle
        // would start the next period in another law (the circle's), and near a fixed point just inside
        // the circle (i > 1) the iteration would cycle between the two.
        // For i = 0 a full step out of the disc where the tip would slip at tau = 0 says that the steady
        // period starts on the circle (its law at the section is the circle's, the plane's Newton could only
        // creep towards it): search on the circle's angle from there. Should the best angle leave the
        // circle, the search comes back to the plane with snapping off.
        if (allow_snap && p.i == 0 && (l0 + dl).norm() >= 1) {
            const Vec2 lc = (l0 + dl).normalized();
            if (lc.dot(m.dP(0)) > 0) {
                l0 = lc;
                ref.valid = false;
                continue;
            }
        }
        const double R = 1 - 0.5 * (1 - std::min(1.0, l0.norm()));
        if ((l0 + dl).norm() > R && dl.squaredNorm() > 0) {
            const double a = dl.squaredNorm(), b = 2 * l0.dot(dl), c = l0.squaredNorm() - R * R;
            const double t = (-b + std::sqrt(std::max(0.0, b * b - 4 * a * c))) / (2 * a);
            dl *= std::clamp(t, 0.0, 1.0);
        }
        l0 = l0 + dl;
        if (l0.norm() > 1) l0 /= l0.norm();
        // Within 1e-6 of the circle and slipping outwards (i > 0): the steady state is on the circle or
        // the approach to it is too flat for the plane's Newton (exponential for i = 1, algebraic for
        // i > 1, with the pinning switching laws in between): search on the circle's angle instead.
        if (allow_snap && p.i > 0 && l0.norm() > 1 - 1e-6 && l0.dot(m.dP(0)) > 0 &&
            !left_before(Vec2(l0 / l0.norm()))) {
            l0 /= l0.norm();
            ref.valid = false;
        }
    }
    if (!out.converged && !*out.failure) out.failure = "the search did not settle within its update limit";
    return out;
}

} // namespace fv::solver
