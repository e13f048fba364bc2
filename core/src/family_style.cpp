#include "family_style.hpp"

#include "fv/format.hpp"

#include <algorithm>
#include <cmath>

namespace fv::family {
namespace {

// The renderer's palette has 7 entries, the last black: black is the rigid model's.
constexpr int kColours = 6;
constexpr Dash kDashes[] = {Dash::solid, Dash::dashed, Dash::dotted};

enum Dim { theta, rdisp, i, dims };

double value(const Curve& c, int d) {
    return d == theta ? c.theta : d == rdisp ? c.rdisp : c.i;
}

// The distinct values of dimension d over the Dahl curves (or over all curves for theta), in order of
// appearance.
std::vector<double> distinct(const std::vector<Curve>& curves, int d, bool dahl_only) {
    std::vector<double> v;
    for (const Curve& c : curves)
        if ((!dahl_only || c.model == Model::dahl) && std::find(v.begin(), v.end(), value(c, d)) == v.end())
            v.push_back(value(c, d));
    return v;
}

int index_of(const std::vector<double>& values, double v) {
    return static_cast<int>(std::find(values.begin(), values.end(), v) - values.begin());
}

std::string label(const Curve& c, bool vary[dims], bool models_vary, bool dahl_varies) {
    std::vector<std::string> parts;
    if (vary[theta]) parts.push_back("θ = " + format_number("%g", c.theta * 180 / kPi) + "°");
    if (c.model == Model::rigid) {
        if (models_vary || parts.empty()) parts.push_back("rigid");
    } else {
        if (vary[rdisp]) parts.push_back("r_{disp} = " + format_number("%g", c.rdisp));
        if (vary[i]) parts.push_back("i = " + format_number("%g", c.i));
        // "Dahl" only where nothing of its own tells it from the rigid curves.
        if (models_vary && !dahl_varies) parts.push_back("Dahl");
    }
    std::string s;
    for (const std::string& p : parts) s += (s.empty() ? "" : ", ") + p;
    return s;
}

} // namespace

std::vector<SeriesData> curve_styles(const std::vector<Curve>& curves) {
    const bool any_dahl =
        std::any_of(curves.begin(), curves.end(), [](const Curve& c) { return c.model == Model::dahl; });
    const bool any_rigid =
        std::any_of(curves.begin(), curves.end(), [](const Curve& c) { return c.model == Model::rigid; });
    std::vector<double> values[dims];
    bool vary[dims];
    std::vector<int> dahl_dims; // the dimensions that vary over the Dahl curves
    for (int d = 0; d < dims; ++d) {
        values[d] = distinct(curves, d, d != theta);
        vary[d] = values[d].size() > 1;
        if (distinct(curves, d, true).size() > 1) dahl_dims.push_back(d);
    }
    const bool models_vary = any_dahl && any_rigid;
    const bool dahl_varies = vary[rdisp] || vary[i] || (vary[theta] && any_dahl);
    const std::vector<double> thetas = values[theta];

    // Two Dahl dimensions, one of them (theta first) with at most 3 values: colour by the other, dash by it.
    int colour_dim = -1, dash_dim = -1;
    if (dahl_dims.size() == 2) {
        const int a = dahl_dims[0], b = dahl_dims[1];
        auto count = [&](int d) { return distinct(curves, d, true).size(); };
        if (a == theta && count(a) <= 3)
            dash_dim = a, colour_dim = b;
        else if (count(b) <= count(a) && count(b) <= 3)
            dash_dim = b, colour_dim = a;
        else if (count(a) <= 3)
            dash_dim = a, colour_dim = b;
    }

    std::vector<SeriesData> out;
    int dahl_k = 0, rigid_k = 0;
    for (const Curve& c : curves) {
        SeriesData s;
        s.label = label(c, vary, models_vary, dahl_varies);
        if (curves.size() == 1) s.label.clear(); // the title says it all
        if (c.model == Model::dahl) {
            int colour = dahl_k, dash = 0;
            if (colour_dim >= 0) {
                const std::vector<double> cv = distinct(curves, colour_dim, true);
                const std::vector<double> dv = distinct(curves, dash_dim, true);
                colour = index_of(cv, value(c, colour_dim));
                dash = index_of(dv, value(c, dash_dim));
            } else {
                dash = colour / kColours;
                colour %= kColours;
            }
            s.palette = colour % kColours;
            s.dash = kDashes[std::min(dash, 2)];
            ++dahl_k;
        } else {
            const int t = index_of(thetas, c.theta);
            if (!any_dahl) { // Fig. 5: a colour per angle
                s.palette = rigid_k % kColours;
                s.dash = kDashes[std::min(rigid_k / kColours, 2)];
            } else if (dash_dim == theta) {
                s.ink = Ink::rigid;
                s.dash = kDashes[std::min(t, 2)];
            } else if (vary[theta] && dahl_dims.size() == 1) {
                // Theta is the only Dahl dimension: the colour of the Dahl curve at this angle, dashed.
                s.palette = t % kColours;
                s.dash = Dash::dashed;
            } else if (vary[theta]) {
                s.ink = Ink::rigid;
                s.dash = kDashes[std::min(t, 2)];
            } else {
                s.ink = Ink::rigid; // Figs. 10-13
                s.dash = Dash::dashed;
            }
            ++rigid_k;
        }
        out.push_back(std::move(s));
    }
    return out;
}

std::vector<SeriesData> data_series(const MeasurementSet& data, const ZetaSpan& span) {
    const std::string what = data.synthetic ? "synthetic data" : "measured";
    std::vector<double> angles; // NaN: points without an angle
    for (const Measurement& m : data.points) {
        const double t = m.theta_deg.value_or(std::nan(""));
        if (std::none_of(angles.begin(), angles.end(),
                         [&](double a) { return a == t || (std::isnan(a) && std::isnan(t)); }))
            angles.push_back(t);
    }
    constexpr Mark kMarks[] = {Mark::circle, Mark::square, Mark::triangle, Mark::diamond, Mark::cross};
    std::vector<SeriesData> out;
    for (std::size_t a = 0; a < angles.size(); ++a) {
        SeriesData s;
        s.label =
            what +
            (angles.size() > 1 && !std::isnan(angles[a]) ? ", θ = " + format_number("%g", angles[a]) + "°"
                                                         : "") +
            (data.has_sigma ? " (± σ)" : "");
        s.ink = Ink::black;
        s.mark = kMarks[a % 5];
        s.width = 0; // markers only
        for (const Measurement& m : data.points) {
            const double t = m.theta_deg.value_or(std::nan(""));
            if (!(t == angles[a] || (std::isnan(t) && std::isnan(angles[a])))) continue;
            if (m.zeta < span.from || m.zeta > span.to) continue;
            s.x.push_back(m.zeta);
            s.y.push_back(m.rx);
            if (data.has_sigma) s.y_err.push_back(m.sigma.value_or(0));
        }
        if (!s.x.empty()) out.push_back(std::move(s));
    }
    return out;
}

} // namespace fv::family
