// Drives the lag through its phases over [tau0, tau1] (see period_map.hpp and docs/model.md).
//
// Events (where the law changes) and what they do to the derivative of the map (saltation matrices,
// S = I + (f+ - f-) grad(g)^T / (grad(g) . f-)):
//   reach    |l| = 1 with v > 0 (stick -> circle for i = 0; interior -> circle at 1 - rho = kPin for i > 0):
//            f- - f+ = (radial part) e, grad g = e, so S = I - e e^T: the radial perturbation is forgotten
//            and the arc coordinate takes da = e_perp . dL.
//   leave    v = e . P' turns negative on the circle: f is continuous there (v = 0), S = I; dL = e_perp da.
//   velocity v changes sign inside (i > 0): continuous, only a kink; S = I.
// Every event is located on the step's collocation polynomial, and the step is then retaken to end
// exactly there, so the state at the event carries the method's full order.
#include "period_map.hpp"
#include "plane_angles.hpp"

#include "radau_iia.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fv::solver {
namespace {

// An event function of the current phase: it must stay on the side `sign` (sign * g >= -noise); the event
// is the first instant where it leaves.
struct EventFn {
    OdeEventKind kind;
    double sign;
    double noise;
};

enum class StepEnd { reached_end, event, failed };

// The cubic through an event function's values at a Radau step's nodes s = 0, c1, c2, 1, at s = q/16
// (q = 1..15): Lagrange weights, the same for every step (computed once; per step they cost more than the
// step's own arithmetic for these small systems).
constexpr int kCubicProbes = 15;
struct CubicWeights {
    double w[kCubicProbes][4];
    CubicWeights() {
        const double node[4] = {0, RadauTableau::c1, RadauTableau::c2, 1};
        for (int q = 0; q < kCubicProbes; ++q) {
            const double x = (q + 1) / 16.0;
            for (int k = 0; k < 4; ++k) {
                w[q][k] = 1;
                for (int m = 0; m < 4; ++m)
                    if (m != k) w[q][k] *= (x - node[m]) / (node[k] - node[m]);
            }
        }
    }
};
const CubicWeights kCubic;

struct PhaseOutcome {
    StepEnd how = StepEnd::reached_end;
    int event = -1;      // index into the event list
    double short_by = 0; // how far the event function still was on the old side where the event was taken
};

// Integrates y' = f from tau to tau1 with Radau IIA steps until tau1 or the first event.
// g(k, tau, y) evaluates event function k; on_step(step, s_end) is called for every accepted step (s_end = 1)
// or the step retaken to an event, with the step's integral of F.
template <class Pb, class G, class OnStep>
PhaseOutcome integrate_phase(const Pb& pb, double& tau, double tau1, typename Pb::Vec& y, double& h,
                             const PeriodRequest& rq, const EventFn* evs, int n_ev, const G& g,
                             OnStep on_step, PeriodResult& out) {
    using Vec = typename Pb::Vec;
    constexpr int kProbes = 4; // dense-output probes per step for sign changes of the event functions
    RadauStep<Pb> prev;
    typename Pb::Point start = pb.eval(tau, y); // the law at (tau, y)
    bool have_prev = false;
    bool after_reject = true;
    PhaseOutcome res;
    while (tau1 - tau > 1e-14 * (1 + std::abs(tau))) {
        if (out.steps + out.rejected >= rq.max_steps) {
            out.ok = false;
            out.failure = "step budget exhausted";
            res.how = StepEnd::failed;
            return res;
        }
        double hh = std::min({h, rq.max_step, tau1 - tau});
        if (tau1 - tau - hh < 1e-9) hh = tau1 - tau;
        RadauStep<Pb> st = radau_step(pb, tau, y, start, hh, rq.atol, have_prev ? &prev : nullptr,
                                      rq.sensitivity, after_reject);
        // The period means are a quadrature of F over the steps, controlled as well (see step_integral).
        Eigen::Vector2d integral(0, 0);
        double qerr = 0; // quadrature error relative to its tolerance; ~h^5
        if (st.solved && st.error <= 1) {
            integral = step_integral(pb, st, qerr);
            qerr /= rq.atol_force * hh;
        }
        // Step factor from both estimates (the state's ~h^4, the quadrature's ~h^5).
        auto factor = [&] {
            const double fs = st.error > 0 ? 0.9 / std::sqrt(std::sqrt(st.error)) : 4.0;
            const double fq = qerr > 0 ? 0.9 * std::pow(qerr, -0.2) : 4.0;
            return std::min({4.0, fs, fq});
        };
        if (qerr > 1) st.error = std::max(st.error, qerr);
        if (!st.solved || !(st.error <= 1)) {
            ++out.rejected;
            after_reject = true;
            have_prev = false;
            const double fac = st.solved && std::isfinite(st.error) ? std::max(0.1, factor()) : 0.25;
            h = hh * fac;
            if (h < 1e-13 * (1 + std::abs(tau))) {
                out.ok = false;
                out.failure = "step size underflow";
                res.how = StepEnd::failed;
                return res;
            }
            continue;
        }
        // Events: the first probe where some event function is off its side. The probes inside the step are
        // needed only where some function comes near its zero: at the step's start and at the three stages
        // (where the law is known already) each must stay on its side by a quarter of its largest size there.
        const double tn[4] = {tau, tau + RadauTableau::c1 * hh, tau + RadauTableau::c2 * hh, tau + hh};
        // Also the cubic through the four values must stay on its side: four values well clear of zero
        // can straddle a dip between them (v = zeta + cos tau near tau = pi for zeta just below 1).
        bool clear = true;
        for (int j = 0; j < n_ev && clear; ++j) {
            double lo = std::numeric_limits<double>::infinity(), big = 0, gv[4];
            for (int k = 0; k < 4; ++k) {
                gv[k] = evs[j].sign * g(j, tn[k], k == 0 ? st.p0 : st.pz[k - 1]);
                lo = std::min(lo, gv[k]);
                big = std::max(big, std::abs(gv[k]));
            }
            clear = lo >= 0.25 * big + evs[j].noise;
            for (int q = 0; q < kCubicProbes && clear; ++q) {
                const double cubic = kCubic.w[q][0] * gv[0] + kCubic.w[q][1] * gv[1] +
                                     kCubic.w[q][2] * gv[2] + kCubic.w[q][3] * gv[3];
                clear = cubic > evs[j].noise; // the cubic predicts no crossing
            }
        }
        int hit = -1;
        double s_lo = 0, s_hi = 0;
        // g_j at s of the step (the dense output; the step's end is its last stage).
        auto g_at = [&](int j, double s) {
            return evs[j].sign * (s == 1 ? g(j, tau + hh, st.pz[2]) : g(j, tau + s * hh, st.at(s)));
        };
        for (int k = clear ? kProbes : 1; k <= kProbes && hit < 0; ++k) {
            const double s = static_cast<double>(k) / kProbes;
            for (int j = 0; j < n_ev; ++j)
                if (g_at(j, s) < -evs[j].noise) {
                    hit = j;
                    s_lo = static_cast<double>(k - 1) / kProbes;
                    s_hi = s;
                    break;
                }
        }
        if (!clear) {
            // A function came near its zero: it may dip below and come back between probes, before the
            // first coarse probe found off its side or where none is (theta = 0, zeta just below 1: v = zeta
            // + cos tau < 0 for 2 sqrt(2 (1 - zeta)) around tau = pi, 0.11 at zeta = 0.9984 against steps of
            // 0.5; missed, the tip stayed on the circle and r_x came out 1 instead of 0.99955). Each
            // function's smallest value over the step is found (finer probes, then golden section around the
            // least); a dip below is an event, its first crossing before the minimum.
            constexpr int kFine = 16;
            // Where a coarse probe is off its side already, only the stretch before the probe ahead of it.
            const int k_end = hit >= 0 ? static_cast<int>(s_lo * kFine + 0.5) : kFine;
            for (int j = 0; j < n_ev && k_end > 0; ++j) {
                int k_min = 0;
                double g_min = g_at(j, 0);
                int k_off = -1; // the first fine probe off its side
                for (int k = 1; k <= k_end && k_off < 0; ++k) {
                    const double gk = g_at(j, static_cast<double>(k) / kFine);
                    if (gk < g_min) g_min = gk, k_min = k;
                    if (gk < -evs[j].noise) k_off = k;
                }
                if (k_off > 0) {
                    const double s_off = static_cast<double>(k_off) / kFine;
                    if (hit < 0 || s_off < s_hi) {
                        hit = j;
                        s_hi = s_off;
                        s_lo = static_cast<double>(k_off - 1) / kFine;
                    }
                    continue;
                }
                double a = std::max(0, k_min - 1) / static_cast<double>(kFine);
                double b = std::min(k_end, k_min + 1) / static_cast<double>(kFine);
                constexpr double kGold = 0.6180339887498949;
                double c = b - kGold * (b - a), d = a + kGold * (b - a);
                double gc = g_at(j, c), gd = g_at(j, d);
                for (int it = 0; it < 60 && b - a > 1e-12 && gc >= -evs[j].noise && gd >= -evs[j].noise;
                     ++it) {
                    if (gc < gd) {
                        b = d, d = c, gd = gc;
                        c = b - kGold * (b - a);
                        gc = g_at(j, c);
                    } else {
                        a = c, c = d, gc = gd;
                        d = a + kGold * (b - a);
                        gd = g_at(j, d);
                    }
                }
                const double s_min = gc < gd ? c : d;
                if (std::min(gc, gd) < -evs[j].noise && (hit < 0 || s_min < s_hi)) {
                    hit = j;
                    s_hi = s_min;
                    s_lo = std::floor(s_min * kFine) / kFine; // a probe, and every probe is on its side
                }
            }
        }
        if (hit >= 0) {
            // Earliest crossing in (s_lo, s_hi] among the functions that leave their side there.
            double best = s_hi;
            double roots[4] = {s_hi, s_hi, s_hi, s_hi}; // located crossing of each function (n_ev <= 4)
            for (int j = 0; j < n_ev; ++j) {
                auto gj = [&](double s) {
                    return evs[j].sign *
                           (s == 1 ? g(j, tau + s * hh, st.pz[2]) : g(j, tau + s * hh, st.at(s)));
                };
                if (!(gj(s_hi) < -evs[j].noise)) continue;
                double a = s_lo, b = s_hi;
                double fa = std::max(gj(a), std::numeric_limits<double>::min()), fb = gj(b);
                int side = 0;
                for (int it = 0; it < 100 && b - a > 1e-15; ++it) {
                    double c = (a * fb - b * fa) / (fb - fa);
                    if (!(c > a && c < b)) c = 0.5 * (a + b);
                    const double fc = gj(c);
                    // On its side as the event test defines it: a phase that starts exactly on the
                    // function's zero (v = 0 where the tip just left the circle) is not an event at once.
                    if (fc >= -evs[j].noise) {
                        a = c;
                        fa = fc;
                        if (side == -1) fb *= 0.5;
                        side = -1;
                    } else {
                        b = c;
                        fb = fc;
                        if (side == 1) fa *= 0.5;
                        side = 1;
                    }
                }
                if (j < 4) roots[j] = b;
                if (b < best || (b == best && j < hit)) {
                    best = b;
                    hit = j;
                }
            }
#ifdef FV_SOLVER_TRACE
            std::fprintf(stderr, "  event: tau=%.9f hh=%.3e s_lo=%g s_hi=%g best=%.12g hit=%d\n", tau, hh,
                         s_lo, s_hi, best, hit);
#endif
            // Retake the step to end at the event. The collocation polynomial locates it to its own accuracy
            // (order 3); the retaken step is order 5 and may still be a hair on the old side. Secant
            // corrections of its length put it on the new side, so that the next phase starts where its law
            // holds (else it would switch back at once).
            double he = best * hh;
            // No further than a hair past the located root, and never past another event: where two events
            // fall within that hair (the tip grazes the circle just as v turns), stepping past the other one
            // would integrate its stretch with the wrong law.
            double s_cap = std::min(s_hi, best + 0.01);
            for (int j = 0; j < n_ev && j < 4; ++j)
                if (j != hit && roots[j] > best) s_cap = std::min(s_cap, roots[j]);
            const double h_cap = s_cap * hh;
            const double slope = [&] {
                const double d = std::min(1e-3, best);
                const double g1 = evs[hit].sign * g(hit, tau + best * hh, st.at(best));
                const double g0 = evs[hit].sign * g(hit, tau + (best - d) * hh, st.at(best - d));
                return d > 0 ? (g1 - g0) / (d * hh) : 0.0;
            }();
            RadauStep<Pb> se;
            bool have_se = false;
            double short_by = 0;
            for (int it = 0; it < 6 && he > 1e-13 * (1 + std::abs(tau)); ++it) {
                RadauStep<Pb> trial = radau_step(pb, tau, y, start, he, rq.atol, &st, rq.sensitivity, false);
                if (!trial.solved) break;
                se = trial;
                have_se = true;
                const double ge = evs[hit].sign * g(hit, tau + he, se.pz[2]);
                short_by = std::max(0.0, ge);
                if (ge <= 0 || !(slope < 0) || he >= h_cap) break;
                bool other = false;
                for (int j = 0; j < n_ev; ++j)
                    if (j != hit && evs[j].sign * g(j, tau + he, se.pz[2]) < -evs[j].noise) other = true;
                if (other) break;
                he = std::min(h_cap, he + 1.5 * ge / -slope +
                                         4 * std::numeric_limits<double>::epsilon() * (1 + std::abs(tau)));
            }
            if (!have_se && he > 1e-13 * (1 + std::abs(tau))) {
                // The stage equations of the shorter step did not converge (a singular law next to the circle
                // for i < 1): the accepted step's collocation polynomial stands in, order 3 at the event.
                se = st;
                se.h = he;
                const double cs[3] = {RadauTableau::c1 * best, RadauTableau::c2 * best, best};
                for (int j = 0; j < 3; ++j) {
                    se.z[j] = st.at(cs[j]) - y;
                    se.pz[j] = pb.eval(tau + cs[j] * hh, Vec(y + se.z[j]));
                }
                se.dy1_dy0_minus_i = st.dy1_dy0_minus_i * best; // first order in the fraction of the step
                have_se = true;
                short_by = std::max(0.0, evs[hit].sign * g(hit, tau + he, se.pz[2]));
            }
            if (he > 1e-13 * (1 + std::abs(tau))) {
                ++out.steps;
                double qerr_e = 0;
                on_step(se, step_integral(pb, se, qerr_e));
                tau += se.h;
                y = se.y1();
            }
            res.how = StepEnd::event;
            res.event = hit;
            res.short_by = short_by;
            return res;
        }
        ++out.steps;
#ifdef FV_SOLVER_TRACE
        std::fprintf(stderr, "  step tau=%.9f h=%.3e err=%.2e qerr=%.2e g0(start)=%.3e g0(end)=%.3e\n", tau,
                     hh, st.error, qerr, g(0, tau, y), g(0, tau + hh, st.y1()));
#endif
        on_step(st, integral);
        tau += hh;
        y = st.y1();
        start = st.pz[2];
        prev = st;
        have_prev = true;
        after_reject = false;
        h = hh * std::max(0.2, factor());
    }
    tau = tau1;
    return res;
}

} // namespace

Phase classify(const LagModel& m, double tau, Vec2& l) {
    const double rho = l.norm();
    if (rho > 1) l /= rho;
    const double v = l.dot(m.dP(tau));
    const double on = m.i == 0 ? 1 - 1e-11 : 1 - kPin;
    if (rho >= on && v > 0) {
        l /= l.norm();
        return Phase::circle;
    }
    return m.i == 0 ? Phase::stick : Phase::interior;
}

PeriodResult run_lag(const LagModel& m, Vec2 l0, double tau0, double tau1, const PeriodRequest& rq) {
    PeriodResult out;
    const double r = m.r;
    Vec2 l = l0;
    Phase ph = classify(m, tau0, l);
    out.start = ph;
    double tau = tau0;
    // Sensitivity: M = I + E while the state is in the plane; R = d a / d L(tau0) (a row) on the circle.
    Eigen::Matrix2d& E = out.E;
    E.setZero();
    Eigen::RowVector2d R = Eigen::RowVector2d::Zero();
    if (ph == Phase::circle) {
        R = perp(l).transpose();
        out.visited_circle = true;
    }
    double s = 1; // branch of the interior law
    {
        const double v = l.dot(m.dP(tau));
        s = v < 0 ? -1 : 1;
    }
    double h = 0.01;
    int next_sample = 1;
    const int n_samples = rq.samples ? std::max(1, rq.n_samples) : 0;
    auto sample_at = [&](double ts, const Vec2& lf) {
        Sample sm;
        sm.tau = ts;
        sm.P = body_point(*rq.params, ts);
        Vec2 lc = lf;
        const double rho = lc.norm();
        if (rho > 1)
            lc /= rho; // dense output may stray past the circle by the tolerance; the model never does
        sm.F = lc;
        sm.T = sm.P - lc / r;
        sm.z = lc.norm() / r;
        rq.samples->push_back(sm);
    };
    // Samples falling in (ta, tb]; lf(t) gives the force there.
    auto record = [&](double ta, double tb, auto lf) {
        if (!rq.samples) return;
        while (next_sample <= n_samples) {
            const double ts = tau0 + (tau1 - tau0) * next_sample / n_samples;
            const bool last = next_sample == n_samples && tb >= tau1 - 1e-12;
            if (ts > tb && !last) break;
            (void)ta;
            sample_at(ts, lf(std::min(ts, tb)));
            ++next_sample;
        }
    };
    auto event = [&](OdeEventKind k) {
        ++out.events;
        if (rq.events) rq.events->push_back({tau, k, Vec2(l / r)});
    };
    auto to_circle = [&] {
        // Pin onto the circle: the radial remainder (at most kPin) is dropped, and with it the radial
        // perturbation (saltation S = I - e e^T).
        const Vec2 lc = l / l.norm();
        out.dL += (lc - l) / r;
        l = lc;
        R = perp(l).transpose() * (Eigen::Matrix2d::Identity() + E);
        ph = Phase::circle;
        out.visited_circle = true;
    };
    int same_instant = 0;
    double last_event_tau = -1;

    while (tau1 - tau > 1e-14 * (1 + std::abs(tau))) {
        if (out.events > 0 && tau == last_event_tau) {
            if (++same_instant > 20) {
                out.ok = false;
                out.failure = "events chatter at one instant";
                break;
            }
        } else {
            same_instant = 0;
        }
        last_event_tau = tau;
        if (ph == Phase::stick) {
            const std::optional<double> ts = stick_slip_time(m, tau, l, tau1);
            const double tb = ts ? *ts : tau1;
            const Vec2 la = l;
            const double ta = tau;
            record(ta, tb, [&](double t) { return Vec2(la + r * m.dispP(ta, t)); });
            out.force_integral += la * (tb - ta) + r * m.int_dispP(ta, tb);
            if (rq.sensitivity) out.G += (tb - ta) * (Eigen::Matrix2d::Identity() + E); // T fixed: dl/dl0 too
            out.dL += m.dispP(ta, tb);
            l = la + r * m.dispP(ta, tb);
            tau = tb;
            if (ts) {
                to_circle();
                event(OdeEventKind::reach_zss);
            }
            continue;
        }
        if (ph == Phase::circle) {
            const CircleProblem pb{&m, std::atan2(l.y(), l.x())};
            Eigen::Matrix<double, 1, 1> a;
            a.setZero();
            const EventFn evs[1] = {{OdeEventKind::leave_zss, 1.0, 1e-14 * (1 + m.zeta)}};
            auto g = [&](int, double t, const auto& y) { return pb.force(y).dot(m.dP(t)); };
            auto on_step = [&](const RadauStep<CircleProblem>& st, const Eigen::Vector2d& integral) {
                out.force_integral += integral;
                out.v_min_circle =
                    std::min({out.v_min_circle, st.p0.e.dot(st.p0.dp), st.pz[0].e.dot(st.pz[0].dp),
                              st.pz[1].e.dot(st.pz[1].dp), st.pz[2].e.dot(st.pz[2].dp)});
                if (rq.sensitivity) {
                    // dl/dl0 = e_perp R on the circle; its integral by the trapezoidal rule.
                    const Eigen::Matrix2d m0 = perp(pb.force(st.p0)) * R;
                    R *= 1 + st.dy1_dy0_minus_i(0, 0);
                    out.G += 0.5 * st.h * (m0 + perp(pb.force(st.pz[2])) * R);
                }
                record(st.tau0, st.tau0 + st.h,
                       [&](double t) { return pb.force(st.at((t - st.tau0) / st.h)); });
            };
            const PhaseOutcome oc = integrate_phase(pb, tau, tau1, a, h, rq, evs, 1, g, on_step, out);
            // Displacement on the circle, zss (e(phi_a + r a) - e(phi_a)), without cancellation.
            const double half = 0.5 * r * a[0];
            const double mid = pb.phi_a + half;
            out.dL += (2 * std::sin(half) / r) * Vec2(-std::sin(mid), std::cos(mid));
            l = pb.force(a);
            if (oc.how == StepEnd::failed) break;
            if (oc.how == StepEnd::event) {
                E = perp(l) * R - Eigen::Matrix2d::Identity();
                out.left_circle = true;
                ph = m.i == 0 ? Phase::stick : Phase::interior;
                s = -1;
                event(OdeEventKind::leave_zss);
            }
            continue;
        }
        // Interior (i > 0).
        const InteriorProblem pb(m, l, s);
        Eigen::Vector2d D = Eigen::Vector2d::Zero();
        const bool can_reach = s > 0;
        const EventFn evs[2] = {{OdeEventKind::velocity_sign, s, 1e-14 * (1 + m.zeta)},
                                {OdeEventKind::reach_zss, -1.0, 0.0}};
        auto g = [&](int k, double t, const auto& y) {
            const Vec2 lf = pb.force(y);
            return k == 0 ? lf.dot(m.dP(t)) : lf.norm() - (1 - kPin);
        };
        auto on_step = [&](const RadauStep<InteriorProblem>& st, const Eigen::Vector2d& integral) {
            out.force_integral += integral;
            if (rq.sensitivity) {
                const Eigen::Matrix2d m0 = Eigen::Matrix2d::Identity() + E;
                E += st.dy1_dy0_minus_i * m0;
                out.G += 0.5 * st.h * (m0 + Eigen::Matrix2d::Identity() + E);
            }
            record(st.tau0, st.tau0 + st.h, [&](double t) { return pb.force(st.at((t - st.tau0) / st.h)); });
        };
        const PhaseOutcome oc =
            integrate_phase(pb, tau, tau1, D, h, rq, evs, can_reach ? 2 : 1, g, on_step, out);
        out.dL += D;
        l = pb.force(D);
        if (oc.how == StepEnd::failed) break;
        if (oc.how == StepEnd::event) {
            if (oc.event == 0) {
                s = -s;
                event(OdeEventKind::velocity_sign);
            } else {
                // Reached where the step had to stop short (the tip grazes the circle just as v turns, and
                // the velocity event comes first): for i >= 1 the remainder dropped by pinning is an error
                // of its own. For i < 1 the law closes a gap d in a time ~ d^(1 - i) (finite-time reach), so
                // dropping it only moves the reach that much earlier.
                if (m.i >= 1) out.pin_drop = std::max(out.pin_drop, oc.short_by);
                to_circle();
                event(OdeEventKind::reach_zss);
            }
        }
    }
    out.end = ph;
    out.l_end = l;
    if (!l.allFinite() || !out.force_integral.allFinite() || !out.E.allFinite()) {
        out.ok = false;
        out.failure = "non-finite state";
    }
    if (ph == Phase::circle && out.ok) {
        // The map ends on the circle: dL(tau1) = e_perp da.
        E = perp(l) * R - Eigen::Matrix2d::Identity();
    }
    return out;
}

} // namespace fv::solver
