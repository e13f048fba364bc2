#include "fv/live_panels.hpp"

#include "figure_panels.hpp"
#include "scene_parts.hpp"

#include "fv/axis_titles.hpp"
#include "fv/fit_figure.hpp"
#include "fv/format.hpp"
#include "fv/paper_scheme.hpp"
#include "fv/setup_picture.hpp"

#include <algorithm>
#include <cmath>

namespace fv {
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

// The asperity as a spring from T to P: a zigzag of `coils` turns, `amp` wide, straight ends.
SeriesData spring_series(const Vec2& T, const Vec2& P, double amp, Ink ink) {
    SeriesData s;
    s.ink = ink;
    s.width = 2.4f;
    const Vec2 d = P - T;
    const double len = d.norm();
    if (!(len > 0)) return s;
    const Vec2 u = d / len, n{-u.y(), u.x()};
    constexpr int kCoils = 6;
    const double a = std::min(amp, 0.5 * len);
    s.x.push_back(T.x()), s.y.push_back(T.y());
    for (int k = 0; k <= 2 * kCoils; ++k) {
        const double f = 0.15 + 0.7 * k / (2.0 * kCoils);
        const double side = k == 0 || k == 2 * kCoils ? 0 : (k % 2 ? 1 : -1);
        const Vec2 q = T + f * d + side * a * n;
        s.x.push_back(q.x()), s.y.push_back(q.y());
    }
    s.x.push_back(P.x()), s.y.push_back(P.y());
    return s;
}

// An outline through the corners (closed), for the body.
SeriesData box_series(const Vec2& c, double hw, double hh, const std::string& label) {
    SeriesData s;
    s.label = label;
    s.ink = Ink::spring;
    s.dash = Dash::dashed;
    s.width = 1.4f;
    s.x = {c.x() - hw, c.x() + hw, c.x() + hw, c.x() - hw, c.x() - hw};
    s.y = {c.y() - hh, c.y() - hh, c.y() + hh, c.y() + hh, c.y() - hh};
    s.labels_off = true; // a label across the dashed outline read as struck through
    return s;
}

// A legend entry with no data.
SeriesData key(const std::string& label, Ink ink, float width, float opacity = 1, Dash dash = Dash::solid) {
    SeriesData s;
    s.label = label;
    s.ink = ink;
    s.width = width;
    s.opacity = opacity;
    s.dash = dash;
    return s;
}

// Where the v and friction arrows start, relative to P: where one of them lies near the other's line or the
// spring T-P (within 60 degrees; the friction on the body always does: it pulls P towards T), it is moved
// `gap` off that line, the two to opposite sides, v to the side it points to, so that they part and none
// hides another or the spring.
struct ArrowOffsets {
    Vec2 v{0, 0}, f{0, 0};
};
ArrowOffsets arrow_offsets(const Vec2& v, const Vec2& f, const Vec2& spring, double gap) {
    auto along = [](const Vec2& a, const Vec2& b) {
        const double na = a.norm(), nb = b.norm();
        return na > 0 && nb > 0 && std::abs(a.x() * b.y() - a.y() * b.x()) < std::sin(kPi / 3) * na * nb;
    };
    ArrowOffsets o;
    const Vec2 base = f.norm() > 0 ? f : v;
    if (!(base.norm() > 0)) return o;
    // One normal for both: to the side v points to (up on screen where v runs along the friction's line).
    Vec2 n = Vec2(-base.y(), base.x()) / base.norm();
    const double side = v.dot(n);
    if (side < 0 || (std::abs(side) <= 1e-9 * v.norm() && (n.y() < 0 || (n.y() == 0 && n.x() < 0)))) n = -n;
    if (along(v, f) || along(v, spring)) o.v = gap * n;
    if (along(f, v) || along(f, spring)) o.f = -gap * n;
    return o;
}

// The axis ranges from the frame `box` (relative to the vibration centre C). body: the camera on C (or on
// the origin when the user has panned away from following), the floor sliding past. ground: the window
// stands still on the floor, C's place in it taken modulo its width, and the picture drawn again one width
// to the left and right without labels, so that the body leaving at one edge comes in at the other.
void place_frame(PanelData& panel, const FrameBox& box, const Vec2& C, const ViewState& view) {
    if (view.frame == FrameChoice::body) {
        const Vec2 origin = (view.follow ? C : Vec2(0, 0)) + view.pan;
        panel.x_min = origin.x() + box.x0, panel.x_max = origin.x() + box.x1;
        panel.y_min = origin.y() + box.y0, panel.y_max = origin.y() + box.y1;
        return;
    }
    panel.x_title = "x / x_{v} on the floor (it stands still; the body wraps round at the edges)";
    panel.x_title_short = "x / x_{v} on the floor (the body wraps round)";
    const double w = box.width(), left = box.x0 + view.pan.x();
    panel.x_min = left, panel.x_max = left + w;
    panel.y_min = C.y() + box.y0 + view.pan.y(), panel.y_max = C.y() + box.y1 + view.pan.y();
    if (!(w > 0)) return;
    shift_panel_x(panel, -w * std::floor((C.x() - left) / w));
    panel.x_min = left, panel.x_max = left + w; // shifted with the rest: set again
    PanelData copy;
    for (const SeriesData& s : panel.series)
        if (!s.x.empty()) copy.series.push_back(s), copy.series.back().label.clear();
    copy.segments = panel.segments, copy.circles = panel.circles, copy.arrows = panel.arrows;
    copy.points = panel.points;
    for (SegmentData& s : copy.segments) s.label.clear();
    for (ArrowData& a : copy.arrows) a.label.clear();
    for (PointData& q : copy.points) q.label.clear();
    // A label goes with the copy whose arrow head or point is well inside the window (at most one is); none
    // while the body crosses the edge, where a label would be drawn beyond the axes.
    const double margin = 0.06 * w;
    auto inside_at = [&](double x, double dx) {
        return x + dx >= left + margin && x + dx <= left + w - margin;
    };
    std::vector<PanelData> copies;
    for (const double dx : {-w, w}) {
        PanelData c = copy;
        for (std::size_t k = 0; k < c.arrows.size(); ++k)
            if (inside_at(panel.arrows[k].to.x(), dx)) c.arrows[k].label = panel.arrows[k].label;
        for (std::size_t k = 0; k < c.points.size(); ++k)
            if (inside_at(panel.points[k].at.x(), dx)) c.points[k].label = panel.points[k].label;
        copies.push_back(std::move(c));
    }
    for (ArrowData& a : panel.arrows)
        if (!inside_at(a.to.x(), 0)) a.label.clear();
    for (PointData& q : panel.points)
        if (!inside_at(q.at.x(), 0)) q.label.clear();
    for (std::size_t k = 0; k < copies.size(); ++k) {
        PanelData& c = copies[k];
        const double dx = k == 0 ? -w : w;
        shift_panel_x(c, dx);
        panel.series.insert(panel.series.end(), c.series.begin(), c.series.end());
        panel.segments.insert(panel.segments.end(), c.segments.begin(), c.segments.end());
        panel.circles.insert(panel.circles.end(), c.circles.begin(), c.circles.end());
        panel.arrows.insert(panel.arrows.end(), c.arrows.begin(), c.arrows.end());
        panel.points.insert(panel.points.end(), c.points.begin(), c.points.end());
    }
}

} // namespace

void shift_panel_x(PanelData& p, double dx) {
    const Vec2 d(dx, 0);
    for (SeriesData& s : p.series)
        for (double& x : s.x) x += dx;
    for (SegmentData& s : p.segments) s.a += d, s.b += d;
    for (PointData& q : p.points) q.at += d;
    for (CircleData& c : p.circles) c.center += d;
    for (ArrowData& a : p.arrows) a.from += d, a.to += d;
    for (BandData& b : p.bands) b.x0 += dx, b.x1 += dx;
    if (p.heatmap) p.heatmap->x0 += dx, p.heatmap->x1 += dx;
    if (p.x_min) *p.x_min += dx;
    if (p.x_max) *p.x_max += dx;
}

SimMoment moment_at(const LiveSim& sim, double rewind) {
    SimMoment m;
    const Params& p = sim.params();
    const auto& h = sim.history();
    if (rewind > 0 && !h.empty()) {
        const double t = std::max(sim.tau() - rewind, h.front().tau);
        auto it =
            std::upper_bound(h.begin(), h.end(), t, [](double v, const LiveSample& s) { return v < s.tau; });
        const LiveSample& s = it == h.begin() ? *it : *std::prev(it);
        m.tau = s.tau, m.P = s.P, m.T = s.T, m.F = s.F, m.slip = s.slip;
        m.velocity = body_velocity(p, s.tau);
        m.centre = s.P - std::sin(s.tau) * Vec2(std::cos(p.theta), std::sin(p.theta));
        m.z = (s.P - s.T).norm();
        return m;
    }
    m.tau = sim.tau(), m.P = sim.P(), m.T = sim.T(), m.F = sim.force(), m.slip = sim.slipping();
    m.velocity = sim.velocity(), m.centre = sim.vibration_centre(), m.z = sim.z();
    return m;
}

double max_rewind(const LiveSim& sim) {
    return sim.history().empty() ? 0 : sim.tau() - sim.history().front().tau;
}

PanelData top_view_panel(const LiveSim& sim, const ViewState& view, const char* setup) {
    const Params& p = sim.params();
    const bool rigid = sim.model() == Model::rigid;
    const SimMoment m = moment_at(sim, view.rewind);
    const bool slip = m.slip;
    PanelData panel = scene::top_view_axes();
    // The trail moves: a legend inside would cover it sooner or later. Compare mode: none, so that the two
    // views get the same room (a legend beside one only would halve it; the help overlay names every symbol).
    panel.legend = setup ? Legend::none : Legend::outside;
    const std::string head =
        setup ? std::string(setup) + ": θ = " + format_number("%.0f°", p.theta * 180 / kPi) + ", "
              : "top view: ";
    panel.title = head + (rigid ? "rigid body, friction opposes the velocity"
                                : (slip ? "tip T slips: z = z_{ss} (on the circle)"
                                        : (p.i == 0 ? "tip T sticks: z < z_{ss} (inside the circle)"
                                                    : "tip T creeps: z < z_{ss} (inside the circle)")));

    // Fading trails: older fifths of the history drawn more transparent.
    const auto& h = sim.history();
    const std::size_t stride = stride_for(h.size(), 600);
    const double t_now = m.tau, span = view.trail_periods * 2 * kPi;
    constexpr int kChunks = 5;
    for (int who = 0; who < (rigid ? 1 : 2); ++who) {
        for (int c = 0; c < kChunks; ++c) {
            SeriesData s = who == 0 ? scene::body_path(2.2f) : scene::tip_path(2.2f);
            s.opacity = 0.2f + 0.8f * static_cast<float>(c + 1) / kChunks;
            if (c != kChunks - 1) s.label.clear(); // the newest part names the path
            const double lo = t_now - span * (kChunks - c) / kChunks,
                         hi = t_now - span * (kChunks - c - 1) / kChunks;
            const double overlap = static_cast<double>(stride) * sim.dtau();
            for (std::size_t k = 0; k < h.size(); k += stride) {
                // Include the sample just past each chunk's end so that the chunks join.
                if (h[k].tau < lo - overlap || h[k].tau > std::min(hi + overlap, t_now)) continue;
                const Vec2& q = who == 0 ? h[k].P : h[k].T;
                s.x.push_back(q.x());
                s.y.push_back(q.y());
            }
            if (c == kChunks - 1) {
                const Vec2 q = who == 0 ? m.P : m.T;
                s.x.push_back(q.x());
                s.y.push_back(q.y());
            }
            if (!s.x.empty()) panel.series.push_back(std::move(s));
        }
    }
    const Vec2 P = m.P, T = m.T;
    // The frame: fixed for the parameters (top_view_frame.hpp; the app eases it between parameter sets),
    // scaled about its centre by the zoom. It does not follow the trajectory's extent, so nothing in the
    // picture grows or shrinks with the phase.
    FrameBox box = view.box ? *view.box : steady_frame(sim.model(), p, view.trail_periods, view.aspect);
    {
        const double mx = 0.5 * (box.x0 + box.x1), my = 0.5 * (box.y0 + box.y1);
        const double hw = 0.5 * box.width() * view.zoom, hh = 0.5 * box.height() * view.zoom;
        box = {mx - hw, mx + hw, my - hh, my + hh};
    }
    // What moves, drawn behind the trails' heads: the body around P (it carries P and
    // drifts at v_b), the line P vibrates on (+-x_v at theta through where P would be without vibrating),
    // the asperity as a spring from its tip T (held by the fixed plane while it sticks) to P, green while it
    // sticks or creeps inside the circle z < z_ss, reddish purple while it slips on it.
    const BodyOutline outline = body_outline(sim.model(), p);
    const double bw = outline.half_w, bh = outline.half_h;
    panel.series.insert(panel.series.begin(), box_series(P, bw, bh, "body (carries P, drifts at v_{b})"));
    const Vec2 C = m.centre, dir{std::cos(p.theta), std::sin(p.theta)};
    // The line is named in the legend: a label beside it met T, the arrows or v_b at one angle or another.
    panel.segments.push_back({C - dir, C + dir, Ink::body, Dash::dotted, 1.3f, "", 0.5f, 0});
    panel.series.push_back(key("P's vibration: ±x_{v} at θ = " + format_number("%.0f°", p.theta * 180 / kPi),
                               Ink::body, 1.3f, 1, Dash::dotted));
    panel.arrows.push_back({P + Vec2(-bw, bh), P + Vec2(-bw + 0.4 * p.zeta, bh), Ink::body, "v_{b}", 2.0f});
    if (!rigid) {
        const Ink state = slip ? Ink::slip : Ink::pull;
        panel.circles.push_back({P, p.zss(), state, slip ? Dash::solid : Dash::dashed, 1.6f});
        panel.series.push_back(spring_series(T, P, 0.02 * box.height(), state));
        panel.series.push_back(
            key(p.i == 0 ? "asperity sticks (z < z_{ss})" : "asperity creeps (z < z_{ss})", Ink::pull, 2.4f));
        panel.series.push_back(key("asperity slips (z = z_{ss})", Ink::slip, 2.4f));
    }
    // Arrows: P's velocity (scaled by 0.4) and the friction force on the body, -F: the force plot's F is
    // (P - T)/z_ss in units of F_c, positive along v_b (the ratio's convention); F_c drawn as 0.5 x_v. The
    // friction's label is "−F", short (the legend says "friction on the body = −F"): "friction" found no
    // free place beside its arrow at some instants, crowded by T, P and v.
    const Vec2 v = 0.4 * m.velocity, f = -0.5 * m.F;
    const ArrowOffsets off = arrow_offsets(v, f, rigid ? Vec2::Zero() : Vec2(P - T), 0.02 * box.height());
    panel.arrows.push_back({P + off.v, P + off.v + v, Ink::body, "v", 2.5f});
    panel.arrows.push_back({P + off.f, P + off.f + f, Ink::black, "−F", 2.5f});
    panel.series.push_back(key("friction on the body = −F", Ink::black, 2.5f));
    // P's and T's labels on their far sides from each other (off the spring between them; P above and T
    // below where they nearly coincide): they never meet, however close P and T are.
    const Vec2 d = P - T;
    const int up = d.y() > 1e-9 * (1 + d.norm()) || std::abs(d.y()) <= 1e-9 * (1 + d.norm()) ? -1 : 1;
    const int right = d.x() >= 0 ? 1 : -1;
    panel.points.push_back(scene::body_mark(P, 11));
    panel.points.back().label_dx = rigid ? 0 : right, panel.points.back().label_dy = rigid ? 0 : up;
    if (!rigid) {
        panel.points.push_back(scene::tip_mark(T, slip ? Ink::slip : Ink::pull, 11));
        panel.points.back().label_dx = -right, panel.points.back().label_dy = -up;
    }
    place_frame(panel, box, C, view);
    return panel;
}

namespace {

// The period mean of F_x before each instant in [t0, t1] (the history's running sums): once the transient is
// over it settles on the steady r_x, which is how the period mean of Eq. (30) becomes the ratio.
SeriesData period_mean_series(const LiveSim& sim, double t0, double t1, std::size_t stride, std::string label,
                              Ink ink) {
    SeriesData run{std::move(label), {}, {}, ink, Dash::dashed, Mark::none, 1.6f};
    const auto& h = sim.history();
    const std::size_t n = static_cast<std::size_t>(sim.steps_per_period());
    for (std::size_t k = n; k < h.size(); k += stride) {
        if (h[k].tau < t0) continue;
        if (h[k].tau > t1) break;
        run.x.push_back(h[k].tau), run.y.push_back((h[k].fx_sum - h[k - n].fx_sum) / static_cast<double>(n));
    }
    return run;
}

// The steady r_x of `curves` across [t0, t1] when they are the simulation's (their value is in the panel
// and the ratio plot's title: the legend's rows above the axes stay short).
void add_steady_line(PanelData& panel, const LiveSim& sim, const RatioCurves* curves, double t0, double t1,
                     Ink ink) {
    if (!curves || curves->request.params.zeta != sim.params().zeta) return;
    // Unlabelled in a setup's colour (compare mode names the kind of line once, in black), unless unverified.
    const bool verified = ok(shown_status(curves->current));
    const std::string label = ink == Ink::rigid
                                  ? std::string("steady r_{x}") + (verified ? "" : " (NOT VERIFIED)")
                              : verified ? ""
                                         : "steady r_{x} NOT VERIFIED";
    panel.series.push_back(hline(label, t0, t1, curves->current.rx, ink, Dash::dotted));
}

// One setup's F_x over [t0, t1], for compare mode.
SeriesData fx_series(const LiveSim& sim, double t0, double t1, std::size_t stride, std::string label,
                     Ink ink) {
    SeriesData s{std::move(label), {}, {}, ink, Dash::solid, Mark::none, 2};
    const auto& h = sim.history();
    for (std::size_t k = 0; k < h.size(); k += stride) {
        if (h[k].tau < t0) continue;
        if (h[k].tau > t1) break;
        s.x.push_back(h[k].tau), s.y.push_back(h[k].F.x());
    }
    return s;
}

} // namespace

PanelData force_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, double rewind,
                           const CompareOverlay& b) {
    PanelData panel = scene::force_axes(titles::kTime);
    panel.title = "friction force (F_{x} > 0 resists v_{b}), last periods";
    // The curves scroll through every part of the axes: a legend inside would cover them sooner or later.
    panel.legend = Legend::above;
    const auto& h = sim.history();
    const double t1 = std::max(moment_at(sim, rewind).tau, 0.5), t0 = std::max(0.0, t1 - 2 * kPi * 2.0);
    panel.x_min = t0;
    panel.x_max = t1;
    const std::size_t stride = stride_for(h.size(), 400);
    if (b.sim) {
        // Compare mode: the two setups on one time base, A in blue and B in orange.
        const std::size_t stride_b = stride_for(b.sim->history().size(), 400);
        panel.title = "friction force along v_{b}: A and B, last periods";
        // Four legend entries, not six: the setups by colour, the kinds of line by dash.
        panel.series.push_back(fx_series(sim, t0, t1, stride, "A: F_{x}", Ink::body));
        panel.series.push_back(fx_series(*b.sim, t0, t1, stride_b, "B: F_{x}", Ink::setup_b));
        panel.series.push_back(period_mean_series(sim, t0, t1, stride, "", Ink::body));
        panel.series.push_back(period_mean_series(*b.sim, t0, t1, stride_b, "", Ink::setup_b));
        add_steady_line(panel, sim, curves ? &*curves : nullptr, t0, t1, Ink::body);
        add_steady_line(panel, *b.sim, b.curves, t0, t1, Ink::setup_b);
        panel.series.push_back(key("period mean", Ink::black, 1.6f, 1, Dash::dashed));
        panel.series.push_back(key("steady r_{x}", Ink::black, 1.5f, 1, Dash::dotted));
        return panel;
    }
    scene::ForceCurves f;
    for (std::size_t k = 0; k < h.size(); k += stride) {
        if (h[k].tau < t0) continue;
        if (h[k].tau > t1) break;
        f.add(h[k].tau, h[k].F);
    }
    panel.series = f.take();
    // The times the tip slips, shaded (consecutive samples joined into intervals).
    if (sim.model() == Model::dahl) {
        for (std::size_t k = 0; k < h.size(); ++k) {
            if (h[k].tau > t1) break;
            if (!h[k].slip || h[k].tau < t0) continue;
            const double a = k > 0 ? h[k - 1].tau : h[k].tau;
            if (!panel.bands.empty() && panel.bands.back().x1 >= a) {
                panel.bands.back().x1 = h[k].tau;
            } else {
                panel.bands.push_back({std::max(a, t0), h[k].tau, Ink::slip, 0.13f});
            }
        }
        panel.series.push_back(key("T slips", Ink::slip, 9, 0.25f));
    }
    SeriesData run = period_mean_series(sim, t0, t1, stride, "period mean F_{x}", Ink::black);
    if (!run.x.empty()) panel.series.push_back(std::move(run));
    add_steady_line(panel, sim, curves ? &*curves : nullptr, t0, t1, Ink::rigid);
    return panel;
}

double ratio_zeta_max(const MeasurementSet* data) {
    double zmax = 3;
    if (data)
        for (const Measurement& m : data->points) zmax = std::max(zmax, 1.05 * m.zeta);
    return std::min(zmax, kMaxZeta);
}

namespace {

// A curve's legend entry: the model and what it was computed at. Compare mode (`other`: the other setup's
// curves, or null while they compute) names the setup (`prefix`) and its angle, the two setups' usual
// difference, and r_disp and i only where they differ from the other's: the legend stays short enough to
// leave the r_x points free on a small plot.
std::string curve_label(const RatioCurves& c, const std::string& prefix = "",
                        const RatioCurves* other = nullptr) {
    const Params& p = c.request.params;
    const bool rigid = c.model_rx.empty();
    const std::string failed =
        c.model_failed > 0 ? " (" + std::to_string(c.model_failed) + " failed points not drawn)" : "";
    if (prefix.empty())
        return "Dahl, i = " + format_number("%g", p.i) + ", r_{disp} = " + format_number("%.3g", p.rdisp) +
               failed;
    std::string s =
        prefix + (rigid ? "rigid" : "Dahl") + ", θ = " + format_number("%.0f°", p.theta * 180 / kPi);
    if (rigid) return s;
    const Params* q = other && !other->model_rx.empty() ? &other->request.params : nullptr;
    if (!q || q->i != p.i) s += ", i = " + format_number("%g", p.i);
    if (!q || q->rdisp != p.rdisp) s += ", r_{disp} = " + format_number("%.3g", p.rdisp);
    return s + failed;
}

// Compare mode's setup B on the ratio plot: its curve (the Dahl model's, or the rigid one for the rigid
// model) and its steady r_x point in orange, and its r_x in the title beside A's.
void add_compare_curve(PanelData& panel, const CompareOverlay& b, const RatioCurves& a) {
    if (!b.curves) {
        panel.title += "   B: computing…";
        return;
    }
    const RatioCurves& c = *b.curves;
    const SteadyStatus st = shown_status(c.current);
    panel.title += std::string("   B: ") + (b.busy ? "updating…  " : "") +
                   "r_{x} = " + format_number("%.4f", c.current.rx) +
                   (c.request.start == Start::sliding ? "  from sliding" : "") +
                   (ok(st) ? "" : std::string("  NOT VERIFIED: ") + to_string(st));
    const bool rigid = c.model_rx.empty();
    panel.series.push_back({curve_label(c, "B: ", &a), c.zetas, rigid ? c.rigid_rx : c.model_rx, Ink::setup_b,
                            rigid ? Dash::dashed : Dash::solid, Mark::none, 2.2f});
    panel.points.push_back({Vec2(c.request.params.zeta, c.current.rx), Ink::setup_b,
                            ok(st) ? Mark::diamond : Mark::cross, "B", 12});
}

} // namespace

PanelData ratio_panel_live(const std::optional<RatioCurves>& curves, bool busy, const RatioOverlay& overlay) {
    PanelData panel = scene::ratio_axes(ratio_zeta_max(overlay.data));
    if (overlay.vv_m_s > 0) panel.x_title += "  (v_{v} = " + format_number("%.3g", overlay.vv_m_s) + " m/s)";
    panel.legend = Legend::best;
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
    const bool compare = overlay.b.sim != nullptr;
    panel.title = std::string(busy ? "updating…  " : "") + (compare ? "A: " : "") +
                  "r_{x} = " + format_number("%.4f", curves->current.rx) +
                  (compare ? "" : ",  r_{y} = " + format_number("%.4f", curves->current.ry)) +
                  (curves->request.start == Start::sliding ? "  from sliding" : "") +
                  (ok(st) ? "" : std::string("  NOT VERIFIED: ") + to_string(st));
    if (!curves->model_rx.empty())
        panel.series.push_back({curve_label(*curves, compare ? "A: " : "", overlay.b.curves), curves->zetas,
                                curves->model_rx, Ink::body, Dash::solid, Mark::none, 2.2f});
    panel.series.push_back(scene::rigid_curve(curves->zetas, curves->rigid_rx));
    if (compare) {
        // The rigid curve at A's angle: A's own curve (blue) for the rigid model, else its reference.
        SeriesData& rigid = panel.series.back();
        rigid.label = curves->model_rx.empty() ? curve_label(*curves, "A: ") : rigid.label + " at A's θ";
        if (curves->model_rx.empty()) rigid.ink = Ink::body;
    }
    // Pinned curves in the palette's further colours (the series index picks them), dash-dotted apart.
    if (overlay.pins)
        for (const PinnedCurve& pin : *overlay.pins)
            panel.series.push_back(
                {"pinned: " + pin.label, pin.zeta, pin.rx, Ink::automatic, Dash::dotted, Mark::none, 2.0f});
    add_data(p.theta * 180 / kPi);
    // The current point: a cross instead of the diamond when the solver does not vouch for it.
    panel.points.push_back({Vec2(p.zeta, curves->current.rx), compare ? Ink::body : Ink::tip,
                            ok(st) ? Mark::diamond : Mark::cross, compare ? "A" : "", 12});
    // Where another stable state coexists: a circle at its r_x, each point named by the start reaching it,
    // the label towards the other states (off the flat parts of the curve at r_x = 0 and 1).
    const std::vector<SteadyState>& states = coexisting_states(*curves);
    if (!states.empty()) {
        const double mid = 0.5 * (states.front().rx + states.back().rx); // ordered by r_x
        const std::size_t current = panel.points.size() - 1;             // the diamond
        for (const SteadyState& s : states) {
            const bool reported = std::abs(s.rx - curves->current.rx) <= 1e-6;
            if (!reported) panel.points.push_back({Vec2(p.zeta, s.rx), Ink::tip, Mark::circle, "", 11});
            PointData& point = reported ? panel.points[current] : panel.points.back();
            point.label = (compare ? std::string("A ") : std::string()) + reached_from(s);
            point.label_dx = 1;
            point.label_dy = s.rx > mid ? 1 : -1;
        }
    }
    if (compare) add_compare_curve(panel, overlay.b, *curves);
    return panel;
}

PanelData map_panel_live(const LiveSim& sim, const std::optional<RatioCurves>& curves, bool busy) {
    if (!curves || !curves->map) {
        PanelData p;
        p.title = sim.model() == Model::rigid ? "(ζ, θ) map: Dahl model only" : "(ζ, θ) map: computing…";
        p.x_title = titles::kZeta;
        p.y_title = titles::kTheta;
        p.x_min = 0, p.x_max = 3, p.y_min = 0, p.y_max = 90;
        return p;
    }
    PanelData p = *curves->map;
    const Params& q = curves->request.params;
    p.title = std::string(busy ? "updating…  " : "") +
              "r_{x}(ζ, θ), r_{disp} = " + format_number("%.3g", q.rdisp) +
              ", i = " + format_number("%g", q.i);
    p.legend = Legend::none;
    const double theta_deg = std::min(90.0, std::abs(90 - std::abs(q.theta * 180 / kPi - 90)));
    p.points.push_back({Vec2(std::min(q.zeta, 3.0), theta_deg), Ink::tip, Mark::diamond, "", 12});
    return p;
}

LoopData hysteresis_loop(const LiveSim& sim, double rewind) {
    LoopData loop;
    const Params& p = sim.params();
    const Vec2 dir{std::cos(p.theta), std::sin(p.theta)};
    const auto& h = sim.history();
    const double t1 = moment_at(sim, rewind).tau, t0 = t1 - 2 * kPi;
    if (h.empty() || h.front().tau > t0 + 1e-9) return loop; // less than a period recorded
    const LiveSample* prev = nullptr;
    for (const LiveSample& s : h) {
        if (s.tau < t0 - 1e-9 || s.tau > t1 + 1e-9) continue;
        loop.u.push_back(std::sin(s.tau));
        loop.f.push_back(s.F.dot(dir));
        loop.slip.push_back(s.slip);
        if (prev) {
            // Midpoint rule on each step: the force over the step times P's move over it.
            const Vec2 F = 0.5 * (s.F + prev->F);
            loop.work += F.dot(s.P - prev->P);
            loop.vibration_work += F.dot(dir) * (std::sin(s.tau) - std::sin(prev->tau));
        }
        prev = &s;
    }
    loop.complete = true;
    return loop;
}

PanelData loop_panel_live(const LiveSim& sim, double rewind) {
    PanelData panel;
    panel.x_title = "vibration displacement u / x_{v} = sin τ";
    panel.y_title = "F along the vibration / F_{c}";
    panel.x_min = -1.1, panel.x_max = 1.1, panel.y_min = -1.15, panel.y_max = 1.15;
    panel.legend = Legend::none;
    const LoopData loop = hysteresis_loop(sim, rewind);
    if (!loop.complete) {
        panel.title = "hysteresis loop: after the first period";
        return panel;
    }
    // W: the work of the body against friction over the period, in F_c x_v (what the vibration and the drive
    // together dissipate); the loop's area is the vibration's share.
    panel.title = "last period: W = ∮F·dP = " + format_number("%.3g", loop.work) + " F_{c}x_{v}, loop area " +
                  format_number("%.3g", loop.vibration_work);
    // Coloured by the tip's state, as the top view's spring: the stick ramps green, the slips reddish purple.
    // Each run of one state is a series; the runs share their end samples so that the loop stays closed.
    for (std::size_t k = 0; k < loop.u.size();) {
        std::size_t e = k + 1;
        while (e < loop.u.size() && loop.slip[e] == loop.slip[k]) ++e;
        const std::size_t last = std::min(e, loop.u.size() - 1);
        SeriesData s{"",
                     {loop.u.begin() + static_cast<std::ptrdiff_t>(k),
                      loop.u.begin() + static_cast<std::ptrdiff_t>(last) + 1},
                     {loop.f.begin() + static_cast<std::ptrdiff_t>(k),
                      loop.f.begin() + static_cast<std::ptrdiff_t>(last) + 1},
                     loop.slip[k] ? Ink::slip : Ink::pull,
                     Dash::solid,
                     Mark::none,
                     2.2f};
        panel.series.push_back(std::move(s));
        k = e;
    }
    if (sim.model() == Model::dahl) {
        panel.legend = Legend::best;
        panel.series.push_back(key(sim.params().i == 0 ? "T sticks" : "T creeps", Ink::pull, 2.4f));
        panel.series.push_back(key("T slips", Ink::slip, 2.4f));
    }
    return panel;
}

namespace {

// Whether arrow `a` runs along arrow `b`: a third of it within `within` of the axes' spans of b's shaft, so
// that one hides the other. A live arrow (3 units wide) hides a faded one within 3 % (at the app's panel
// sizes several pixels, more than the layout test's reach); two faded ones (1.2 units) hide each other within
// 1 % (looser, and at 90 deg the velocities at tau = 0 and pi/4 would go, which the eye tells apart).
constexpr double kLiveHides = 0.03, kFadedHides = 0.01;
bool runs_along(const ArrowData& a, const ArrowData& b, const PanelData& panel, double within = kLiveHides) {
    const double sx = panel.x_max.value_or(1) - panel.x_min.value_or(0),
                 sy = panel.y_max.value_or(1) - panel.y_min.value_or(0);
    const Vec2 scale(1 / sx, 1 / sy);
    const Vec2 b0 = b.from.cwiseProduct(scale), d = (b.to - b.from).cwiseProduct(scale);
    const double l2 = d.squaredNorm();
    int near = 0;
    constexpr int kN = 24;
    for (int k = 0; k <= kN; ++k) {
        const Vec2 q = (a.from + (a.to - a.from) * (static_cast<double>(k) / kN)).cwiseProduct(scale);
        const double t = l2 > 0 ? std::clamp((q - b0).dot(d) / l2, 0.0, 1.0) : 0.0;
        near += (q - b0 - t * d).norm() <= within;
    }
    return near * 3 > kN + 1;
}

// Drops the faded arrows of `panel` that run along `over` (either way): the live arrow
// stands in for what it would hide.
void drop_hidden(PanelData& panel, const ArrowData& over) {
    auto& a = panel.arrows;
    a.erase(std::remove_if(
                a.begin(), a.end(),
                [&](const ArrowData& x) { return runs_along(x, over, panel) || runs_along(over, x, panel); }),
            a.end());
}

} // namespace

const PanelData& MechanismBase::for_params(const Params& p) {
    const Vec2 key{p.zeta, p.theta};
    if (!cached_ || cached_->first != key) {
        FigureData fig4; // the paper's Fig. 4 at these zeta and theta: its left panel
        mechanism_panels(MechanismFigure{p.zeta, p.theta}, fig4);
        PanelData base = std::move(fig4.panels.at(0));
        // Faded: the live arrows are the ones to follow. Of two that run along each other (at theta = 30 deg
        // the friction at tau = 0 and pi/4; at 90 deg the friction at pi/2 and the mean) the later is kept:
        // the mean friction is last.
        for (ArrowData& a : base.arrows) a.width *= 0.6f, a.opacity = 0.5f, a.label.clear();
        for (SeriesData& x : base.series) x.opacity *= 0.6f;
        std::vector<ArrowData> kept;
        for (auto a = base.arrows.rbegin(); a != base.arrows.rend(); ++a)
            if (std::none_of(kept.begin(), kept.end(), [&](const ArrowData& k) {
                    return runs_along(*a, k, base, kFadedHides) || runs_along(k, *a, base, kFadedHides);
                }))
                kept.push_back(*a);
        base.arrows.assign(kept.rbegin(), kept.rend());
        cached_.emplace(key, std::move(base));
    }
    return cached_->second;
}

PanelData mechanism_panel_live(const LiveSim& sim, MechanismBase& base, double rewind) {
    PanelData panel = base.for_params(sim.params());
    const SimMoment m = moment_at(sim, rewind);
    const Vec2 v = m.velocity;
    // The friction on the body: against the velocity (rigid), or -F of the asperity (Dahl).
    const bool rigid = sim.model() == Model::rigid;
    const Vec2 f = rigid ? coulomb(v) : Vec2(-m.F);
    const double phase = std::fmod(m.tau / (2 * kPi), 1.0);
    ArrowData va{Vec2::Zero(), v, Ink::body, "v", 3.0f}, fa{Vec2::Zero(), f, Ink::tip, "friction", 3.0f};
    std::string what = "v turns, friction follows", state;
    if (mechanism_parallel(sim.params().theta)) {
        // The rows of the base are instants up a time axis: the live arrows ride up it at the phase now,
        // their components along v_b, and the friction's label says whether the tip sticks.
        const double t = 2 * kPi * phase;
        va.from = Vec2(0, t + kMechanismRowGap), va.to = Vec2(v.x(), t + kMechanismRowGap);
        fa.from = Vec2(0, t - kMechanismRowGap), fa.to = Vec2(f.x(), t - kMechanismRowGap);
        const bool reverses = sim.params().zeta < std::abs(std::cos(sim.params().theta));
        what = !reverses
                   ? "v never reverses, friction stays against v_{b}"
                   : (rigid ? "v reverses, friction reverses with it" : "v reverses, friction after it");
        // Whether the tip sticks (the friction turning over while P moves back) or slips, in the title: a
        // longer label would find no free place between the rows.
        if (!rigid) state = m.slip ? ", T slips" : (sim.params().i == 0 ? ", T sticks" : ", T creeps");
    } else {
        // The labels centred beyond the heads first (above an arrow pointing up, below one pointing down):
        // beside a sloping shaft the label's corner may touch it.
        va.label_dy = v.y() > 0 ? -1 : 1;
        fa.label_dy = f.y() > 0 ? -1 : 1;
    }
    // Looser than a faded arrow's (5 % of the span): in presentation mode the panel is smaller and its
    // arrows wider, and two live arrows within 3 % met on screen.
    constexpr double kLiveMeet = 0.05;
    if (!mechanism_parallel(sim.params().theta) &&
        (runs_along(fa, va, panel, kLiveMeet) || runs_along(va, fa, panel, kLiveMeet))) {
        // In the plane both start at the body: where the friction lies along the velocity (the Dahl
        // friction has not turned yet, or v is so short that it is all tail), the friction is drawn beside
        // it, shifted across its own line by 4 % of the axes' span, away from v.
        const Vec2 d = fa.to - fa.from;
        if (d.norm() > 0) {
            const double span = panel.x_max.value_or(1) - panel.x_min.value_or(0);
            Vec2 shift = Vec2(-d.y(), d.x()).normalized() * (0.04 * span);
            if (shift.dot(va.to - va.from) > 0) shift = -shift; // to the side away from the velocity
            fa.from += shift, fa.to += shift;
        }
    }
    panel.title = "mechanism now (τ/2π = " + format_number("%.2f", phase) + state + "): " + what;
    drop_hidden(panel, va);
    drop_hidden(panel, fa);
    panel.arrows.push_back(va);
    panel.arrows.push_back(fa);
    panel.legend = Legend::none; // the loci are explained by the help overlay; a legend would cover arrows
    return panel;
}

PanelData lower_panel_live(LowerPanel which, const LiveSim& sim, const std::optional<RatioCurves>& curves,
                           bool busy, const RatioOverlay& overlay, MechanismBase& mechanism, double rewind) {
    PanelData p;
    switch (which) {
    case LowerPanel::map:
        p = map_panel_live(sim, curves, busy);
        break;
    case LowerPanel::loop:
        p = loop_panel_live(sim, rewind);
        break;
    case LowerPanel::why:
        p = mechanism_panel_live(sim, mechanism, rewind);
        break;
    case LowerPanel::setup:
        p = setup_panel(sim.params().theta);
        break;
    case LowerPanel::curves:
        return ratio_panel_live(curves, busy, overlay);
    }
    // The panels that show A alone say so beside B.
    if (overlay.b.sim) p.title = "A: " + p.title;
    return p;
}

} // namespace fv
