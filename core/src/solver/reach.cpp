// Which periodic state the motion from a start settles into (see reach.hpp, docs/model.md).
#include "reach.hpp"

#include "closed_forms.hpp"
#include "coast.hpp"
#include "creep_skip.hpp"
#include "plane_angles.hpp"
#include "search_starts.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <optional>

namespace fv::solver {
namespace {

using cd = std::complex<double>;

void sort_desc(cd mu[2]) {
    if (std::abs(mu[1]) > std::abs(mu[0])) std::swap(mu[0], mu[1]);
}

void eigen_multipliers(const Eigen::Matrix2d& M, cd mu[2]) {
    const Eigen::EigenSolver<Eigen::Matrix2d> es(M, false);
    mu[0] = es.eigenvalues()[0];
    mu[1] = es.eigenvalues()[1];
    sort_desc(mu);
}

} // namespace

PeriodRequest state_only(const ReachSetup& s) {
    return PeriodRequest{s.rq.atol, s.rq.atol_force, false};
}

double arrival_noise(const ReachSetup& s) {
    return std::max(30 * s.aim, 1e-10);
}

double v_integral(const LagModel& m, const std::vector<Sample>& samples) {
    if (samples.empty()) return 0;
    double sum = 0;
    for (const Sample& x : samples) sum += x.F.normalized().dot(m.dP(x.tau));
    return sum * kTwoPi / static_cast<double>(samples.size());
}

bool advance(const ReachSetup& s, Vec2& l, const PeriodRequest& rq, PeriodResult* last) {
    const LagModel& m = *s.m;
    PeriodResult pr = run_lag(m, l, 0, kTwoPi, rq);
    if (!pr.ok) return false;
    if (m.i == 0 && !pr.visited_circle) {
        Vec2 l0 = l;
        classify(m, 0, l0);
        const auto ts = stick_slip_time(m, 0, l0, std::numeric_limits<double>::max());
        if (!ts) { // zeta = 0 and no slip: every state is periodic
            if (last) *last = pr;
            l = pr.l_end;
            return true;
        }
        const double k = std::floor(*ts / kTwoPi);
        pr = run_lag(m, l0 + m.r * m.dispP(0, *ts), *ts - k * kTwoPi, kTwoPi, rq);
        if (!pr.ok) return false;
    }
    l = pr.l_end;
    if (last) *last = pr;
    return true;
}

namespace {

bool advance_k(const ReachSetup& s, Vec2& l, int k, const PeriodRequest& rq) {
    for (int j = 0; j < k; ++j)
        if (!advance(s, l, rq)) return false;
    return true;
}

// The map's push Phi^k(z) - z moves towards y at x and at every sixteenth of the way from y to x, along w
// and along the segment itself: no fixed point between them (unless two, closer than the samples: a
// saddle-node pair about to appear). Samples only near y (1/2, 1/4, 1/8, 1/16 of the way) missed the
// unstable state between two basins: at zeta 0.075, theta 90 deg, rdisp 0.1, i = 5 the motion from sliding,
// warm-started at the state from rest (0.0342), was said to reach it; it reaches 0.9975. Along w alone (the
// slow direction at y) the push said the same at zeta 0.1548, theta 83 deg, rdisp 0.1, i = 5 for the motion
// from sliding, which stays on the circle: w there is nearly across the segment, and the motion along the
// circle showed as a push towards the state from rest (0.3259; the motion reaches 0.9975).
// Towards a state on the circle (i > 1), a sample whose period is a creep period (inside, no law change,
// v > 0) moves outwards by the law itself (Eq. (16): rho' = r v (1 - rho)^i > 0), however little: next to the
// circle the push falls below the rounding of l (rdisp 1e-8, i = 10: 1e-17 at rho = 0.875) and its measured
// sign says nothing, so such samples count as pushing towards it (the circle's own law then contracts the
// angle onto the state's, DPhi = exp(-r int v) < 1).
bool pushes_towards(const ReachSetup& s, const Vec2& x, const Vec2& y, int k, const Eigen::RowVector2d& w,
                    bool circle_state, double floor, int& periods) {
    const PeriodRequest rq = state_only(s);
    const Vec2 d = y - x;
    const double wd = w.dot(d); // the push along w must have its sign (none where w is across the segment)
    // w across the segment (within 0.06 deg): y and x hardly differ along w, and the sign of the push along w
    // against that difference says nothing; the push along the segment still has to hold (it is what rules
    // out the false credit at zeta 0.1548, theta 83 deg above). At zeta 0.3162, theta 30 deg, rdisp 1e-9,
    // i = 0.5 (both multipliers 1 - O(rdisp)) w . d was 1e-12 |w||d|, at zeta 0.004217, theta 90 deg,
    // rdisp 0.01, i = 0.5 it was 6e-6 |w||d|: both failed every point of the motion from rest, which was then
    // followed for hundreds to 1900 periods.
    const bool across = std::abs(wd) <= 1e-3 * w.norm() * d.norm();
    // Only the push's sign is asked for, so a sample is first integrated at kLoose times the tolerances, and
    // that answer is kept where both pushes clear the loose period's error by kMargin (bounded by its steps
    // times their local tolerance, in force units: l = r L). Where the map is nearly the identity (tiny
    // r_disp) the pushes are large in the integrated units and every sample clears it, at about 60 % of
    // the cost; where one does not, it and the rest are integrated at the tolerances themselves.
    constexpr double kLoose = 100, kMargin = 100;
    PeriodRequest loose = rq;
    loose.atol *= kLoose;
    loose.atol_force *= kLoose;
    bool try_loose = k == 1;
    auto towards = [&](const Vec2& z) {
        for (;;) {
            const bool is_loose = try_loose;
            Vec2 z1 = z;
            PeriodResult pr;
            const bool ok = k == 1 ? advance(s, z1, is_loose ? loose : rq, &pr) : advance_k(s, z1, k, rq);
            periods += k;
            const Vec2 push = z1 - z;
            const double d_floor = floor * (1 + z.norm()) * d.norm(); // the push along d must exceed it
            if (is_loose) {
                const double err = kMargin * s.m->r * loose.atol * static_cast<double>(pr.steps + 1);
                const bool clear = ok && (across || std::abs(w.dot(push)) > err * w.norm()) &&
                                   std::abs(d.dot(push)) > err * d.norm() + d_floor;
                if (!clear) {
                    try_loose = false;
                    continue;
                }
            }
            if (ok && circle_state && k == 1 && creep_period(*s.m, z, pr)) return true;
#ifdef FV_SOLVER_TRACE
            std::fprintf(stderr, "push at (%.6g,%.6g)%s: along w %.3g (wd %.3g), along d %.3g\n", z.x(),
                         z.y(), is_loose ? " loose" : "", w.dot(push), wd, d.dot(push));
#endif
            return ok && (across || wd * w.dot(push) > 0) && d.dot(push) > d_floor;
        }
    };
    // x and the sample next to it first, then from y outwards: where the test fails it mostly fails next to
    // x (another state close to the start: zeta 0.001, theta 90 deg, rdisp 1e-3, i 5 from rest, the circle's
    // state tested, the state reached at |l| = 5e-4) or next to y (a state on the circle whose chord samples
    // lie inside it), so a failure costs few periods.
    if (!towards(x) || !towards(y + (15 / 16.0) * (x - y))) return false;
    for (int j = 1; j <= 14; ++j)
        if (!towards(y + (j / 16.0) * (x - y))) return false;
    return true;
}

// int v dtau over a period on the circle from l0 (v = e . P', |e| = 1), on 256 samples.
double circle_v_integral(const ReachSetup& s, const Vec2& l0) {
    std::vector<Sample> samples;
    PeriodRequest rq = state_only(s);
    rq.samples = &samples;
    rq.n_samples = 256;
    rq.params = s.p;
    const PeriodResult pr = run_lag(*s.m, l0, 0, kTwoPi, rq);
    return pr.ok ? v_integral(*s.m, samples) : 0;
}

} // namespace

bool stable(const cd mu[2]) {
    return std::abs(mu[0]) <= 1 && std::abs(mu[1]) < 1;
}

namespace {

bool same_orbit(const Orbit& a, const Orbit& b) {
    if (a.k != b.k) return false;
    return std::abs(a.rx - b.rx) <= 1e-6 + a.error_estimate + b.error_estimate &&
           std::abs(a.ry - b.ry) <= 1e-6 + a.error_estimate + b.error_estimate;
}

// A k-period orbit by Newton's method on the k-times iterated map (in the plane), its verification and
// error estimate like the 1-period state's (verify_state.cpp).
struct KSearch {
    bool converged = false;
    Vec2 y{0, 0};
    Eigen::Matrix2d M = Eigen::Matrix2d::Identity(); // D(Phi^k) at y
    Vec2 force_integral{0, 0};
    Eigen::Matrix2d G = Eigen::Matrix2d::Zero(); // d(force integral over the k periods)/dy
    double dist = std::numeric_limits<double>::infinity();
    bool visited_circle = false;
    double pin_drop = 0;
    int events = 0;
    long steps = 0;
    int periods = 0, newton_steps = 0;
    const char* failure = "";
};

bool compose(const ReachSetup& s, const Vec2& y, int k, const PeriodRequest& rq, KSearch& out, Vec2& end) {
    Vec2 l = y;
    out.M.setIdentity();
    out.G.setZero();
    out.force_integral.setZero();
    out.visited_circle = false;
    out.pin_drop = 0;
    out.events = 0;
    out.steps = 0;
    for (int j = 0; j < k; ++j) {
        const PeriodResult pr = run_lag(*s.m, l, 0, kTwoPi, rq);
        ++out.periods;
        if (!pr.ok) {
            out.failure = pr.failure;
            return false;
        }
        if (rq.sensitivity) {
            // Forces as l = r L: the force integral moves by G dl0 / r per unit of l0 (G is per x_v).
            out.G += pr.G * out.M;
            out.M = (Eigen::Matrix2d::Identity() + pr.E) * out.M;
        }
        out.force_integral += pr.force_integral;
        out.visited_circle = out.visited_circle || pr.visited_circle;
        out.pin_drop = std::max(out.pin_drop, pr.pin_drop);
        out.events += pr.events;
        out.steps += pr.steps;
        l = pr.l_end;
    }
    end = l;
    return true;
}

KSearch newton_k(const ReachSetup& s, Vec2 y, int k, int max_periods) {
    KSearch out;
    const double tol_newton = 0.1 * s.aim;
    double best = std::numeric_limits<double>::infinity();
    int stalled = 0;
    for (int it = 0; it < 40 && out.periods + k <= max_periods; ++it) {
        Vec2 end;
        if (!compose(s, y, k, s.rq, out, end)) return out;
        const Vec2 F = end - y;
        const Eigen::Matrix2d J = out.M - Eigen::Matrix2d::Identity();
        const double det = J.determinant();
        if (!(std::abs(det) > 1e-13 * std::max(1.0, J.cwiseAbs().maxCoeff()))) {
            y = end; // no Newton step: a plain k-period step
            continue;
        }
        Vec2 delta = -J.inverse() * F;
        ++out.newton_steps;
        out.dist = delta.norm();
        if (out.dist <= tol_newton || (out.dist <= 1e3 * s.aim && ++stalled >= 3)) {
            out.converged = true;
            out.y = y;
            return out;
        }
        if (out.dist < 0.5 * best) {
            best = out.dist;
            stalled = 0;
        }
        if (delta.norm() > 0.1) delta *= 0.1 / delta.norm();
        y += delta;
        if (y.norm() > 1) y /= y.norm();
    }
    out.failure = "the period-k search did not settle";
    return out;
}

// Whether the motion's sections xs repeat far better after a multiple of k periods (up to kMaxPeriodK, as
// far as xs reaches back) than the distance d they have after k.
bool repeats_better(const std::vector<Vec2>& xs, int k, double d) {
    const std::size_t n = xs.size() - 1;
    for (std::size_t j = 2 * static_cast<std::size_t>(k); j <= kMaxPeriodK && 2 * j <= n; j *= 2)
        if ((xs[n] - xs[n - j]).norm() < 0.1 * d) return true;
    return false;
}

// Whether the k-periodic point y repeats after k/2 periods already (a state of a shorter period, which
// Newton's method on the k-times map finds as well): not a period-k orbit. Newton's method stops within
// 0.1 aim of its stable fixed point, so a shorter period's point comes back within about twice that; a true
// k-orbit closer than 10 aim to itself after k/2 has means within the tolerance of that state's. Costs k/2
// periods.
bool repeats_sooner(const ReachSetup& s, const Vec2& y, int k, int& periods) {
    Vec2 half = y;
    periods += k / 2;
    if (!advance_k(s, half, k / 2, s.rq)) return false;
    return (half - y).norm() <= 10 * s.aim;
}

Orbit verify_k(const ReachSetup& s, const KSearch& ks, int k, int& periods) {
    Orbit o;
    o.k = k;
    o.l0 = ks.y;
    eigen_multipliers(ks.M, o.mu);
    o.have_mu = true;
    o.M = ks.M;
    o.newton_steps = ks.newton_steps;
    o.rx = ks.force_integral.x() / (kTwoPi * k);
    o.ry = ks.force_integral.y() / (kTwoPi * k);
    // The same k periods at a 4x looser tolerance: their means' difference is the integration error (as
    // for the 1-period state); the search's distance moves the means by G/(2 pi k) times it.
    PeriodRequest check{4 * s.rq.atol, 4 * s.rq.atol_force, false};
    check.max_step = s.rq.max_step;
    if (static_cast<double>(ks.steps) <= k * (kTwoPi / s.rq.max_step + 2))
        check.max_step = 0.5 * s.rq.max_step;
    std::vector<Sample> samples;
    std::vector<OdeEvent> events;
    if (s.record) {
        check.samples = &samples;
        check.n_samples = std::max(1, s.record_samples);
        check.params = s.p;
        check.events = &events;
    }
    KSearch again;
    Vec2 end;
    bool ok = compose(s, ks.y, k, check, again, end);
    periods += again.periods;
    // As for the 1-period state (verify_state.cpp): a looser run in nearly as many steps took the capped
    // steps of the reported one, and their difference would not show the error; again at half the cap.
    if (ok && check.max_step == s.rq.max_step && 10 * again.steps >= 9 * ks.steps) {
        check.max_step = 0.5 * s.rq.max_step;
        samples.clear();
        events.clear();
        again = KSearch{};
        ok = compose(s, ks.y, k, check, again, end);
        periods += again.periods;
    }
    if (!ok) {
        o.status = SteadyStatus::integration_failed;
        o.failure = again.failure;
        return o;
    }
    o.integration_error = (again.force_integral - ks.force_integral).cwiseAbs().maxCoeff() / (kTwoPi * k);
    const double gain = ks.G.norm() / (kTwoPi * k) / s.p->rdisp;
    const double offset = ks.dist;
    o.steady_error = 2 * offset * (offset <= 1e-3 && std::isfinite(gain) ? gain : std::max(1.0, gain));
    const double pin = std::max(s.p->i > 0 && ks.visited_circle ? kPin : 0, ks.pin_drop);
    o.error_estimate = o.steady_error + o.integration_error + pin + 1e-14;
    o.events_per_period = ks.events;
    o.steps_per_period = static_cast<int>(ks.steps / k);
    if (s.record) {
        // Only the first period's samples (taus 0..2 pi) make the figure's period.
        samples.resize(std::min(samples.size(), static_cast<std::size_t>(std::max(1, s.record_samples))));
        o.samples = std::move(samples);
        o.events = std::move(events);
    }
    o.status = o.error_estimate <= s.tol ? SteadyStatus::periodic : SteadyStatus::not_converged;
    if (o.status != SteadyStatus::periodic) o.failure = "error estimate above tolerance";
    return o;
}

void add_other(Reach& out, Orbit o) {
    o.samples.clear();
    o.events.clear();
    for (const Orbit& x : out.others)
        if (same_orbit(x, o)) return;
    out.others.push_back(std::move(o));
}

} // namespace

// Evidence that the motion through x (force units, a point of the start's motion) settles into the state
// y of the k-period map with derivative M (docs/model.md, "Which steady state"):
//   at y to within `noise`; or
//   in the linear regime: one k-period step from a point of the motion lands where M predicts, to within
//     half the contraction 1 - max|mu| (in the norm of M's eigenvectors); the remainder, quadratic in the
//     distance, is smaller still closer in, so every later step contracts;
//   a state on the circle approached from inside (i > 0): periods inside with v > 0 throughout (no law
//     change: rho grows monotonically) whose angle closes in on the state's;
//   else the map's push along the segment from the motion's point to y keeps the sign that moves towards y
//     (pushes_towards): along the slow multiplier's left eigenvector w where there is one (real mu_s >=
//     0.5, not a state on the circle; w is blind to the fast direction to first order), else along the
//     segment.
// `periods` counts the periods integrated.
bool reaches(const ReachSetup& s, Vec2 x, const Vec2& y, const Eigen::Matrix2d& M, int k, bool circle_state,
             int& periods) {
    const LagModel& m = *s.m;
    const PeriodRequest rq = state_only(s);
    const double noise = arrival_noise(s);
    cd mu[2];
    eigen_multipliers(M, mu);
    const double rho = std::abs(mu[0]);
    const Eigen::ComplexEigenSolver<Eigen::Matrix2cd> ces(M.cast<cd>());
    const Eigen::Matrix2cd V = ces.eigenvectors();
    const bool diagonal = std::abs(V.determinant()) > 1e-8;
    const Eigen::Matrix2cd Vinv = diagonal ? Eigen::Matrix2cd(V.inverse()) : Eigen::Matrix2cd::Identity();
    auto nrm = [&](const Vec2& e) { return (Vinv * e.cast<cd>()).norm(); };
    const double contraction = 1 - rho;
    int creeping = 0, shrinking = 0;
    double prev_ratio = 0, prev_dist = 0;
    constexpr int kSteps = 6;
    for (int n = 0; n < kSteps; ++n) {
        const Vec2 e0 = x - y;
        if (e0.norm() <= noise) return true;
        if (circle_state && x.norm() < 1 - 10 * kPin) {
            // Inside, towards a state on the circle: the approach is algebraic for i > 1 (no linear regime).
            PeriodResult pr;
            Vec2 x1 = x;
            if (!advance(s, x1, rq, &pr)) return false;
            periods += 1;
            if ((x1 - y).norm() <= noise) return true; // arrived
            const bool creep = pr.start == Phase::interior && pr.events == 0 && pr.end == Phase::interior &&
                               x1.norm() > x.norm() && x.dot(m.dP(0)) > 0;
            if (creep) {
                const double a0 = std::abs(turn_angle(y, x)), a1 = std::abs(turn_angle(y, x1));
                if (a1 <= noise || a1 < a0)
                    ++creeping;
                else
                    creeping = 0;
                if (creeping >= 2) return true;
            } else {
                creeping = 0;
            }
            x = x1;
            continue;
        }
        Vec2 x1 = x;
        if (!advance_k(s, x1, k, rq)) return false;
        periods += k;
        const Vec2 e1 = x1 - y;
        if (e1.norm() <= noise) return true; // arrived
        if (diagonal && contraction > 0) {
            const double ratio = nrm(e1 - M * e0) / (0.5 * contraction * nrm(e0)), dist = e1.norm();
#ifdef FV_SOLVER_TRACE
            std::fprintf(stderr, "reaches: n %d |e0| %.3g |e1| %.3g ratio %.3g\n", n, e0.norm(), dist, ratio);
#endif
            if (ratio <= 1) return true;
            // The steps left cannot pass either test where the last step's gains, kept up, fall short (a slow
            // approach gains little per period): the push below decides, without following on here.
            if (n >= 1) {
                const int left = kSteps - 1 - n;
                const bool no_linear = ratio * std::pow(std::min(1.0, ratio / prev_ratio), left) > 1;
                const bool no_arrival = dist * std::pow(std::min(1.0, dist / prev_dist), left) > noise;
                if (no_linear && no_arrival) break;
            }
            prev_ratio = ratio;
            prev_dist = dist;
        }
        // M without a basis of eigenvectors (e.g. nilpotent on the circle): the distance shrinks by at
        // least (1 + rho)/2 in two successive steps.
        if (!diagonal && rho < 1 && e1.norm() <= 0.5 * (1 + rho) * e0.norm()) {
            if (++shrinking >= 2) return true;
        } else {
            shrinking = 0;
        }
        x = x1;
    }
    // The map's push along the segment from x to y keeps its sign: along the slow direction's left
    // eigenvector w where there is one (real mu_s >= 0.5, and the other direction contracts at least twice as
    // fast; w is blind to the fast direction to first order), else along the segment itself (the motion may
    // creep where the map is far from its linearisation at y: a law change next to y, i > 1). Two directions
    // that contract alike have no slow one: w is then either eigenvector, and away from y the flow turns it
    // (zeta 0.0041, theta 65.6 deg, rdisp 0.0176, i 0.5, |mu| 0.9906 and 0.9895: the push along w changed
    // sign a fifth of the way from rest while the push along the segment kept it; 54 -> 30 periods).
    Eigen::RowVector2d w = (y - x).normalized().transpose();
    const bool slow_real =
        !circle_state && diagonal && rho >= 0.5 && rho < 1 && std::abs(mu[0].imag()) <= 1e-12;
    const bool separated = 1 - std::abs(mu[1]) >= 2 * (1 - rho);
    if (slow_real && separated) {
        const int slow = std::abs(ces.eigenvalues()[0]) >= std::abs(ces.eigenvalues()[1]) ? 0 : 1;
        w = Vinv.row(slow).real();
    }
    // Where the segment stands in for a slow direction there is none of, its push alone decides: it must
    // exceed 64 units in the last place of l (relative to the segment), not be rounding whatever its sign
    // (zeta 0, theta 90 deg, rdisp 1e-8, i 5 from sliding, |mu| 1 - 1e-8 twice: pushes of 1e-15, and +-1e-32
    // at the circle, would have decided between not_converged and a state reached).
    const double floor = slow_real && !separated ? 64 * std::numeric_limits<double>::epsilon() : 0;
#ifdef FV_SOLVER_TRACE
    std::fprintf(stderr, "reaches: the push from (%.6g,%.6g), %d periods so far\n", x.x(), x.y(), periods);
#endif
    return pushes_towards(s, x, y, k, w, circle_state, floor, periods);
}

Orbit orbit_of(const ReachSetup& s, const Verified& v) {
    Orbit o;
    o.k = 1;
    o.l0 = v.l0;
    o.rx = v.last.force_integral.x() / kTwoPi;
    o.ry = v.last.force_integral.y() / kTwoPi;
    o.error_estimate = v.error_estimate;
    o.steady_error = v.steady_error;
    o.integration_error = v.integration_error;
    o.on_circle = v.search.on_circle || v.last.start == Phase::circle;
    o.M = Eigen::Matrix2d::Identity() + v.last.E;
    o.circle_state =
        v.last.start == Phase::circle && v.last.end == Phase::circle && v.last.events == 0 && s.p->i > 0;
    o.newton_steps = v.search.newton_steps;
    o.plain_steps = v.search.plain_steps;
    o.periods_skipped = v.search.periods_skipped;
    o.events_per_period = v.last.events;
    o.steps_per_period = static_cast<int>(v.last.steps);
    o.failure = v.failure;
    o.events = v.events;
    o.samples = v.samples;
    if (!v.converged) {
        o.status = v.search.status == SteadyStatus::converged ? SteadyStatus::not_converged : v.search.status;
    } else if (!(v.error_estimate <= s.tol)) {
        o.status = SteadyStatus::not_converged;
        o.failure = "error estimate above tolerance";
    } else {
        o.status = SteadyStatus::converged;
    }
    if (!std::isfinite(o.rx) || !std::isfinite(o.ry)) o.status = SteadyStatus::non_finite;
    return o;
}

void period1_multipliers(const ReachSetup& s, const PeriodResult& pr, Vec2 l0, cd mu[2]) {
    const Eigen::Matrix2d M = Eigen::Matrix2d::Identity() + pr.E;
    const bool whole_period_on_circle =
        pr.start == Phase::circle && pr.end == Phase::circle && pr.events == 0;
    if (!whole_period_on_circle || s.p->i == 0) {
        eigen_multipliers(M, mu);
        return;
    }
    // The angle's multiplier is M's nonzero eigenvalue (its trace); the radial one the approach from inside.
    mu[0] = M.trace();
    const double i = s.p->i;
    mu[1] = i < 1 ? 0.0 : i == 1 ? std::exp(-s.p->rdisp * circle_v_integral(s, l0)) : 1.0;
    sort_desc(mu);
}

Reach reach_from(const ReachSetup& s, Vec2 start, const std::vector<Vec2>& guesses, const Prior& prior) {
    const Params& p = *s.p;
    const LagModel& m = *s.m;
    Reach out;
    Orbit& st = out.state;
    int search_periods = 0;
    Orbit unstable_seen; // the closest fixed point found when nothing stable is reached
    bool have_unstable = prior.unstable != nullptr;
    if (prior.unstable) unstable_seen = *prior.unstable;
    auto searched_before = [&](const Vec2& g) { return near_any(prior.fruitless, g, 1e-12); };
    Search closest;

    // The last stable state found that the motion was not (yet) shown to reach.
    std::optional<Search> candidate;
    // Stable states that the evidence from the start itself did not show reached: the one the caller found
    // and tested from the start already, and those this call verified. Found again by another search (every
    // search from the starts may end in one: zeta 0.2253, theta 85.2 deg, rdisp 4.13, i 6.3 from sliding
    // tried the same evidence three times), such a state is only remembered, to try the evidence again from
    // further on: the test from the start would repeat itself.
    std::vector<Vec2> failed_from_start;
    if (prior.rejected) failed_from_start.push_back(prior.rejected->l0);
    // A converged period-1 search: its multipliers, the evidence that `from` (a point of the start's
    // motion) reaches it, its verification. True when it is the state reached. `retry`: the candidate again,
    // from a later point of the motion (verified and listed the first time).
    auto take_period1 = [&](const Search& sr, const Vec2& from, bool retry = false) {
        if (!sr.converged) {
            if (!closest.have_last || (sr.have_last && sr.dist < closest.dist)) closest = sr;
            return false;
        }
        // The same fixed point, to well within the searches' convergence.
        const double same_state = std::max(1e3 * s.aim, 1e-9);
        if (from == start && near_any(failed_from_start, sr.last_l0, same_state)) {
            candidate = sr;
            return false;
        }
        cd mu[2];
        period1_multipliers(s, sr.last, sr.last_l0, mu);
        const bool circle_state =
            sr.last.start == Phase::circle && sr.last.end == Phase::circle && sr.last.events == 0 && p.i > 0;
        if (!stable(mu)) {
            if (!have_unstable) {
                const Verified v = verify_fixed_point(p, m, sr, s.rq, s.aim, s.tol, false, 0, 0);
                unstable_seen = orbit_of(s, v);
                unstable_seen.status = SteadyStatus::unsettled;
                unstable_seen.failure = "the periodic state found is unstable: the motion does not settle";
                std::copy(mu, mu + 2, unstable_seen.mu);
                unstable_seen.have_mu = true;
                have_unstable = true;
            }
            return false;
        }
        const bool reached = reaches(s, from, sr.last_l0, Eigen::Matrix2d::Identity() + sr.last.E, 1,
                                     circle_state, out.periods);
#ifdef FV_SOLVER_TRACE
        std::fprintf(stderr,
                     "reach: evidence from (%.6g,%.6g) to (%.6g,%.6g) |mu| %.4g %.4g: %s, %d periods\n",
                     from.x(), from.y(), sr.last_l0.x(), sr.last_l0.y(), std::abs(mu[0]), std::abs(mu[1]),
                     reached ? "reached" : "not shown", out.periods);
#endif
        if (retry && !reached) return false; // verified and listed the first time
        const Verified v = verify_fixed_point(p, m, sr, s.rq, s.aim, s.tol, s.record && reached,
                                              s.record_samples, s.max_search_periods);
        out.periods += v.periods;
        Orbit o = orbit_of(s, v);
        std::copy(mu, mu + 2, o.mu);
        o.have_mu = true;
        o.on_circle = o.on_circle || circle_state;
        if (v.unstable) return false;
        if (reached) {
            o.reached = true;
            st = std::move(o);
            return true;
        }
        if (ok(o.status)) {
            add_other(out, std::move(o));
            candidate = sr;
            if (from == start) failed_from_start.push_back(sr.last_l0);
        }
        return false;
    };

    // Newton's method from g within `budget` periods, its periods counted against the searches' budget.
    auto search = [&](const Vec2& g, int budget) {
        const Search sr = search_from(p, m, g, s.rq, s.aim, budget, kGiveUp);
        search_periods += sr.periods;
        out.periods += sr.periods;
#ifdef FV_SOLVER_TRACE
        std::fprintf(stderr, "reach: search from (%.6g,%.6g): %s after %d periods (%d in all)\n", g.x(),
                     g.y(), sr.converged ? "converged" : sr.failure, sr.periods, out.periods);
#endif
        return sr;
    };

    // 1. Newton's method from the guesses (a warm start, the start itself, limits).
    for (const Vec2& g : guesses) {
        if (search_periods >= s.max_search_periods) break;
        if (searched_before(g)) continue;
        const Search sr = search(g, s.max_search_periods - search_periods);
        if (sr.status == SteadyStatus::integration_failed) {
            st.status = SteadyStatus::integration_failed;
            st.failure = sr.failure;
            return out;
        }
        if (take_period1(sr, start)) return out;
    }

    // A budget too small for a search's give-up rule is too small to follow the motion as well.
    if (s.max_search_periods < kGiveUp) {
        st.status = SteadyStatus::not_converged;
        st.failure = "period budget exhausted";
        st.error_estimate = closest.have_last ? closest.dist : std::numeric_limits<double>::infinity();
        if (closest.have_last) {
            st.rx = closest.last.force_integral.x() / kTwoPi;
            st.ry = closest.last.force_integral.y() / kTwoPi;
        }
        return out;
    }

    // 2. Follow the motion from the start; where its sections repeat after k periods (k = 1, 2, 4, ...),
    // Newton's method on the k-times map from there.
    const PeriodRequest rq_state = state_only(s);
    std::vector<Vec2> xs;
    Vec2 x = start;
    classify(m, 0, x);
    xs.push_back(x);
    int chunk = 4;
    // Where (in periods of the motion, integrated or projected over) each k was last tried.
    double followed = 0;
    std::vector<double> tried_at(kMaxPeriodK + 1, -1000);
    int creep_skips = 0, coasts = 0;
    bool tried_limits = false;
    while (static_cast<int>(xs.size()) <= kFollowPeriods) {
        Vec2 before = x;
        int creep_run = 0; // creep periods in a row at the chunk's end
        for (int j = 0; j < chunk; ++j) {
            before = x;
            PeriodResult last;
            if (!advance(s, x, rq_state, &last)) {
                st.status = SteadyStatus::integration_failed;
                st.failure = "the integrator could not continue";
                return out;
            }
            creep_run = creep_period(m, before, last) ? creep_run + 1 : 0;
            xs.push_back(x);
        }
        out.periods += chunk;
        followed += chunk;
        chunk = std::min(2 * chunk, 64);
        const int n = static_cast<int>(xs.size()) - 1;
        for (int k = 1; k <= kMaxPeriodK; k *= 2) {
            if (n < 2 * k) break;
            const double d = (xs[n] - xs[n - k]).norm(), dprev = (xs[n - k] - xs[n - 2 * k]).norm();
            // Repeating, or closing in (a slow creep for k = 1, a slow approach to a period-k orbit: zeta
            // 0.244623, theta 62 deg, rdisp 2, i 10 closes in on a period-2 orbit at 0.992 a period).
            if (!(d < 0.02 && (d < 1e-7 || d <= dprev))) continue;
            // Not a k whose multiple repeats far better: on or near a period-4 orbit the distance after 2
            // periods holds steady and passes for closing in, and Newton's method on the 2-times map would
            // spend its periods first, again and again (zeta 0.448, theta 8.1 deg, rdisp 37, i 10 from
            // sliding: 130 -> 508 periods until this held for every k, not only beside an unstable state).
            if (k > 1 && repeats_better(xs, k, d)) continue;
            // Just tried from near here: again once the motion has gone on for 16 k periods, and (a long
            // approach, still moving) as long again as before the last try.
            const double wait = d < 1e-7 ? 16.0 * k : std::max(16.0 * k, tried_at[k]);
            // Past an unstable period-1 state the motion hovers near it, so k = 1 qualifies over and over;
            // a longer k that repeats is then looked at as well, not only the smallest (zeta 0.45, theta
            // 8.1 deg, rdisp 37, i 10: a period-4 orbit within 3e-4 of the unstable state, which the motion
            // reaches in about 140 periods, was never tried).
            const bool longer_too = k == 1 && have_unstable;
            if (followed - tried_at[k] < wait) {
                if (longer_too) continue;
                break;
            }
            tried_at[k] = followed;
#ifdef FV_SOLVER_TRACE
            std::fprintf(stderr, "follow: k %d tried at %.0f periods followed (d %.3g, %d periods in all)\n",
                         k, followed, d, out.periods);
#endif
            if (k == 1 && candidate && (xs[n] - xs[n - 1]).dot(candidate->last_l0 - xs[n]) > 0) {
                // Heading for the state found before: the evidence again from here, without a new search.
                if (take_period1(*candidate, xs[n], true)) return out;
            } else if (k == 1 && have_unstable && d > kNearRepeat) {
                // Beside an unstable period-1 state, Newton's method from a motion whose sections are still
                // far from repeating lands where the first search went and retraces it (traced at zeta
                // 0.146142, theta 136 deg, rdisp 15.13, i 10: every search from the motion reached the same
                // point of the circle and gave up after 14 periods). Tried once the motion repeats more
                // closely, where it may be heading for another, stable period-1 state.
            } else if (k == 1) {
                const int budget = std::max(s.max_search_periods - search_periods, 100);
                const Search sr = search(xs[n], budget);
                if (take_period1(sr, xs[n])) return out;
                // Newton's method from the motion finds nothing where the map is nearly a translation there
                // (J = DPhi - I ~ 0: a slow drift at a steady rate, zeta = 0, theta = 90 deg from sliding):
                // once, the limits (search_starts.hpp) as well, the state found held to the same evidence
                // from this point of the motion. The guesses hold them all but the default search's own
                // start.
                if (!sr.converged && !tried_limits) {
                    tried_limits = true;
                    for (const Vec2& g : other_starts(m)) {
                        if (searched_before(g) || near_any(guesses, g, 1e-12)) continue;
                        if (take_period1(search(g, budget), xs[n])) return out;
                    }
                }
            } else {
                // Beside an unstable period-1 state, where the motion hovers and every k that repeats is
                // tried (longer_too): a short try, its orbit may not be there yet (the motion is followed on,
                // and k tried again from further on).
                const KSearch ks = newton_k(s, xs[n], k, (have_unstable ? 8 : 40) * k);
                out.periods += ks.periods;
                if (!ks.converged) break;
                cd mu[2];
                eigen_multipliers(ks.M, mu);
                if (!stable(mu)) break;
                if (repeats_sooner(s, ks.y, k, out.periods)) break;
                if (!reaches(s, xs[n], ks.y, ks.M, k, false, out.periods)) break;
                Orbit o = verify_k(s, ks, k, out.periods);
                o.reached = true;
                st = std::move(o);
                return out;
            }
            if (longer_too) continue;
            break;
        }
        // A slow creep towards the circle (i > 1), where Newton's method from the chunk's end (above) found
        // no state the motion reaches: skipped to a few periods before the motion leaves it
        // (creep_skip.hpp), and followed from there.
        // Only a creep of several periods in a row: a period-k orbit may have a creep period among its k.
        // A skip of a few periods is not taken (the motion is followed on as it is).
        if (creep_skips < kMaxCreepSkips && creep_run >= kMinCreepRun) {
            const CreepSkip cs = skip_creep(s, before, x);
            out.periods += cs.periods;
            if (cs.skipped >= kMinCreepSkip) {
                ++creep_skips;
                out.skipped += cs.skipped;
                x = cs.x;
                xs.assign(1, x);
                std::fill(tried_at.begin(), tried_at.end(), -1000);
                followed = 0;
                chunk = 4;
                continue;
            }
        }
        // A slow approach (successive steps aligned and changing little): projected over (coast.hpp), as far
        // again as the motion has gone, so that the evidence is tried on the way (a state is often shown to
        // be reached long before the motion gets near it).
        // Not over a creep (creep periods at the chunk's end): the creep skip above is made for it, and its
        // count of periods is what the output reports as the creep's length.
        if (coasts < kMaxCoasts && n >= 2 && creep_run == 0) {
            const Coast cs = coast(s, xs[n - 2], xs[n - 1], xs[n], std::max(followed, 64.0));
            out.periods += cs.periods;
            followed += cs.periods;
            if (cs.jumps > 0) {
                ++coasts;
                followed += cs.skipped;
                x = cs.c;
                xs = {cs.a, cs.b, cs.c};
                chunk = 4;
            }
        }
    }

    // 3. No periodic state reached: the long-time means over a window, their standard error from batch
    // means (the batches long enough to be nearly independent where the motion mixes).
    std::vector<Vec2> batch(kWindowBatches, Vec2::Zero());
    const int per_batch = kWindowPeriods / kWindowBatches;
    // At an 8x looser tolerance: the means' integration error (~0.4 of the quadrature's tolerance per unit
    // time, 8 x 0.3 tol here) stays below a tenth of the smallest standard error reported (10 tol, below),
    // and the window costs 15-30 % less (zeta 0.075, theta 30 deg, rdisp 100, i 10: 0.31 -> 0.26 s).
    const PeriodRequest rq_means{8 * s.rq.atol, 8 * s.rq.atol_force, false};
    PeriodResult pr;
    // How far the motion's sections range within each batch: a motion that keeps moving over the sections
    // as much at the window's end as at its start does not settle, however well its means agree.
    std::vector<double> reach_of_batch(kWindowBatches, 0.0);
    for (int b = 0; b < kWindowBatches; ++b) {
        const Vec2 x_b = x;
        for (int j = 0; j < per_batch; ++j) {
            if (!advance(s, x, rq_means, &pr)) {
                st.status = SteadyStatus::integration_failed;
                st.failure = "the integrator could not continue";
                return out;
            }
            batch[static_cast<std::size_t>(b)] += pr.force_integral / kTwoPi;
            reach_of_batch[static_cast<std::size_t>(b)] =
                std::max(reach_of_batch[static_cast<std::size_t>(b)], (x - x_b).norm());
        }
        batch[static_cast<std::size_t>(b)] /= per_batch;
    }
    out.periods += kWindowPeriods;
    // The motion may have settled within the window (a slow approach that took longer than the periods
    // followed): where the window's last half no longer moves, Newton's method from its end.
    {
        double late = 0;
        for (int b = kWindowBatches / 2 + 1; b < kWindowBatches; ++b)
            late =
                std::max(late, (batch[static_cast<std::size_t>(b)] - batch[static_cast<std::size_t>(b - 1)])
                                   .cwiseAbs()
                                   .maxCoeff());
        if (late <= s.tol) {
            const Search sr = search_from(p, m, x, s.rq, s.aim, std::max(s.max_search_periods, 100), kGiveUp);
            out.periods += sr.periods;
            if (take_period1(sr, x)) return out;
        }
    }
    Vec2 mean = Vec2::Zero();
    for (const Vec2& b : batch) mean += b;
    mean /= kWindowBatches;
    Vec2 var = Vec2::Zero();
    for (const Vec2& b : batch) var += (b - mean).cwiseAbs2();
    var /= kWindowBatches - 1;
    const double se = std::sqrt(std::max(var.x(), var.y()) / kWindowBatches);
    // A motion still creeping towards a state drifts one way through the window: its batch means follow
    // a line (least squares on the batch index) to within a small part of their spread.
    double drift_fit = 0, spread = 0;
    for (int c = 0; c < 2; ++c) {
        double sx = 0, sxx = 0, sy = 0, sxy = 0;
        for (int b = 0; b < kWindowBatches; ++b) {
            const double y = batch[static_cast<std::size_t>(b)][c];
            sx += b, sxx += double(b) * b, sy += y, sxy += b * y;
        }
        const double nb = kWindowBatches;
        const double slope = (nb * sxy - sx * sy) / (nb * sxx - sx * sx), icpt = (sy - slope * sx) / nb;
        for (int b = 0; b < kWindowBatches; ++b) {
            const double y = batch[static_cast<std::size_t>(b)][c];
            drift_fit = std::max(drift_fit, std::abs(y - (icpt + slope * b)));
            spread = std::max(spread, std::abs(y - mean[c]));
        }
    }
    bool drifting = false;
    for (int c = 0; c < 2; ++c) {
        int up = 0, down = 0;
        for (int b = 1; b < kWindowBatches; ++b) {
            const double d =
                batch[static_cast<std::size_t>(b)][c] - batch[static_cast<std::size_t>(b - 1)][c];
            up += d > 0, down += d < 0;
        }
        drifting = drifting || up == kWindowBatches - 1 || down == kWindowBatches - 1;
    }
    drifting = drifting || (spread > 0 && drift_fit <= 0.05 * spread);
    // Or the window's halves differ by more than their means' scatter allows (3 standard errors of the
    // difference): a stationary irregular motion gives the same mean in both halves.
    {
        const int h = kWindowBatches / 2;
        Vec2 first = Vec2::Zero(), second = Vec2::Zero();
        for (int b = 0; b < h; ++b) first += batch[static_cast<std::size_t>(b)] / h;
        for (int b = h; b < kWindowBatches; ++b)
            second += batch[static_cast<std::size_t>(b)] / (kWindowBatches - h);
        drifting =
            drifting || (first - second).cwiseAbs().maxCoeff() > 3 * std::sqrt(2.0) * se * std::sqrt(2.0);
    }
#ifdef FV_SOLVER_TRACE
    std::fprintf(stderr, "window: se %.3g drifting %d reach first %.3g last %.3g\n", se, drifting,
                 reach_of_batch.front(), reach_of_batch.back());
#endif
    // Sections that range as far in the window's last batch as in its first (at least half as far), and far
    // beyond the tolerance: the motion goes on moving (e.g. round an invariant curve of the map: zeta 0.448,
    // theta 8.1 deg, rdisp 37, i 10, whose only period-1 state has mu = 1.51; the sections range over
    // 4.5e-4 in every batch while the batch means agree to 1e-7), so its means are its steady values.
    const bool moving = reach_of_batch.back() >= 0.5 * reach_of_batch.front() &&
                        reach_of_batch.back() > kMovingSections * s.tol;
    if ((se <= 10 * s.tol && !moving) || drifting) {
        // The motion hardly changes any more, yet no periodic state could be vouched for: a slow transient
        // or a state the searches could not pin down. Not a result; the window's means are shown.
        if (have_unstable) {
            st = unstable_seen;
            return out;
        }
        st = Orbit{};
        st.status = SteadyStatus::not_converged;
        st.rx = mean.x();
        st.ry = mean.y();
        st.error_estimate = std::max(se, closest.have_last ? closest.dist : se);
        st.l0 = x;
        st.failure = drifting ? "the motion still creeps towards a state after the periods followed"
                              : "the motion settles, but no periodic state could be verified";
        return out;
    }
    st = Orbit{};
    st.status = SteadyStatus::not_periodic;
    st.rx = mean.x();
    st.ry = mean.y();
    st.standard_error = se;
    st.window = kWindowPeriods;
    // Not below the means' integration error (the window's looser tolerance above).
    st.error_estimate = std::max(se, 10 * s.tol);
    st.l0 = x;
    st.failure = "the motion does not repeat: long-time means over a window";
    if (have_unstable) {
        std::copy(unstable_seen.mu, unstable_seen.mu + 2, st.mu);
        st.have_mu = true;
    }
    return out;
}

} // namespace fv::solver
