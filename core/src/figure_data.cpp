#include "fv/figure_data.hpp"
#include "fv/axis_titles.hpp"

#include "family_style.hpp"
#include "figure_panels.hpp"
#include "scene_parts.hpp"

#include "fv/adaptive_sampling.hpp"
#include "fv/format.hpp"
#include "fv/ode_solver.hpp"
#include "fv/rigid.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fv {
namespace {

std::string curve_label(const Curve& c, bool vary_theta) {
    if (c.model == Model::rigid)
        return vary_theta ? "θ = " + format_number("%g", c.theta * 180 / kPi) + "°" : "rigid";
    return "r_{disp} = " + format_number("%g", c.rdisp);
}

// The marks of the points the solver could not vouch for (their curves have a gap there), at their last
// value; empty when there are none.
SeriesData unverified_marks(const std::vector<std::vector<SweepPoint>>& computed, bool side_force) {
    SeriesData s{"no steady state vouched for (gap)", {}, {}, Ink::tip, Dash::solid, Mark::cross, 0};
    for (const std::vector<SweepPoint>& pts : computed)
        for (const SweepPoint& sp : pts)
            if (!ok(sp.result.status)) {
                s.x.push_back(sp.params.zeta);
                s.y.push_back(side_force ? sp.result.ry : sp.result.rx);
            }
    return s;
}

// r_x(zeta) curves, steady states reached from `start`; one table row per point. A point the solver cannot
// vouch for is not drawn as if it were valid: its curve has a gap there, marked (unverified_marks); the
// table keeps its values and status.
PanelData ratio_panel(const RatioCurvesFigure& spec, Start start, std::vector<SweepPoint>& rows,
                      int threads) {
    PanelData panel;
    panel.x_title = titles::kZeta;
    panel.y_title = spec.side_force ? titles::kRy : titles::kRx;
    const std::vector<double>& zetas = spec.zetas;
    panel.x_min = spec.axis ? spec.axis->from : std::min(0.0, zetas.front());
    panel.x_max = spec.axis ? spec.axis->to : zetas.back();
    panel.log_x = spec.log_zeta;
    if (!spec.side_force) { // r_y: fitted to the curves
        panel.y_min = 0;
        panel.y_max = 1.05;
    }
    bool all_rigid = true;
    for (const auto& c : spec.curves) all_rigid = all_rigid && c.model == Model::rigid;
    // On a log axis the curves are sampled evenly in u = log10(zeta), so that each decade gets its share;
    // the start grid's ends stay exactly the span's.
    std::vector<double> grid = zetas;
    if (spec.log_zeta)
        for (double& u : grid) u = std::log10(u);
    auto zeta_of = [&](double x) {
        if (!spec.log_zeta) return x;
        return x == grid.front() ? zetas.front() : x == grid.back() ? zetas.back() : std::pow(10.0, x);
    };
    // Each round of points over all curves in one flat list keeps both cores busy even when one curve is
    // slow. Without a budget the grid is the samples.
    std::vector<std::vector<SweepPoint>> computed(spec.curves.size());
    auto eval = [&](const std::vector<SampleRequest>& req) {
        std::vector<SweepPoint> pts(req.size());
        for (std::size_t k = 0; k < req.size(); ++k) {
            const Curve& c = spec.curves[req[k].curve];
            const double nan = std::nan("");
            pts[k].model = c.model;
            pts[k].params = {zeta_of(req[k].x), c.theta, c.model == Model::rigid ? nan : c.rdisp,
                             c.model == Model::rigid ? nan : c.i};
        }
        parallel_for(
            static_cast<int>(pts.size()),
            [&](int k) {
                auto& sp = pts[static_cast<std::size_t>(k)];
                SteadyOptions o;
                o.start = start;
                sp.result = steady_ratio(sp.model, sp.params, o);
            },
            threads);
        std::vector<double> y(req.size());
        for (std::size_t k = 0; k < req.size(); ++k) {
            y[k] = spec.side_force ? pts[k].result.ry : pts[k].result.rx;
            computed[req[k].curve].push_back(pts[k]);
        }
        return y;
    };
    AdaptiveSampling o;
    o.x_span = spec.log_zeta ? grid.back() - grid.front() : *panel.x_max - *panel.x_min;
    o.y_span = panel.y_min && panel.y_max ? *panel.y_max - *panel.y_min : 0; // 0: the values' own range
    o.budget = spec.zeta_budget > 0 ? spec.zeta_budget : zetas.size();
    if (spec.zeta_budget == 0) o.max_rounds = 1;
    adaptive_sample(spec.curves.size(), grid, o, eval);
    const std::vector<SeriesData> styles =
        spec.family ? family::curve_styles(spec.curves) : std::vector<SeriesData>{};
    rows.clear();
    for (std::size_t ci = 0; ci < spec.curves.size(); ++ci) {
        const Curve& c = spec.curves[ci];
        std::vector<SweepPoint>& pts = computed[ci];
        std::stable_sort(pts.begin(), pts.end(), [](const SweepPoint& a, const SweepPoint& b) {
            return a.params.zeta < b.params.zeta;
        });
        SeriesData s;
        s.label = curve_label(c, all_rigid);
        if (spec.family) {
            s = styles[ci];
        } else if (spec.side_force) {
            // One colour per angle, the model by the dash: "θ = 30°, Dahl" solid, "θ = 30°, rigid" dashed.
            s.label = curve_label({Model::rigid, c.theta, 0, 0}, true) +
                      (c.model == Model::rigid ? ", rigid" : ", Dahl");
            s.palette = 0;
            for (std::size_t cj = 0; cj < ci; ++cj)
                if (spec.curves[cj].model == c.model) ++s.palette;
            if (c.model == Model::rigid) s.dash = Dash::dashed;
        } else if (c.model == Model::rigid && !all_rigid) {
            s = scene::rigid_curve({}, {});
        }
        for (const SweepPoint& sp : pts) {
            s.x.push_back(sp.params.zeta);
            s.y.push_back(!ok(sp.result.status) ? std::nan("")
                          : spec.side_force     ? sp.result.ry
                                                : sp.result.rx);
            rows.push_back(sp);
        }
        panel.series.push_back(std::move(s));
    }
    if (SeriesData marks = unverified_marks(computed, spec.side_force); !marks.x.empty())
        panel.series.push_back(std::move(marks));
    if (spec.data) {
        for (SeriesData& d :
             family::data_series(*spec.data, spec.axis.value_or(ZetaSpan{0, kZetaRange.hi}))) {
            // Noisy points beyond [0, 1] stay on the plot.
            for (std::size_t k = 0; k < d.y.size(); ++k) {
                const double err = d.y_err.empty() ? 0 : d.y_err[k];
                panel.y_max = std::max(*panel.y_max, d.y[k] + err + 0.02);
                panel.y_min = std::min(*panel.y_min, d.y[k] - err - 0.02);
            }
            panel.series.push_back(std::move(d));
        }
    }
    return panel;
}

// One steady period with samples: the continuous-time solver (1024 samples) unless the spec asks for the
// paper's scheme at a given resolution.
SteadyResult steady_trace(const Params& p, int steps, Start start = Start::rest, bool list_states = false) {
    SteadyOptions o;
    o.record_period = true;
    o.steps_per_period = steps;
    o.start = start;
    o.list_states = list_states;
    return steady_ratio(Model::dahl, p, o);
}

// Which steady state a figure's number belongs to, where that is not plain: " (period 2)", "; also stable:
// 0.9975 (from sliding)" (the other stable states' r_x and the start that reaches each).
// The stable states other than the one reported that some start's motion is shown to reach (a state found
// without that evidence is left out).
std::vector<SteadyState> other_reached_states(const SteadyResult& r) {
    std::vector<SteadyState> out;
    for (const SteadyState& st : r.states)
        if ((std::abs(st.rx - r.rx) > 1e-6 || std::abs(st.ry - r.ry) > 1e-6) &&
            (st.from_rest || st.from_sliding))
            out.push_back(st);
    return out;
}

std::string state_note(const SteadyResult& r) {
    std::string s;
    if (r.status == SteadyStatus::periodic) s += " (period " + std::to_string(r.period_k) + ")";
    std::string others;
    for (const SteadyState& st : other_reached_states(r)) {
        others += std::string(others.empty() ? "" : ",") + " " + format_number("%.4f", st.rx);
        if (st.from_rest != st.from_sliding) others += st.from_rest ? " (from rest)" : " (from sliding)";
    }
    if (!others.empty()) s += "; also stable:" + others;
    return s;
}

// P and T over one steady period with the spring drawn at 24 regular instants.
PanelData top_view(const Params& p, const std::vector<Sample>& period, const std::vector<Sample>* other) {
    PanelData panel = scene::top_view_axes();
    SeriesData P = scene::body_path(2.5f), T = scene::tip_path(2.5f);
    // Start the paths at the period's start (the sample before the first of Eq. (30)'s k = 1..n).
    const Sample& last = period.back();
    const Vec2 shift(-2 * kPi * p.zeta, 0);
    P.x.push_back(last.P.x() + shift.x());
    P.y.push_back(last.P.y());
    T.x.push_back(last.T.x() + shift.x());
    T.y.push_back(last.T.y());
    for (const auto& s : period) {
        P.x.push_back(s.P.x());
        P.y.push_back(s.P.y());
        T.x.push_back(s.T.x());
        T.y.push_back(s.T.y());
    }
    const std::size_t n = period.size();
    for (int j = 0; j < 24; ++j) {
        const Sample& s = period[(n * static_cast<std::size_t>(j)) / 24 + n / 48];
        panel.segments.push_back({s.P, s.T, Ink::spring, Dash::solid, 1.2f, ""});
    }
    // With the other i overlaid (Fig. 17), both tips say which i they are, as the title does.
    if (other) T.label += ", i = " + format_number("%g", p.i);
    panel.series.push_back(std::move(P));
    panel.series.push_back(std::move(T));
    if (other) {
        SeriesData T0{"", {}, {}, Ink::black, Dash::dashed, Mark::none, 1.5f};
        T0.label = p.i == 0 ? "asperity tip T, i = 1" : "asperity tip T, i = 0"; // the overlaid other i
        for (const auto& s : *other) {
            T0.x.push_back(s.T.x());
            T0.y.push_back(s.T.y());
        }
        panel.series.push_back(std::move(T0));
    }
    panel.points.push_back(scene::body_mark(last.P + shift, 9));
    panel.points.push_back(scene::tip_mark(last.T + shift, Ink::tip, 9));
    // Frame both paths with a margin, so the labels of the start points stay inside the plot.
    double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
    for (const SeriesData& s : panel.series)
        for (std::size_t k = 0; k < s.x.size(); ++k) {
            x0 = std::min(x0, s.x[k]), x1 = std::max(x1, s.x[k]);
            y0 = std::min(y0, s.y[k]), y1 = std::max(y1, s.y[k]);
        }
    const double m = 0.08 * std::max(x1 - x0, y1 - y0);
    panel.x_min = x0 - m, panel.x_max = x1 + m, panel.y_min = y0 - m, panel.y_max = y1 + m;
    return panel;
}

PanelData force_panel(const std::vector<Sample>& period) {
    // The convention of F: the captions say what it means.
    PanelData panel = scene::force_axes(std::string(titles::kTime) + " over one period");
    panel.x_min = 0;
    panel.x_max = 2 * kPi;
    scene::ForceCurves f;
    const double t0 = period.front().tau - (period[1].tau - period[0].tau);
    for (const auto& s : period) f.add(s.tau - t0, s.F);
    panel.series = f.take();
    return panel;
}

// Fig. 8: choose the step of a coarse steady period where the pull line turns the spring the most, so
// that P(t), P(t+dt), T(t), T(t+dt) are all distinct on the page.
PanelData step_panel(const Params& p, int n, std::vector<Sample>& rows) {
    SteadyOptions o;
    o.steps_per_period = n;
    const SteadyResult res = dahl_steady(p, o);
    PaperStepper st(p, n,
                    res.period.empty() ? Vec2::Zero() : Vec2(res.period.back().P - res.period.back().T));
    int best = 0;
    double best_turn = -1;
    {
        PaperStepper probe = st;
        for (int k = 0; k < n; ++k) {
            const Vec2 lag = probe.lag();
            probe.step();
            const Vec2 nl = probe.lag();
            const double turn =
                std::abs(lag.x() * nl.y() - lag.y() * nl.x()) / (lag.norm() * nl.norm() + 1e-300);
            if (turn > best_turn) {
                best_turn = turn;
                best = k;
            }
        }
    }
    for (int k = 0; k < best; ++k) st.step();
    const Sample a = st.sample();
    st.step();
    const Sample b = st.sample();
    rows = {a, b};

    PanelData panel;
    panel.equal_aspect = true;
    panel.x_title = titles::kTopViewX;
    panel.y_title = titles::kTopViewY;
    // P's path around the step, finely resolved.
    SeriesData path{"path of P", {}, {}, Ink::body, Dash::solid, Mark::none, 1.5f};
    for (int j = -40; j <= 60; ++j) {
        const Vec2 q = body_point(p, a.tau + j * (b.tau - a.tau) / 20);
        path.x.push_back(q.x());
        path.y.push_back(q.y());
    }
    panel.series.push_back(std::move(path));
    // T(t+dt) lies on the pull line (Eqs. (21)-(22)), so z(t+dt) overlaps it: label them on opposite sides.
    panel.segments.push_back({a.P, a.T, Ink::spring, Dash::solid, 2.0f, "z(t)", 0.5f, 0});
    panel.segments.push_back({b.P, b.T, Ink::tip, Dash::solid, 3.0f, "z(t+Δt)", 0.5f, 1});
    panel.segments.push_back({b.P, a.T, Ink::pull, Dash::dashed, 1.5f, "pull line T(t)–P(t+Δt)", 0.35f, -1});
    panel.points.push_back({a.P, Ink::body, Mark::circle, "P(t)", 10});
    panel.points.push_back({b.P, Ink::body, Mark::circle, "P(t+Δt)", 10});
    // The tip moves little in one step: put its two labels on opposite sides.
    panel.points.push_back({a.T, Ink::tip, Mark::square, "T(t)", 10, -1, -1});
    panel.points.push_back({b.T, Ink::tip, Mark::square, "T(t+Δt)", 10, 1, 1});
    // Frame the step: the four points with a margin of half their spread.
    double x0 = a.P.x(), x1 = x0, y0 = a.P.y(), y1 = y0;
    for (const Vec2& q : {a.P, b.P, a.T, b.T}) {
        x0 = std::min(x0, q.x());
        x1 = std::max(x1, q.x());
        y0 = std::min(y0, q.y());
        y1 = std::max(y1, q.y());
    }
    const double m = 0.35 * std::max(x1 - x0, y1 - y0);
    panel.x_min = x0 - m;
    panel.x_max = x1 + m;
    panel.y_min = y0 - m;
    panel.y_max = y1 + m;
    return panel;
}

// Index and sub-grid position of the smallest value in a row, refined by a parabola through the minimum
// and its neighbours (the curve theta*(zeta) would otherwise move in 1-degree stairs).
double refined_argmin(const std::vector<double>& row, double x0, double dx) {
    std::size_t k = 0;
    for (std::size_t j = 1; j < row.size(); ++j)
        if (row[j] < row[k]) k = j;
    double x = x0 + dx * static_cast<double>(k);
    if (k > 0 && k + 1 < row.size()) {
        const double a = row[k - 1], b = row[k], c = row[k + 1], den = a - 2 * b + c;
        if (den > 0) x += 0.5 * dx * (a - c) / den;
    }
    return x;
}

// Breaks a curve (a NaN sample, which the plot does not join) where it jumps instead of changing: at a step
// larger than `min_jump` and than 4 times each neighbouring step. The argmin theta*(zeta) jumps where another
// angle's minimum becomes the lower one; a line joining the two sides would draw angles that are never best.
void break_at_jumps(SeriesData& s, double min_jump) {
    SeriesData out = s;
    out.x.clear(), out.y.clear();
    const std::size_t n = std::min(s.x.size(), s.y.size());
    auto step = [&](std::size_t k) { return k >= 1 && k < n ? std::fabs(s.y[k] - s.y[k - 1]) : 0.0; };
    for (std::size_t k = 0; k < n; ++k) {
        const double d = step(k);
        if (k > 0 && d > min_jump && d > 4 * step(k - 1) && d > 4 * step(k + 1)) {
            out.x.push_back(std::nan(""));
            out.y.push_back(std::nan(""));
        }
        out.x.push_back(s.x[k]);
        out.y.push_back(s.y[k]);
    }
    s = std::move(out);
}

// The map's cells that one colour does not describe, marked at their centres (in the legend only where
// some are): motion with a longer period (the colour is its mean over the k periods), a second stable
// steady state (the other start reaches it; the colour is the state this start reaches), and no state that
// the solver could vouch for (the colour is its last value; the CSV names the status).
std::vector<SeriesData> cell_marks(const std::vector<SweepPoint>& rows) {
    SeriesData period{"period 2, 4, … (mean shown)", {}, {}, Ink::black, Dash::solid, Mark::cross, 0};
    SeriesData two{"2 stable states", {}, {}, Ink::black, Dash::solid, Mark::circle, 0};
    SeriesData none{"no steady state vouched for", {}, {}, Ink::tip, Dash::solid, Mark::square, 0};
    for (const SweepPoint& sp : rows) {
        const double z = sp.params.zeta, th = sp.params.theta * 180 / kPi;
        // States that some start's motion is shown to reach (a state found without that evidence is not
        // marked).
        const long reached =
            std::count_if(sp.result.states.begin(), sp.result.states.end(),
                          [](const SteadyState& st) { return st.from_rest || st.from_sliding; });
        SeriesData* to = !ok(sp.result.status)                        ? &none
                         : sp.result.status == SteadyStatus::periodic ? &period
                         : reached >= 2                               ? &two
                                                                      : nullptr;
        if (!to) continue;
        to->x.push_back(z);
        to->y.push_back(th);
    }
    std::vector<SeriesData> out;
    for (SeriesData* s : {&period, &two, &none})
        if (!s->x.empty()) {
            s->mark_size = 4.5f;
            out.push_back(std::move(*s));
        }
    return out;
}

std::vector<double> map_thetas(const MapFigure& spec) {
    const double dth = spec.theta_max_deg / (spec.theta_count - 1);
    std::vector<double> thetas;
    for (int j = 0; j < spec.theta_count; ++j) thetas.push_back(j * dth * kPi / 180);
    return thetas;
}

PanelData map_panel(const MapFigure& spec, std::string& table, int threads,
                    std::vector<SweepPoint>& rows_out) {
    // Row by row along zeta (a cell may start from the cells before it), rows spread over the cores.
    rows_out = map_points(spec);
    const std::size_t nz = spec.zetas.size();
    parallel_for(
        spec.theta_count,
        [&](int row) {
            for (std::size_t k = 0; k < nz; ++k) {
                const std::size_t u = static_cast<std::size_t>(row) * nz + k;
                rows_out[u].result = map_cell(spec, rows_out, u);
            }
        },
        threads);
    return map_panel_of(spec, rows_out, &table, threads);
}

} // namespace

std::vector<SweepPoint> map_points(const MapFigure& spec) {
    return sweep_grid(spec.model, spec.zetas, map_thetas(spec), {spec.rdisp}, {spec.i});
}

SteadyOptions map_options(const MapFigure& spec) {
    SteadyOptions opt;
    if (spec.ode_tolerance > 0) opt.ode_tolerance = spec.ode_tolerance;
    opt.record_period = false; // as sweep() computes them
    opt.start = spec.start;
    opt.list_states = true; // the map marks the cells where the other start reaches another state
    return opt;
}

SteadyResult map_cell(const MapFigure& spec, const std::vector<SweepPoint>& points, std::size_t k) {
    if (spec.model == Model::rigid) return steady_ratio(Model::rigid, points[k].params); // Eq. 9
    const std::size_t pos = k % spec.zetas.size(); // place in its theta row
    const SteadyResult* prev1 = pos >= 1 ? &points[k - 1].result : nullptr;
    const SteadyResult* prev2 = pos >= 2 ? &points[k - 2].result : nullptr;
    OdeOptions o = ode_options(map_options(spec));
    o.list_states_after_failure = false; // a failed cell is marked as such, whatever the other start gives
    o.list_only_reached = true;          // its marks name only states a start reaches
    return ode_map_cell(points[k].params, prev1, prev2, o);
}

PanelData map_panel_of(const MapFigure& spec, const std::vector<SweepPoint>& rows, std::string* best_table,
                       int threads) {
    const std::vector<double>& zetas = spec.zetas;
    const int nth = spec.theta_count;
    const double dth = spec.theta_max_deg / (nth - 1);
    const std::vector<double> thetas = map_thetas(spec);
    const std::size_t nz = zetas.size();
    HeatmapData h;
    h.nx = static_cast<int>(nz);
    h.ny = nth;
    // Cells centred on the grid values.
    const double dz = (zetas.back() - zetas.front()) / static_cast<double>(nz - 1);
    h.x0 = zetas.front() - dz / 2, h.x1 = zetas.back() + dz / 2;
    h.y0 = -dth / 2, h.y1 = spec.theta_max_deg + dth / 2;
    h.label = "r_{x}";
    h.values.assign(nz * static_cast<std::size_t>(nth), 0);
    for (int j = 0; j < nth; ++j)
        for (std::size_t k = 0; k < nz; ++k)
            h.values[static_cast<std::size_t>(j) * nz + k] =
                rows[static_cast<std::size_t>(j) * nz + k].result.rx;

    // theta*(zeta): the angle of the smallest r_x, for the Dahl model and for the rigid one.
    SeriesData best{"best angle θ*, Dahl", {}, {}, Ink::black, Dash::solid, Mark::none, 2.5f};
    SeriesData best_rigid{"best angle θ*, rigid", {}, {}, Ink::black, Dash::dashed, Mark::none, 1.8f};
    std::string table = "zeta,theta_star_deg,r_x_min,theta_star_rigid_deg,r_x_rigid_min\n";
    std::vector<double> col(static_cast<std::size_t>(nth)), col_rigid(static_cast<std::size_t>(nth));
    std::vector<double> rigid(nz * static_cast<std::size_t>(nth));
    parallel_for(
        static_cast<int>(rigid.size()),
        [&](int k) {
            const std::size_t u = static_cast<std::size_t>(k);
            rigid[u] = rigid_ratio(zetas[u % nz], thetas[u / nz]).rx;
        },
        threads);
    for (std::size_t k = 0; k < nz; ++k) {
        double rmin = 1e9, rrmin = 1e9;
        for (int j = 0; j < nth; ++j) {
            const std::size_t u = static_cast<std::size_t>(j) * nz + k;
            col[static_cast<std::size_t>(j)] = h.values[u];
            col_rigid[static_cast<std::size_t>(j)] = rigid[u];
            rmin = std::min(rmin, h.values[u]);
            rrmin = std::min(rrmin, rigid[u]);
        }
        const double t = refined_argmin(col, 0, dth), tr = refined_argmin(col_rigid, 0, dth);
        best.x.push_back(zetas[k]), best.y.push_back(t);
        best_rigid.x.push_back(zetas[k]), best_rigid.y.push_back(tr);
        table += format_number("%.6g", zetas[k]) + "," + format_number("%.4f", t) + "," +
                 format_number("%.8f", rmin) + "," + format_number("%.4f", tr) + "," +
                 format_number("%.8f", rrmin) + "\n";
    }
    break_at_jumps(best, 5);
    break_at_jumps(best_rigid, 5);
    std::vector<SeriesData> marks = cell_marks(rows);
    PanelData panel;
    panel.x_title = titles::kZeta;
    panel.y_title = titles::kTheta;
    panel.x_min = h.x0, panel.x_max = h.x1, panel.y_min = h.y0, panel.y_max = h.y1;
    panel.heatmap = std::move(h);
    panel.series = {std::move(best), std::move(best_rigid)};
    for (SeriesData& m : marks) panel.series.push_back(std::move(m));
    if (best_table) *best_table = std::move(table);
    return panel;
}

namespace {

// Fig. 14: one top view per exponent on shared axes (the frame of all panels), titled (a), (b), ...; one
// trace table each ("", "-b", ...). only_panel keeps one of them, on the same axes.
void period_panels(const PeriodViewFigure& spec, FigureData& fig) {
    std::vector<PanelData> panels;
    std::vector<TableData> tables;
    for (std::size_t k = 0; k < spec.panel_i.size(); ++k) {
        Params q = spec.params;
        q.i = spec.panel_i[k];
        const SteadyResult r = steady_trace(q, spec.steps_per_period);
        PanelData panel = top_view(q, r.period, nullptr);
        const std::string tag(1, static_cast<char>('a' + k));
        panel.title = "(" + tag + ") i = " + format_number("%g", q.i) +
                      (q.i == 0 ? " (stiction, Eq. 27)" : (q.i == 1 ? " (no stiction, Eq. 17)" : ""));
        panels.push_back(std::move(panel));
        tables.push_back({k == 0 ? "" : "-" + tag, {}, r.period, "", r.status});
    }
    for (PanelData& p : panels)
        for (const PanelData& o : panels) {
            p.x_min = std::min(*p.x_min, *o.x_min), p.x_max = std::max(*p.x_max, *o.x_max);
            p.y_min = std::min(*p.y_min, *o.y_min), p.y_max = std::max(*p.y_max, *o.y_max);
        }
    if (spec.only_panel >= 0) {
        const auto k = static_cast<std::size_t>(spec.only_panel);
        panels = {std::move(panels.at(k))};
        panels[0].title.clear(); // the figure's title says which
        tables = {std::move(tables.at(k))};
        tables[0].suffix.clear();
    }
    fig.panels = std::move(panels);
    fig.tables = std::move(tables);
}

// The panels and tables of each kind of figure.
void compute_content(const RatioCurvesFigure& spec, FigureData& fig, int threads) {
    TableData t;
    fig.panels.push_back(ratio_panel(spec, spec.start, t.ratios, threads));
    fig.tables.push_back(std::move(t));
}

void compute_content(const MechanismFigure& spec, FigureData& fig, int) {
    mechanism_panels(spec, fig);
}

void compute_content(const DahlCurvesFigure& spec, FigureData& fig, int) {
    dahl_curve_panels(spec, fig);
}

void compute_content(const StepViewFigure& spec, FigureData& fig, int) {
    TableData t;
    fig.panels.push_back(step_panel(spec.params, spec.steps_per_period, t.trace));
    fig.tables.push_back(std::move(t));
}

void compute_content(const PeriodViewFigure& spec, FigureData& fig, int) {
    if (!spec.panel_i.empty()) {
        period_panels(spec, fig);
        return;
    }
    const Params& p = spec.params;
    const SteadyResult r = steady_trace(p, spec.steps_per_period);
    SteadyStatus status = r.status;
    if (spec.overlay_other_i) {
        Params q = p;
        q.i = p.i == 0 ? 1 : 0;
        const SteadyResult r2 = steady_trace(q, spec.steps_per_period);
        fig.panels.push_back(top_view(p, r.period, &r2.period));
        if (ok(r.status)) status = r2.status;
    } else {
        fig.panels.push_back(top_view(p, r.period, nullptr));
    }
    fig.tables.push_back({"", {}, r.period, "", status});
}

void compute_content(const PeriodForceFigure& spec, FigureData& fig, int) {
    const SteadyResult r = steady_trace(spec.params, spec.steps_per_period);
    fig.panels.push_back(force_panel(r.period));
    fig.tables.push_back({"", {}, r.period, "", r.status});
}

// A family of maps (map_family.hpp): each map's panel, titled with what varies, the rigid map without the
// Dahl theta* line (its own is the dashed one); all heat maps on one colour scale; the grids' rows in one
// table (their model, i and rdisp columns say which map a row is of), the best angles in one table with
// the inputs that vary in front (model, rdisp, i; empty where they do not apply).
void map_family_content(const MapFigure& spec, FigureData& fig, int threads) {
    TableData grid{"", {}, {}, ""}, best{"-best-angle", {}, {}, ""};
    bool by_model = false, by_rdisp = false, by_i = false;
    for (const MapPanelSpec& p : spec.family)
        for (const MapPanelSpec& q : spec.family) {
            by_model = by_model || p.model != q.model;
            if (p.model == Model::dahl && q.model == Model::dahl)
                by_rdisp = by_rdisp || p.rdisp != q.rdisp, by_i = by_i || p.i != q.i;
        }
    const auto cell = [](double v) { return std::isnan(v) ? std::string() : format_number("%.12g", v); };
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const MapPanelSpec& p : spec.family) {
        MapFigure one = spec;
        one.family.clear();
        one.model = p.model, one.rdisp = p.rdisp, one.i = p.i;
        std::string table;
        std::vector<SweepPoint> rows;
        PanelData panel = map_panel(one, table, threads, rows);
        panel.title = p.title;
        if (p.model == Model::rigid) panel.series.erase(panel.series.begin());
        for (double v : panel.heatmap->values)
            if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
        std::string prefix = std::string(by_model ? to_string(p.model) + std::string(",") : "") +
                             (by_rdisp ? cell(p.rdisp) + "," : "") + (by_i ? cell(p.i) + "," : "");
        const std::size_t header_end = table.find('\n') + 1;
        if (best.text.empty())
            best.text = std::string(by_model ? "model," : "") + (by_rdisp ? "rdisp," : "") +
                        (by_i ? "i," : "") + table.substr(0, header_end);
        for (std::size_t at = header_end; at < table.size();) {
            const std::size_t end = table.find('\n', at) + 1;
            best.text += prefix + table.substr(at, end - at);
            at = end;
        }
        grid.ratios.insert(grid.ratios.end(), rows.begin(), rows.end());
        fig.panels.push_back(std::move(panel));
    }
    for (PanelData& p : fig.panels) {
        p.heatmap->vmin = lo, p.heatmap->vmax = hi;
        p.heatmap->color_bar = false;
    }
    fig.columns = spec.columns;
    fig.tables.push_back(std::move(grid));
    fig.tables.push_back(std::move(best));
}

void compute_content(const MapFigure& spec, FigureData& fig, int threads) {
    if (!spec.family.empty()) {
        map_family_content(spec, fig, threads);
        return;
    }
    TableData grid{"", {}, {}, ""}, best{"-best-angle", {}, {}, ""};
    std::vector<SweepPoint> rows;
    fig.panels.push_back(map_panel(spec, best.text, threads, rows));
    // The grid itself as ratio rows (model,i,theta_deg,rdisp,zeta,r_x,...,status), like a sweep.
    grid.ratios = std::move(rows);
    fig.tables.push_back(std::move(grid));
    fig.tables.push_back(std::move(best));
}

void compute_content(const SceneFigure& spec, FigureData& fig, int threads) {
    const Params& p = spec.params;
    const SteadyResult r = steady_trace(p, 0, spec.start, true);
    PanelData view = top_view(p, r.period, nullptr);
    view.title = "top view";
    PanelData force = force_panel(r.period);
    force.title = "friction force over one period";
    TableData ratios{"-ratio", {}, {}, ""};
    PanelData curve = ratio_panel(spec.ratio, spec.start, ratios.ratios, threads);
    curve.title =
        "r_{x} = " + format_number("%.4f", r.rx) + ", r_{y} = " + format_number("%.4f", r.ry) + state_note(r);
    curve.points.push_back({Vec2(p.zeta, r.rx), Ink::black, Mark::diamond, "", 11});
    for (const SteadyState& st : other_reached_states(r)) // named in the title
        curve.points.push_back({Vec2(p.zeta, st.rx), Ink::tip, Mark::diamond, "", 9});
    fig.panels = {std::move(view), std::move(force), std::move(curve)};
    fig.tables.push_back({"", {}, r.period, "", r.status});
    fig.tables.push_back(std::move(ratios));
}

void compute_content(const MeasurementsFigure&, FigureData&, int) {} // computed when the spec was made

// The suffixes of the tables compute_content gives for each kind.
std::vector<std::string> suffixes(const MeasurementsFigure& spec) {
    std::vector<std::string> out;
    if (spec.precomputed)
        for (const TableData& t : spec.precomputed->tables) out.push_back(t.suffix);
    return out;
}

std::vector<std::string> suffixes(const PeriodViewFigure& spec) {
    if (spec.panel_i.empty() || spec.only_panel >= 0) return {""};
    std::vector<std::string> out; // as period_panels names them
    for (std::size_t k = 0; k < spec.panel_i.size(); ++k)
        out.push_back(k == 0 ? "" : "-" + std::string(1, static_cast<char>('a' + k)));
    return out;
}

std::vector<std::string> suffixes(const MapFigure&) {
    return {"", "-best-angle"};
}

std::vector<std::string> suffixes(const SceneFigure&) {
    return {"", "-ratio"};
}

template <class Content> std::vector<std::string> suffixes(const Content&) {
    return {""};
}

} // namespace

FigureData compute_figure(const FigureSpec& spec, int threads) {
    if (const auto* m = std::get_if<MeasurementsFigure>(&spec.content))
        return m->precomputed ? *m->precomputed : FigureData{spec.id, spec.title, {}, 0, {}};
    FigureData fig;
    fig.id = spec.id;
    fig.title = spec.title;
    std::visit([&](const auto& content) { compute_content(content, fig, threads); }, spec.content);
    return fig;
}

std::vector<std::string> table_suffixes(const FigureSpec& spec) {
    return std::visit([](const auto& content) { return suffixes(content); }, spec.content);
}

} // namespace fv
