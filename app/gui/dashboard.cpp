#include "dashboard.hpp"
#include "fv/fit_figure.hpp"
#include "fv/format.hpp"

#include "figures/figure_painter.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fv::app {
namespace {

// Every k-th sample so that a history never costs more than ~max points to draw.
std::size_t stride_for(std::size_t n, std::size_t max) {
    return std::max<std::size_t>(1, (n + max - 1) / max);
}

SeriesData hline(const std::string& label, double x0, double x1, double y, Ink ink, Dash dash) {
    SeriesData s;
    s.label = label;
    s.x = {x0, x1};
    s.y = {y, y};
    s.ink = ink;
    s.dash = dash;
    s.width = 1.5f;
    return s;
}

} // namespace

DashboardLayout layout_dashboard(const gfx::Rect& a) {
    const float split = a.y0 + a.height() * 0.6f;
    const float mid = (a.x0 + a.x1) / 2;
    return {
        {a.x0, a.y0, a.x1, split - 4}, {a.x0, split + 4, mid - 4, a.y1}, {mid + 4, split + 4, a.x1, a.y1}};
}

PanelData top_view_panel(const LiveSim& sim, const ViewState& view) {
    const Params& p = sim.params();
    const bool rigid = sim.model() == Model::rigid;
    const bool slip = sim.slipping();
    PanelData panel;
    panel.equal_aspect = true;
    panel.legend = "top-right";
    panel.x_title = "x / x_{v}";
    panel.y_title = "y / x_{v}";
    panel.title = std::string("top view: ") +
                  (rigid ? "rigid body, friction opposes the velocity"
                         : (slip ? "tip T slips: z = z_{ss} (on the circle)"
                                 : (p.i == 0 ? "tip T sticks: z < z_{ss} (inside the circle)"
                                             : "tip T creeps: z < z_{ss} (inside the circle)")));

    // Fading trails: older fifths of the history drawn more transparent.
    const auto& h = sim.history();
    const std::size_t stride = stride_for(h.size(), 600);
    const double t_now = sim.tau(), span = view.trail_periods * 2 * kPi;
    constexpr int kChunks = 5;
    for (int who = 0; who < (rigid ? 1 : 2); ++who) {
        for (int c = 0; c < kChunks; ++c) {
            SeriesData s;
            s.ink = who == 0 ? Ink::body : Ink::tip;
            s.width = 2.2f;
            s.opacity = 0.2f + 0.8f * static_cast<float>(c + 1) / kChunks;
            if (c == kChunks - 1) s.label = who == 0 ? "body point P" : "asperity tip T";
            const double lo = t_now - span * (kChunks - c) / kChunks,
                         hi = t_now - span * (kChunks - c - 1) / kChunks;
            const double overlap = static_cast<double>(stride) * sim.dtau();
            for (std::size_t k = 0; k < h.size(); k += stride) {
                // Include the sample just past each chunk's end so that the chunks join.
                if (h[k].tau < lo - overlap || h[k].tau > hi + overlap) continue;
                const Vec2& q = who == 0 ? h[k].P : h[k].T;
                s.x.push_back(q.x());
                s.y.push_back(q.y());
            }
            if (c == kChunks - 1) {
                const Vec2 q = who == 0 ? sim.P() : sim.T();
                s.x.push_back(q.x());
                s.y.push_back(q.y());
            }
            if (!s.x.empty()) panel.series.push_back(std::move(s));
        }
    }
    const Vec2 P = sim.P(), T = sim.T();
    if (!rigid) {
        panel.circles.push_back(
            {P, p.zss(), slip ? Ink::tip : Ink::pull, slip ? Dash::solid : Dash::dashed, 1.6f});
        panel.segments.push_back({P, T, Ink::spring, Dash::solid, 3.0f, "z", 0.5f, 0});
    }
    // Arrows: P's velocity (scaled by 0.4) and the friction force on the body (opposite to F/F_c as the
    // ratio counts it), F_c drawn as 0.5 x_v.
    const Vec2 v = sim.velocity(), F = sim.force();
    panel.arrows.push_back({P, P + 0.4 * v, Ink::body, "v", 2.5f});
    panel.arrows.push_back({P, P - 0.5 * F, Ink::black, "friction", 2.5f});
    panel.points.push_back({P, Ink::body, Mark::circle, "P", 11});
    if (!rigid) panel.points.push_back({T, slip ? Ink::tip : Ink::pull, Mark::square, "T", 11});

    // Camera: centred on P's drift (or where the user panned to), tall enough for the vibration and z_ss.
    const double half_h = (1 + (rigid ? 0.5 : p.zss())) * 1.2 * view.zoom;
    const double cx = (view.follow ? P.x() : 0) + view.pan.x(), cy = view.pan.y();
    panel.y_min = cy - half_h;
    panel.y_max = cy + half_h;
    panel.x_min = cx - 1.6 * half_h;
    panel.x_max = cx + 1.6 * half_h;
    return panel;
}

PanelData force_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves) {
    PanelData panel;
    panel.title = "friction force, last periods";
    panel.x_title = "time τ = ωt";
    panel.y_title = "F / F_{c}";
    panel.legend = "best";
    const auto& h = sim.history();
    const double t1 = std::max(sim.tau(), 0.5), t0 = std::max(0.0, t1 - 2 * kPi * 2.0);
    panel.x_min = t0;
    panel.x_max = t1;
    panel.y_min = -1.15;
    panel.y_max = 1.15;
    SeriesData fm{"|F|", {}, {}, Ink::magnitude, Dash::solid, Mark::none, 2.2f};
    SeriesData fx{"F_{x}", {}, {}, Ink::force, Dash::solid, Mark::none, 2};
    SeriesData fy{"F_{y}", {}, {}, Ink::pull, Dash::dashed, Mark::none, 2};
    const std::size_t stride = stride_for(h.size(), 400);
    for (std::size_t k = 0; k < h.size(); k += stride) {
        if (h[k].tau < t0) continue;
        fm.x.push_back(h[k].tau), fm.y.push_back(h[k].F.norm());
        fx.x.push_back(h[k].tau), fx.y.push_back(h[k].F.x());
        fy.x.push_back(h[k].tau), fy.y.push_back(h[k].F.y());
    }
    panel.series = {std::move(fm), std::move(fx), std::move(fy)};
    const Vec2 mean = sim.last_period_mean();
    if (std::isfinite(mean.x()))
        panel.series.push_back(hline("period mean of F_{x} = " + format_number("%.4f", mean.x()), t0, t1,
                                     mean.x(), Ink::black, Dash::dashed));
    if (curves && curves->request.params.zeta == sim.params().zeta)
        panel.series.push_back(hline("steady r_{x} = " + format_number("%.4f", curves->current.rx) +
                                         (ok(shown_status(curves->current)) ? "" : " (NOT VERIFIED)"),
                                     t0, t1, curves->current.rx, Ink::rigid, Dash::dotted));
    return panel;
}

double ratio_zeta_max(const MeasurementSet* data) {
    double zmax = 3;
    if (data)
        for (const Measurement& m : data->points) zmax = std::max(zmax, 1.05 * m.zeta);
    return std::min(zmax, kMaxZeta);
}

PanelData ratio_panel_live(const std::optional<RatioCurves>& curves, bool busy, const RatioOverlay& overlay) {
    PanelData panel;
    panel.x_title = "velocity ratio ζ = v_{b}/v_{v}";
    if (overlay.vv_m_s > 0) panel.x_title += "  (v_{v} = " + format_number("%.3g", overlay.vv_m_s) + " m/s)";
    panel.y_title = "friction ratio r_{x}";
    panel.legend = "bottom-right";
    panel.x_min = 0;
    panel.x_max = ratio_zeta_max(overlay.data);
    panel.y_min = 0;
    panel.y_max = 1.05;
    // Measured points above the curves: they are what the curves are held against.
    auto add_data = [&](std::optional<double> theta_deg) {
        if (!overlay.data) return;
        for (SeriesData& s : measured_series(*overlay.data, theta_deg)) {
            // Points outside [0, 1.05] would be clipped silently: widen the axis to show them.
            for (std::size_t k = 0; k < s.y.size(); ++k) {
                const double e = k < s.y_err.size() ? s.y_err[k] : 0;
                panel.y_min = std::min(*panel.y_min, s.y[k] - e - 0.03);
                panel.y_max = std::max(*panel.y_max, s.y[k] + e + 0.03);
            }
            panel.series.push_back(std::move(s));
        }
    };
    if (!curves) {
        panel.title = "r_{x}(ζ): computing…";
        add_data(std::nullopt);
        return panel;
    }
    const Params& p = curves->request.params;
    const SteadyStatus st = shown_status(curves->current);
    panel.title = std::string(busy ? "updating…  " : "") +
                  "r_{x} = " + format_number("%.4f", curves->current.rx) +
                  ",  r_{y} = " + format_number("%.4f", curves->current.ry) +
                  (ok(st) ? "" : std::string("  NOT VERIFIED: ") + to_string(st));
    if (!curves->model_rx.empty())
        panel.series.push_back(
            {"Dahl, i = " + format_number("%g", p.i) + ", r_{disp} = " + format_number("%.3g", p.rdisp) +
                 (curves->model_failed > 0
                      ? " (" + std::to_string(curves->model_failed) + " failed points not drawn)"
                      : ""),
             curves->zetas, curves->model_rx, Ink::body, Dash::solid, Mark::none, 2.2f});
    panel.series.push_back(
        {"rigid", curves->zetas, curves->rigid_rx, Ink::rigid, Dash::dashed, Mark::none, 1.8f});
    add_data(p.theta * 180 / kPi);
    // The current point: a cross instead of the diamond when the solver does not vouch for it.
    panel.points.push_back(
        {Vec2(p.zeta, curves->current.rx), Ink::tip, ok(st) ? Mark::diamond : Mark::cross, "", 12});
    return panel;
}

PanelData map_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy) {
    if (!curves || !curves->map) {
        PanelData p;
        p.title = sim.model() == Model::rigid ? "(ζ, θ) map: Dahl model only" : "(ζ, θ) map: computing…";
        p.x_title = "velocity ratio ζ = v_{b}/v_{v}";
        p.y_title = "vibration angle θ [°]";
        p.x_min = 0, p.x_max = 3, p.y_min = 0, p.y_max = 90;
        return p;
    }
    PanelData p = *curves->map;
    const Params& q = curves->request.params;
    p.title = std::string(busy ? "updating…  " : "") +
              "r_{x}(ζ, θ), r_{disp} = " + format_number("%.3g", q.rdisp) +
              ", i = " + format_number("%g", q.i);
    p.legend = "none";
    const double theta_deg = std::min(90.0, std::abs(90 - std::abs(q.theta * 180 / kPi - 90)));
    p.points.push_back({Vec2(std::min(q.zeta, 3.0), theta_deg), Ink::tip, Mark::diamond, "", 12});
    return p;
}

DashboardTransforms paint_dashboard(gfx::Canvas& canvas, const gfx::Rect& area, const LiveSim& sim,
                                    const ViewState& view, const std::optional<RatioCurves>& curves,
                                    bool busy, bool show_map, const RatioOverlay& overlay) {
    const DashboardLayout l = layout_dashboard(area);
    DashboardTransforms t;
    t.top_view = paint_panel(canvas, top_view_panel(sim, view), l.top_view);
    t.force = paint_panel(canvas, force_panel_live(sim, curves), l.force);
    t.ratio = paint_panel(
        canvas, show_map ? map_panel_live(sim, curves, busy) : ratio_panel_live(curves, busy, overlay),
        l.ratio);
    return t;
}

} // namespace fv::app
