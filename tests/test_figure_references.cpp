// The numbers of figures fig4, fig6, fig14, ry and fig19 against references that do not come from the code
// that drew them: the paper's closed forms (Eqs. 3, 10, 11, 28-29), the closed form of the Dahl law along a
// monotone path (docs/model.md, "The Dahl law along a monotone path"), an independent quadrature and limits.
#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/fit.hpp"
#include "fv/fit_figure.hpp"
#include "fv/measurements.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

fv::FigureData figure(const std::string& id, const fv::FigureInputs& in = {}) {
    const fv::FigureEntry* e = fv::find_registered(id);
    REQUIRE(e);
    return fv::compute_figure(e->make(in));
}

const fv::SeriesData& series_named(const fv::PanelData& p, const std::string& prefix) {
    for (const fv::SeriesData& s : p.series)
        if (s.label.rfind(prefix, 0) == 0) return s;
    FAIL("no series " << prefix);
    return p.series.front();
}

// Eq. (11) with the standard library's K(k), k = 1/sqrt(1 + zeta^2) (the core uses an AGM of its own).
double eq11(double zeta) {
    const double k = 1 / std::sqrt(1 + zeta * zeta);
    return 2 / kPi * zeta / std::sqrt(1 + zeta * zeta) * std::comp_ellint_1(k);
}

// Eq. (4)'s mean by Gauss-Chebyshev quadrature in u = cos(tau) (the core integrates in tau by Gauss-Kronrod):
// the mean over a period of g(cos tau) is exactly the mean of g over the Chebyshev nodes for polynomials,
// and converges geometrically for the smooth integrand (|v| > 0 when zeta sin(theta) > 0).
double rigid_ry_chebyshev(double zeta, double theta) {
    const int n = 4000;
    double sum = 0;
    for (int k = 1; k <= n; ++k) {
        const double u = std::cos((2 * k - 1) * kPi / (2 * n));
        sum += std::sin(theta) * u / std::hypot(zeta + std::cos(theta) * u, std::sin(theta) * u);
    }
    return sum / n;
}

// The Dahl law du/ds = (1 - sgn(ds) u)^i (u = F/F_c, s = x/z_ss) on a monotone leg of length d from u0, in
// closed form: w = 1 - sgn(ds) u obeys dw/d|s| = -w^i.
double dahl_leg(double u0, double direction, double d, double i) {
    const double w0 = 1 - direction * u0;
    double w;
    if (i == 0)
        w = std::max(0.0, w0 - d); // Eq. (25): stick, then slip at F_c
    else if (i == 1)
        w = w0 * std::exp(-d);
    else if (i < 1)
        w = std::pow(std::max(0.0, std::pow(w0, 1 - i) - (1 - i) * d), 1 / (1 - i));
    else
        w = std::pow(std::pow(w0, 1 - i) + (i - 1) * d, -1 / (i - 1));
    return direction * (1 - w);
}

} // namespace

TEST_CASE("fig4: the friction against v_b is Eq. (3), its mean Eq. (11) or Eq. (10), F is opposite to v",
          "[figures][references]") {
    for (const auto& [zeta, theta_deg] :
         {std::pair{0.5, 90.0}, {0.3, 90.0}, {0.5, 0.0}, {0.8, 0.0}, {0.5, 45.0}}) {
        CAPTURE(zeta, theta_deg);
        fv::FigureInputs in;
        in.zeta = zeta;
        in.theta_deg = {theta_deg};
        const fv::FigureData d = figure("fig4", in);
        REQUIRE(d.panels.size() == 2);
        const double th = theta_deg * kPi / 180;
        // Right: -F_x/F_c at every sample is Eq. (3) (the friction on the body, over -mu F_N).
        const fv::SeriesData& fx = series_named(d.panels[1], "−F_{x}");
        int checked = 0;
        for (std::size_t k = 0; k < fx.x.size(); ++k) {
            if (!std::isfinite(fx.x[k])) continue; // a break at a reversal (theta = 0)
            const double c = std::cos(fx.x[k]);
            const double eq3 =
                (zeta + std::cos(th) * c) / std::sqrt(zeta * zeta + 2 * zeta * std::cos(th) * c + c * c);
            REQUIRE(fx.y[k] == Approx(eq3).margin(1e-12));
            ++checked;
        }
        CHECK(checked >= 1025);
        // The marked mean: Eq. (11) at 90 deg, Eq. (10) at 0 deg.
        const fv::SeriesData& mean = series_named(d.panels[1], "mean r_{x}");
        if (theta_deg == 90) CHECK(mean.y[0] == Approx(eq11(zeta)).margin(1e-12));
        if (theta_deg == 0) CHECK(mean.y[0] == Approx(2 / kPi * std::asin(zeta)).margin(1e-12));
        // ... and it is the mean of the curve drawn (rectangle rule on the periodic samples; at 0 deg the
        // integrand jumps twice, so only to the sample spacing).
        double sum = 0;
        int n = 0;
        for (std::size_t k = 0; k + 1 < fx.x.size(); ++k)
            if (std::isfinite(fx.x[k])) sum += fx.y[k], ++n;
        CHECK(sum / n == Approx(mean.y[0]).margin(theta_deg == 0 ? 4e-3 : 1e-10));
        const auto& arrows = d.panels[0].arrows;
        if (fv::mechanism_parallel(th)) {
            // Along the sliding line the left panel is nine rows up a time axis, tau = k pi/4: v's component
            // along v_b (Eq. 1 over v_v) above each row, the friction's, -sgn v_x (Eq. 2), below it; the mean
            // friction is the dashed line at -r_x.
            REQUIRE(arrows.size() == 18);
            for (std::size_t k = 0; k < 9; ++k) {
                const fv::ArrowData &v = arrows[2 * k], &f = arrows[2 * k + 1];
                const double tau = kPi * static_cast<double>(k) / 4, vx = zeta + std::cos(th) * std::cos(tau);
                CHECK(v.to.x() - v.from.x() == Approx(vx).margin(1e-12));
                CHECK(v.from.y() > tau);
                CHECK(v.to.y() == v.from.y());
                CHECK(f.from.y() < tau);
                if (std::abs(vx) > 1e-12)
                    CHECK(f.to.x() - f.from.x() == Approx(vx > 0 ? -1 : 1).margin(1e-12));
            }
            CHECK(-series_named(d.panels[0], "mean friction").x[0] == Approx(mean.y[0]).margin(1e-12));
            continue;
        }
        // Left: each friction arrow has length 1 and points against the velocity arrow before it (Eq. 2).
        REQUIRE(arrows.size() == 11);
        for (std::size_t k = 0; k + 1 < arrows.size(); k += 2) {
            const fv::Vec2 v = arrows[k].to, f = arrows[k + 1].to;
            const double tau = kPi * static_cast<double>(k / 2) / 4;
            CHECK(v.x() == Approx(zeta + std::cos(th) * std::cos(tau)).margin(1e-12)); // Eq. (1) over v_v
            CHECK(v.y() == Approx(std::sin(th) * std::cos(tau)).margin(1e-12));
            if (v.norm() < 1e-12) continue;
            CHECK(f.norm() == Approx(1).margin(1e-12));
            CHECK(f.dot(v) / v.norm() == Approx(-1).margin(1e-12));
        }
        // The mean friction arrow is -(r_x, r_y): its x part is the marked mean.
        CHECK(-arrows.back().to.x() == Approx(mean.y[0]).margin(1e-12));
    }
}

TEST_CASE("fig6: every curve follows the closed form of the Dahl law along each monotone leg",
          "[figures][references]") {
    const fv::FigureData d = figure("fig6");
    REQUIRE(d.tables.size() == 1);
    std::istringstream in(d.tables[0].text);
    std::string line;
    std::getline(in, line);
    REQUIRE(line == "i,leg,x_over_zss,F_over_Fc");
    // The reference walks the cycle 0 -> 3 -> -3 -> 3 in closed form, leg by leg, from F = 0.
    double worst = 0;
    int rows = 0;
    std::vector<double> exponents;
    double leg_u0 = 0, leg_x0 = 0, last_i = -1;
    int last_leg = 0;
    while (std::getline(in, line)) {
        double i = 0, x = 0, u = 0;
        int leg = 0;
        REQUIRE(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf", &i, &leg, &x, &u) == 4);
        if (i != last_i) { // a new curve, from rest
            exponents.push_back(i);
            leg_u0 = 0, leg_x0 = 0, last_leg = 1;
        } else if (leg != last_leg) { // a reversal: the leg before ends at +-3
            const double dir = last_leg == 2 ? -1.0 : 1.0;
            leg_u0 = dahl_leg(leg_u0, dir, std::abs(dir * 3 - leg_x0), i);
            leg_x0 = dir * 3;
            last_leg = leg;
        }
        last_i = i;
        const double dir = leg == 2 ? -1.0 : 1.0;
        const double ref = dahl_leg(leg_u0, dir, std::abs(x - leg_x0), i);
        worst = std::max(worst, std::abs(u - ref));
        CAPTURE(i, leg, x);
        REQUIRE(std::abs(u - ref) < 2e-4); // the bound the caption states
        ++rows;
    }
    CHECK(exponents == std::vector<double>{0, 0.5, 1, 2});
    CHECK(rows == 4 * 1501);
    WARN("fig6: largest difference from the closed form " << worst << " F_c");
    // Panel (a): the paper's Fig. 6, loading from rest: i = 0 reaches F_c at x = z_ss, i = 0.5 at 2 z_ss, i =
    // 1 is 1 - e^-x, i = 2 is x/(1 + x) (docs/model.md).
    const fv::PanelData& a = d.panels.at(0);
    REQUIRE(a.series.size() == 4);
    for (std::size_t k = 0; k < a.series[0].x.size(); ++k) {
        const double x = a.series[0].x[k];
        CHECK(a.series[0].y[k] == Approx(std::min(x, 1.0)).margin(2e-4));
        CHECK(a.series[1].y[k] == Approx(x < 2 ? x - x * x / 4 : 1.0).margin(2e-4));
        CHECK(a.series[2].y[k] == Approx(1 - std::exp(-x)).margin(2e-4));
        CHECK(a.series[3].y[k] == Approx(x / (1 + x)).margin(2e-4));
    }
}

TEST_CASE("ry: rigid r_y is the mean of Eq. (4), the Dahl r_y tends to it as r_disp grows",
          "[figures][references]") {
    const fv::FigureData d = figure("ry");
    const fv::PanelData& p = d.panels.at(0);
    REQUIRE(p.series.size() == 6);
    const double thetas[] = {30, 45, 60};
    for (int k = 0; k < 3; ++k) {
        const fv::SeriesData& rigid = p.series[static_cast<std::size_t>(3 + k)];
        CHECK(rigid.label.find("rigid") != std::string::npos);
        CHECK(p.series[static_cast<std::size_t>(k)].palette == rigid.palette); // one colour per angle
        const double th = thetas[k] * kPi / 180;
        for (std::size_t j = 0; j < rigid.x.size(); ++j)
            REQUIRE(rigid.y[j] == Approx(rigid_ry_chebyshev(rigid.x[j], th)).margin(1e-10));
        // Large zeta: r_y = -sin(2 theta)/(4 zeta^2) (1 + O(zeta^-2)).
        const double z = rigid.x.back(), lead = -std::sin(2 * th) / (4 * z * z);
        CHECK(rigid.y.back() == Approx(lead).epsilon(0.1));
    }
    // Rigid limit of the Dahl model: at r_disp = 1000 within O(1/r_disp^2) of the rigid curve (for ζ away
    // from the rigid model's non-smooth points the error is ~1/r^2; allow 1e-3).
    fv::FigureInputs stiff;
    stiff.rdisp = {1000};
    stiff.i = {1};
    fv::FigureSpec spec = fv::find_registered("ry")->make(stiff);
    auto& curves = std::get<fv::RatioCurvesFigure>(spec.content);
    curves.zetas = {0.3, 0.6, 1.2, 2.0};
    curves.zeta_budget = 0; // exactly these samples, no adaptive refinement
    const fv::FigureData s = fv::compute_figure(spec);
    for (int k = 0; k < 3; ++k)
        for (std::size_t j = 0; j < curves.zetas.size(); ++j) {
            const double th = thetas[k] * kPi / 180;
            CAPTURE(thetas[k], curves.zetas[j]);
            CHECK(s.panels[0].series[static_cast<std::size_t>(k)].y[j] ==
                  Approx(rigid_ry_chebyshev(curves.zetas[j], th)).margin(1e-3));
        }
}

TEST_CASE("fig14: panels (a) i = 1 and (b) i = 0 on shared axes, P follows Eqs. (28)-(29), the i = 0 tip "
          "moves only at z = z_ss",
          "[figures][references]") {
    const fv::FigureData d = figure("fig14");
    REQUIRE(d.panels.size() == 2);
    const fv::PanelData &a = d.panels[0], &b = d.panels[1];
    CHECK(a.title.rfind("(a) i = 1", 0) == 0);
    CHECK(b.title.rfind("(b) i = 0", 0) == 0);
    CHECK((*a.x_min == *b.x_min && *a.x_max == *b.x_max && *a.y_min == *b.y_min && *a.y_max == *b.y_max));
    REQUIRE(d.tables.size() == 2);
    for (const fv::TableData& t : d.tables) {
        CHECK(fv::ok(t.status));
        for (const fv::Sample& s : t.trace) {
            // Eqs. (28)-(29) in units of x_v: zeta = 0.15, theta = 90 deg.
            CHECK(s.P.x() == Approx(0.15 * s.tau).margin(1e-9));
            CHECK(s.P.y() == Approx(std::sin(s.tau)).margin(1e-12));
            CHECK(s.z <= 0.5 + 1e-9); // z_ss = 1/r_disp
            // Inside the panel's frame.
            CHECK((s.T.y() >= *a.y_min && s.T.y() <= *a.y_max && s.P.y() >= *a.y_min && s.P.y() <= *a.y_max));
        }
    }
    // (b) i = 0, Eq. (25): below z_ss the tip sticks (T does not move between two samples below z_ss).
    const auto& tb = d.tables[1].trace;
    int stuck = 0;
    for (std::size_t k = 1; k < tb.size(); ++k)
        if (tb[k].z < 0.5 - 1e-6 && tb[k - 1].z < 0.5 - 1e-6) {
            CHECK((tb[k].T - tb[k - 1].T).norm() < 1e-9);
            ++stuck;
        }
    CHECK(stuck > 100);
    // The aliases are the panels alone, on the same axes.
    const fv::FigureData fa = figure("fig14a"), fb = figure("fig14b");
    REQUIRE(fa.panels.size() == 1);
    CHECK(*fa.panels[0].x_min == *a.x_min);
    CHECK(*fb.panels[0].y_max == *b.y_max);
    CHECK(fb.tables.at(0).trace.size() == tb.size());
}

TEST_CASE("fig19: synthetic data are labelled so, the top axis is v_b = zeta 2 pi f A for --amplitude, "
          "--frequency",
          "[figures][references][long]") {
    fv::FigureInputs in;
    in.data = std::string(FV_TEST_DATA_DIR) + "/synthetic_two_angles_rdisp2_i0.csv";
    in.amplitude_um = 1.4;
    in.frequency_khz = 30;
    const fv::FigureSpec spec = fv::find_registered("fig19")->make(in);
    CHECK(spec.title.find("synthetic example data") != std::string::npos);
    CHECK(spec.caption.find("synthetic example data") != std::string::npos);
    const fv::FigureData d = fv::compute_figure(spec);
    for (const fv::PanelData& p : d.panels) {
        CHECK(p.top_scale == Approx(2 * kPi * 30e3 * 1.4e-6).epsilon(1e-12)); // m/s per unit zeta
        CHECK(p.top_title.find("A = 1.4 µm, f = 30 kHz") != std::string::npos);
        CHECK(p.series.back().label.rfind("synthetic example data", 0) == 0);
    }
    // z_ss = A / r_disp in the caption (the fit's r_disp does not depend on A for a zeta column).
    const double zss = 1.4 / std::get<fv::MeasurementsFigure>(spec.content).fit->best.rdisp;
    char text[32];
    std::snprintf(text, sizeof text, "z_ss = A/r_disp = %.3g µm", zss);
    CHECK(spec.caption.find(text) != std::string::npos);
    // Without the flags: the paper's experiment, 0.7 um at 60 kHz.
    in.amplitude_um.reset();
    in.frequency_khz.reset();
    const fv::FigureData d0 = fv::compute_figure(fv::find_registered("fig19")->make(in));
    CHECK(d0.panels.at(0).top_scale == Approx(2 * kPi * 60e3 * 0.7e-6).epsilon(1e-12));
}

TEST_CASE("Measured data are called measured unless a comment of the file says synthetic", "[figures]") {
    const fv::MeasurementSet own = fv::parse_measurements("zeta,r_x\n0.1,0.2\n0.3,0.5\n", "own.csv");
    const fv::MeasurementSet made =
        fv::parse_measurements("# Synthetic test points\nzeta,r_x\n0.1,0.2\n", "made.csv");
    CHECK_FALSE(own.synthetic);
    CHECK(made.synthetic);
    CHECK(fv::measured_series(own).at(0).label == "measured");
    CHECK(fv::measured_series(made).at(0).label == "synthetic example data");
}
