#include "fv/fit_figure.hpp"
#include "fv/axis_titles.hpp"

#include "fv/format.hpp"
#include "fv/rigid.hpp"
#include "fv/sweep.hpp"

#include <algorithm>
#include <cmath>

namespace fv {

std::vector<SeriesData> measured_series(const MeasurementSet& data, std::optional<double> theta_deg) {
    SeriesData here, other;
    const std::string what = data.synthetic ? "synthetic example data" : "measured";
    here.label = what + (data.has_sigma ? " (± σ)" : "");
    other.label = what + " at another θ";
    for (SeriesData* s : {&here, &other}) {
        s->ink = Ink::black;
        s->mark = Mark::circle;
        s->width = 0; // markers only
    }
    other.opacity = 0.3f;
    for (const auto& m : data.points) {
        const bool elsewhere = theta_deg && m.theta_deg && std::abs(*m.theta_deg - *theta_deg) > 0.5;
        SeriesData& s = elsewhere ? other : here;
        s.x.push_back(m.zeta);
        s.y.push_back(m.rx);
        if (data.has_sigma) s.y_err.push_back(m.sigma.value_or(0));
    }
    std::vector<SeriesData> out;
    for (SeriesData* s : {&here, &other})
        if (!s->x.empty()) out.push_back(std::move(*s));
    return out;
}

FigureData measurement_figure(const MeasurementSet& data, const FitOptions& opt, FitResult* fit_out) {
    if (data.points.empty()) throw FitError("no measured points");
    // The angles, in the order the file gives them: one panel each, like the paper's Fig. 19 (a), (b).
    std::vector<double> angles;
    for (const auto& m : data.points) {
        const double t = m.theta_deg.value_or(opt.theta_deg.value_or(std::nan("")));
        if (!std::isfinite(t)) throw FitError("no vibration angle: give --theta or a theta_deg column");
        if (std::none_of(angles.begin(), angles.end(), [&](double a) { return std::abs(a - t) <= 1e-9; }))
            angles.push_back(t);
    }
    constexpr std::size_t kMaxPanels = 4;
    if (angles.size() > kMaxPanels)
        throw FitError("the figure draws one panel per vibration angle, at most 4; the data have " +
                       std::to_string(angles.size()) + " (split the file)");

    // One fit for all points: r_disp and i describe the contact, whatever the angle of the vibration.
    FitOptions o = opt;
    o.shape = ShapeChoice::automatic;
    const FitResult fit = fit_rdisp(data, o);
    if (fit_out) *fit_out = fit;

    FigureData fig;
    fig.id = "fig19";
    for (std::size_t a = 0; a < angles.size(); ++a) {
        const double theta_deg = angles[a];
        MeasurementSet here = data;
        here.points.clear();
        for (const auto& m : data.points)
            if (std::abs(m.theta_deg.value_or(theta_deg) - theta_deg) <= 1e-9) here.points.push_back(m);
        double zmax = 0;
        for (const auto& m : here.points) zmax = std::max(zmax, m.zeta);
        const std::vector<double> zetas = linspace(0.01, std::max(0.5, 1.1 * zmax), 120);
        const double theta = theta_deg * kPi / 180;

        PanelData panel;
        if (angles.size() > 1)
            panel.title = "(" + std::string(1, static_cast<char>('a' + a)) +
                          ") θ = " + format_number("%g", theta_deg) + "°";
        panel.x_title = titles::kZeta;
        panel.y_title = titles::kRx;
        panel.x_min = 0;
        panel.x_max = zetas.back();
        panel.y_min = 0;
        panel.y_max = 1.05;
        SeriesData rigid{"rigid (Eq. " + std::string(theta_deg == 0 ? "10" : (theta_deg == 90 ? "11" : "9")) +
                             ")",
                         zetas,
                         {},
                         Ink::rigid,
                         Dash::dashed,
                         Mark::none,
                         1.8f};
        for (double z : zetas) rigid.y.push_back(rigid_ratio(z, theta).rx);
        panel.series.push_back(std::move(rigid));
        for (const FitCandidate& c : fit.candidates) {
            const auto rows = sweep(Model::dahl, zetas, {theta}, {c.rdisp}, {c.i});
            SeriesData s;
            s.label = "Dahl, i = " + format_number("%g", c.i) +
                      ", fitted r_{disp} = " + format_number("%.3g", c.rdisp) + " ± " +
                      format_number("%.2g", c.rdisp_sigma) + (c.i == fit.best.i ? " (best)" : "");
            s.x = zetas;
            for (const auto& r : rows) s.y.push_back(r.result.rx);
            s.ink = c.i == 0 ? Ink::tip : Ink::body;
            s.dash = c.i == fit.best.i ? Dash::solid : Dash::dotted;
            s.width = c.i == fit.best.i ? 2.4f : 1.8f;
            panel.series.push_back(std::move(s));
        }
        for (SeriesData& s : measured_series(here)) panel.series.push_back(std::move(s));
        fig.panels.push_back(std::move(panel));
    }
    std::string angle_list;
    for (std::size_t a = 0; a < angles.size(); ++a)
        angle_list +=
            (a == 0 ? "" : (a + 1 == angles.size() ? " and " : ", ")) + format_number("%g", angles[a]) + "°";
    fig.title = "Fig. 19: model vs. " +
                std::string(data.synthetic ? "synthetic example data" : "measurements") +
                ", θ = " + angle_list;

    // Table: each measured point with both models and residuals.
    TableData t;
    t.text = "line,theta_deg,zeta,r_x,sigma";
    for (const FitCandidate& c : fit.candidates) {
        const std::string i = format_number("%g", c.i);
        t.text += ",model_i" + i + ",residual_i" + i;
    }
    t.text += "\n";
    for (std::size_t k = 0; k < data.points.size(); ++k) {
        const Measurement& m = data.points[k];
        t.text += std::to_string(m.line) + "," +
                  format_number("%.10g", m.theta_deg.value_or(opt.theta_deg.value_or(std::nan("")))) + "," +
                  format_number("%.10g", m.zeta) + "," + format_number("%.10g", m.rx) + "," +
                  (m.sigma ? format_number("%.10g", *m.sigma) : std::string());
        for (const FitCandidate& c : fit.candidates)
            t.text += "," + format_number("%.10g", c.model[k]) + "," + format_number("%.10g", c.residuals[k]);
        t.text += "\n";
    }
    fig.tables.push_back(std::move(t));
    return fig;
}

} // namespace fv
