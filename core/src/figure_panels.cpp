#include "figure_panels.hpp"

#include "fv/axis_titles.hpp"
#include "fv/format.hpp"
#include "fv/paper_scheme.hpp"
#include "fv/rigid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Appends (x, y), first a NaN break where the curve jumps (the rigid friction reverses at once for
// theta = 0), so that no line is drawn across the jump.
void append(SeriesData& s, double x, double y, double jump) {
    if (!s.x.empty() && std::isfinite(s.y.back()) && std::hypot(x - s.x.back(), y - s.y.back()) > jump) {
        s.x.push_back(kNaN);
        s.y.push_back(kNaN);
    }
    s.x.push_back(x);
    s.y.push_back(y);
}

const char* const kPhase[] = {"τ = 0", "π/4", "π/2", "3π/4", "π"};

// The left panel of Fig. 4 in the plane: v/v_v and F/F_c at tau = k pi/4 as arrows from the origin, their
// loci over the period and the mean friction.
PanelData plane_panel(const Params& p, const Ratio& r) {
    const Vec2 e(std::cos(p.theta), std::sin(p.theta)); // the vibration's direction
    PanelData plane;
    plane.title = "velocity v/v_{v} and friction F/F_{c} at τ = kπ/4";
    plane.x_title = "along v_{b}";
    plane.y_title = "across v_{b}";
    plane.equal_aspect = true;
    plane.circles.push_back({Vec2::Zero(), 1.0, Ink::spring, Dash::dotted, 1.2f});
    // The loci over the whole period: v(tau) runs along a segment of length 2 centred on v_b/v_v = (zeta, 0)
    // (Eq. 1); F(tau) along an arc of the unit circle (Eq. 2).
    const Vec2 vb(p.zeta, 0), v0 = vb - e, v1 = vb + e;
    plane.series.push_back({"v(τ)/v_{v}, whole period",
                            {v0.x(), v1.x()},
                            {v0.y(), v1.y()},
                            Ink::body,
                            Dash::dashed,
                            Mark::none,
                            1.5f});
    SeriesData arc{
        "F(τ)/F_{c} = −v/|v|, whole period", {}, {}, Ink::tip, Dash::solid, Mark::none, 5.f, 0.35f};
    for (int k = 0; k <= 720; ++k) {
        const Vec2 f = coulomb(body_velocity(p, kPi * k / 720));
        append(arc, f.x(), f.y(), 0.2);
    }
    plane.series.push_back(std::move(arc));
    for (int k = 0; k <= 4; ++k) {
        const double tau = kPi * k / 4;
        const Vec2 v = body_velocity(p, tau);
        // Nearly parallel vibration: the velocities lie along one line, so their labels go above the heads.
        plane.arrows.push_back({Vec2::Zero(), v, Ink::body, kPhase[k], 2.f, std::abs(e.y()) < 0.25 ? -1 : 0});
        plane.arrows.push_back({Vec2::Zero(), coulomb(v), Ink::tip, "", 2.f});
    }
    // The mean friction; its label beside its head on the side away from the friction arrow along -x (at
    // tau = pi/2, theta = 90 deg the two overlie each other): above when the mean points up, else below.
    plane.arrows.push_back({Vec2::Zero(), Vec2(-r.rx, -r.ry), Ink::black, "", 3.5f});
    plane.points.push_back(
        {Vec2(-r.rx, -r.ry), Ink::black, Mark::circle, "mean friction", 6, -1, -r.ry > 1e-3 ? -1 : 1});
    plane.points.push_back({vb, Ink::body, Mark::cross, "v_{b}/v_{v}", 9, 1, 1});
    const double x1 = std::max({1.0, v0.x(), v1.x()}), x0 = std::min({-1.0, v0.x(), v1.x()});
    plane.x_min = x0 - 0.45, plane.x_max = x1 + 0.45;
    plane.y_min = std::min(-1.0, std::min(v0.y(), v1.y())) - 0.25;
    plane.y_max = std::max(1.0, std::max(v0.y(), v1.y())) + 0.25;
    plane.legend = Legend::bottom_left;
    return plane;
}

// The instants of parallel_panel's rows, tau = k pi/4 over the whole period.
const char* const kInstant[] = {"τ = 0", "π/4", "π/2", "3π/4", "π", "5π/4", "3π/2", "7π/4", "2π"};

// The left panel of Fig. 4 where the vibration runs along v_b or nearly (mechanism_parallel): v and F stay
// on one line, so each instant tau = k pi/4 gets a row up a time axis with v/v_v's component along v_b just
// above it (blue) and F/F_c's just below (vermilion). Read upwards, v shrinks, reverses where v_x = 0 and
// grows back, and the friction reverses with it; the mean friction is the dashed black line across them.
PanelData parallel_panel(const Params& p, const Ratio& r) {
    const double c = std::cos(p.theta);
    const bool reverses = p.zeta < std::abs(c); // v_x = zeta + c cos tau changes sign (Eq. 1)
    // Room beside the longest arrows for their labels, above and below the rows for their arrows.
    const double lo = std::min(-1.0, p.zeta - std::abs(c)), hi = std::max(1.0, p.zeta + std::abs(c));
    const double x0 = lo - 0.15 * (hi - lo) - 0.1, x1 = hi + 0.25 * (hi - lo), y0 = -0.5, y1 = 2 * kPi + 0.6;
    PanelData s;
    s.title = reverses ? "along v_{b}, instant by instant: v reverses, friction reverses with it"
                       : "along v_{b}, instant by instant: v never reverses, friction stays against v_{b}";
    s.x_title = "along v_{b}:  v/v_{v} above each instant, F/F_{c} below";
    s.y_title = titles::kTime;
    // The velocity over the period through the arrows' heads, v_x(tau) = zeta + c cos tau (Eq. 1). (The
    // friction's locus, -sgn v_x at theta = 0, is the arrows' heads at +-1.)
    SeriesData vl{"v_{x}(τ)/v_{v}, whole period", {}, {}, Ink::body, Dash::dashed, Mark::none, 1.5f};
    for (int k = 0; k <= 720; ++k) {
        const double tau = 2 * kPi * k / 720;
        vl.x.push_back(body_velocity(p, tau).x()), vl.y.push_back(tau + kMechanismRowGap);
    }
    s.series.push_back(std::move(vl));
    for (int k = 0; k <= 8; ++k) {
        const double tau = kPi * k / 4;
        const Vec2 v = body_velocity(p, tau), f = coulomb(v);
        s.arrows.push_back({Vec2(0, tau + kMechanismRowGap), Vec2(v.x(), tau + kMechanismRowGap), Ink::body,
                            kInstant[k], 2.f});
        s.arrows.push_back(
            {Vec2(0, tau - kMechanismRowGap), Vec2(f.x(), tau - kMechanismRowGap), Ink::tip, "", 2.f});
    }
    // Where v_x = 0 (cos tau = -zeta / c) the velocity reverses and the friction with it, at once: the rigid
    // model has no stick (its velocity is imposed), the friction jumps from -F_c to +F_c. Named in the
    // legend: a label on the line would lie on the rows' arrows.
    if (reverses) {
        const double turn = std::acos(-p.zeta / c);
        s.series.push_back({"v = 0: friction reverses",
                            {x0, x1, kNaN, x0, x1},
                            {turn, turn, kNaN, 2 * kPi - turn, 2 * kPi - turn},
                            Ink::spring,
                            Dash::dotted,
                            Mark::none,
                            1.2f});
    }
    // The mean friction along v_b, -r_x F_c (Eq. 9), across the rows: the friction arrows' average.
    s.series.push_back(
        {"mean friction −r_{x}F_{c}", {-r.rx, -r.rx}, {y0, y1}, Ink::black, Dash::dashed, Mark::none, 2.f});
    s.x_min = x0, s.x_max = x1;
    s.y_min = y0, s.y_max = y1;
    s.legend = Legend::above;
    return s;
}

} // namespace

Vec2 coulomb(const Vec2& v) {
    const double n = v.norm();
    return n > 0 ? Vec2(-v / n) : Vec2(Vec2::Zero());
}

void mechanism_panels(const MechanismFigure& spec, FigureData& fig) {
    const Params p{spec.zeta, spec.theta, 1, 1};  // r_disp, i: not used by the rigid model
    const Ratio r = rigid_ratio(p.zeta, p.theta); // Eq. (9) and its y-twin
    PanelData plane = mechanism_parallel(p.theta) ? parallel_panel(p, r) : plane_panel(p, r);

    PanelData time;
    time.title = "friction against v_{b} over one period";
    time.x_title = titles::kTime;
    time.y_title = "−F_{x}/F_{c}  (Eq. 3)";
    SeriesData fx{"−F_{x}/F_{c}", {}, {}, Ink::tip, Dash::solid, Mark::none, 2.5f};
    SeriesData phases{"", {}, {}, Ink::tip, Dash::solid, Mark::circle, 0};
    std::string table = "tau,v_x,v_y,F_x,F_y\n";
    double lowest = 0;
    for (int k = 0; k <= 1024; ++k) {
        const double tau = 2 * kPi * k / 1024;
        const Vec2 v = body_velocity(p, tau), f = coulomb(v);
        append(fx, tau, -f.x(), 0.5);
        lowest = std::min(lowest, -f.x());
        if (k % 128 == 0) phases.x.push_back(tau), phases.y.push_back(-f.x());
        if (k < 1024)
            table += format_number("%.10g", tau) + "," + format_number("%.12g", v.x()) + "," +
                     format_number("%.12g", v.y()) + "," + format_number("%.12g", f.x()) + "," +
                     format_number("%.12g", f.y()) + "\n";
    }
    time.series.push_back(std::move(fx));
    time.series.push_back({"mean r_{x} = " + format_number("%.4f", r.rx) + " (Eq. 9)",
                           {0, 2 * kPi},
                           {r.rx, r.rx},
                           Ink::black,
                           Dash::dashed,
                           Mark::none,
                           2.f});
    time.series.push_back(
        {"without vibration: F_{c}", {0, 2 * kPi}, {1, 1}, Ink::spring, Dash::dotted, Mark::none, 2.f});
    time.series.push_back(std::move(phases));
    time.x_min = 0, time.x_max = 2 * kPi;
    // A band below the curve for the legend (the curve fills the corners above it for most angles).
    time.y_min = std::min(0.0, lowest) - 0.5;
    time.y_max = 1.1;
    time.legend = Legend::bottom_right;

    fig.panels = {std::move(plane), std::move(time)};
    TableData t;
    t.text = std::move(table);
    fig.tables.push_back(std::move(t));
}

void dahl_curve_panels(const DahlCurvesFigure& spec, FigureData& fig) {
    PanelData load, cycle;
    load.title = "(a) loading from rest, v > 0";
    cycle.title = "(b) cycle 0 → +3 → −3 → +3 z_{ss}";
    for (PanelData* pd : {&load, &cycle}) {
        pd->x_title = "displacement x / z_{ss}";
        pd->y_title = "friction force F / F_{c}";
    }
    load.x_min = 0, load.x_max = kDahlCurveTurn, load.y_min = 0, load.y_max = 1.1;
    load.legend = Legend::bottom_right;
    cycle.x_min = -kDahlCurveTurn - 0.3, cycle.x_max = kDahlCurveTurn + 0.3;
    cycle.y_min = -1.15, cycle.y_max = 1.15;
    cycle.legend = Legend::none; // the colours of (a)
    std::string table = "i,leg,x_over_zss,F_over_Fc\n";
    // Every 100th step is drawn and written (0.01 z_ss apart), and each leg's end.
    constexpr int kEvery = 100;
    const long per_leg = std::lround(kDahlCurveTurn / kDahlCurveStep);
    for (double i : spec.exponents) {
        // z_ss = 1 (r_disp = 1): lengths in units of z_ss, and the lag P - T is F/F_c (Eqs. 13, 15).
        const Params p{0, 0, 1, i};
        const std::string is = format_number("%g", i);
        SeriesData a{
            "i = " + is + (i == 0 ? " (Eq. 25)" : (i == 1 ? " (Eq. 17)" : "")), {}, {}, Ink::automatic};
        SeriesData b{"", {}, {}, Ink::automatic};
        Vec2 lag = Vec2::Zero();
        double x = 0;
        auto keep = [&](int leg) {
            if (leg == 1) a.x.push_back(x), a.y.push_back(lag.x());
            b.x.push_back(x), b.y.push_back(lag.x());
            table += is + "," + std::to_string(leg) + "," + format_number("%.6g", x) + "," +
                     format_number("%.10g", lag.x()) + "\n";
        };
        keep(1);
        const double legs[] = {kDahlCurveTurn, -kDahlCurveTurn, kDahlCurveTurn};
        for (int leg = 1; leg <= 3; ++leg) {
            const double from = x, dir = legs[leg - 1] > from ? 1.0 : -1.0;
            const long n = leg == 1 ? per_leg : 2 * per_leg;
            for (long j = 1; j <= n; ++j) {
                // The model's step (Eqs. 17-27): the body moves by dx along x.
                lag = dahl_update(p, lag, Vec2(dir * kDahlCurveStep, 0));
                x = from + dir * kDahlCurveStep * static_cast<double>(j);
                if (j % kEvery == 0 || j == n) keep(leg);
            }
        }
        load.series.push_back(std::move(a));
        cycle.series.push_back(std::move(b));
    }
    // The sense of the cycle, beside the plateaus at -F_c (unloading and reversal, towards -x) and +F_c
    // (reloading, towards +x).
    cycle.arrows.push_back({Vec2(-0.4, -1.08), Vec2(-1.4, -1.08), Ink::black, "", 2.f});
    cycle.arrows.push_back({Vec2(0.4, 1.08), Vec2(1.4, 1.08), Ink::black, "", 2.f});
    fig.panels = {std::move(load), std::move(cycle)};
    TableData t;
    t.text = std::move(table);
    fig.tables.push_back(std::move(t));
}

} // namespace fv
