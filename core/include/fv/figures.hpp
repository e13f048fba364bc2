// A figure defined as data: the CLI renders it, the app loads it as a preset, the tests check it. Each figure
// is registered once (figure_registry.hpp, core/src/figures/). Nothing here draws; figure_data.hpp turns a
// spec into numbers.
#pragma once

#include "fv/params.hpp"
#include "fv/steady_state.hpp"

#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace fv {

struct FigureData;
struct FitResult;
struct MeasurementSet;

// A range of zeta: curves over [from, to], from < to (figure_family.hpp reads and checks it).
struct ZetaSpan {
    double from = 0, to = 3;
    bool operator==(const ZetaSpan& o) const { return from == o.from && to == o.to; }
};

// The order of FigureContent's alternatives (a spec's kind is the index of its content).
enum class FigureKind {
    ratio_curves, // r_x(zeta) (or r_y(zeta): side_force) for a family of models/parameters (Figs. 5, 10-13,
                  // ry)
    mechanism,    // the rigid model over one period: velocity and Coulomb friction turning, F_x(tau) (Fig. 4)
    dahl_curves,  // friction-displacement curves of the Dahl law, Eq. (12), for several i (Fig. 6)
    step_view,    // one step of the tracking scheme, top view (Fig. 8)
    period_view,  // P and T over one steady-state period, top view (Figs. 9, 14, 17)
    period_force, // F_x, F_y, |F| over one steady-state period (Figs. 15, 16, 18)
    scene,        // top view + force + ratio curve of one parameter set (any parameters)
    map,          // r_x over a (zeta, theta) grid with the best angle theta*(zeta) (beyond the paper)
    measurements, // measured r_x against the fitted models (Fig. 19): computed when the spec is made
};

// One r_x(zeta) curve.
struct Curve {
    Model model = Model::dahl;
    double theta = 0; // radians
    double rdisp = 0; // Dahl only
    double i = 1;     // Dahl only
};

inline constexpr double kMapTolerance = 1e-6;

// What defines a figure of each kind, beside its id, title and caption (FigureSpec). The order is that of
// FigureKind: a spec's kind is the index of its alternative.

// The curves and the zeta values they are computed at; with a zeta_budget, the start grid of each curve's
// adaptive sampling (adaptive_sampling.hpp), up to zeta_budget samples a curve.
struct RatioCurvesFigure {
    std::vector<Curve> curves;
    std::vector<double> zetas;
    std::size_t zeta_budget = 0;
    bool side_force = false; // plot r_y, the mean force across v_b, instead of r_x
    // A family (figure_family.hpp: rx, ry with lists): each curve's colour and dash by what varies, the
    // legend naming only that; its zeta axis spans `axis` (else from min(0, first zeta) to the last), on a
    // log scale with log_zeta (sampled evenly in log zeta then).
    bool family = false;
    std::optional<ZetaSpan> axis;
    bool log_zeta = false;
    Start start = Start::rest;                  // the history where steady states coexist
    std::shared_ptr<const MeasurementSet> data; // measured r_x drawn over the curves (rx --data)
};

// The rigid model at one velocity ratio and angle (r_disp and i do not apply).
struct MechanismFigure {
    double zeta = 0;
    double theta = 0; // radians
};

// One curve per exponent i.
struct DahlCurvesFigure {
    std::vector<double> exponents;
};

// The figures of one steady period of `params` take it from the paper's scheme at steps_per_period steps a
// period, or at 0 from the continuous-time solver (1024 samples).

// One step of the scheme, top view.
struct StepViewFigure {
    Params params;
    int steps_per_period = 0; // Fig. 8 uses a coarse step to be visible
};

// P and T over the period, top view.
struct PeriodViewFigure {
    Params params;
    int steps_per_period = 0;
    bool overlay_other_i = false; // Fig. 17: draw i = 0 over i = 1 to show that they coincide
    // One panel per exponent, side by side on shared axes (Fig. 14: (a) i = 1, (b) i = 0); empty: one panel
    // at params.i. only_panel >= 0 draws that panel alone, on the same axes (fig14a, fig14b).
    std::vector<double> panel_i;
    int only_panel = -1;
};

// The friction force over the period.
struct PeriodForceFigure {
    Params params;
    int steps_per_period = 0;
};

// Top view and force over one steady period of `params`, and its r_x(zeta) curves. `start`: the history
// that decides between coexisting steady states (SteadyOptions::start); every other figure but the map is
// the paper's, from rest.
struct SceneFigure {
    Params params;
    Start start = Start::rest;
    RatioCurvesFigure ratio;
};

// One map of a family of maps (map_family.hpp): its model, r_disp and i (NaN for the rigid model, which
// has neither) and its panel's title, naming only what varies across the family.
struct MapPanelSpec {
    Model model = Model::dahl;
    double rdisp = 2, i = 1;
    std::string title;
};

// r_x over zetas x theta from 0 to theta_max_deg in theta_count steps, for one r_disp and i (the Dahl
// model), or of the rigid model (Eq. 9; r_disp and i do not apply).
struct MapFigure {
    Model model = Model::dahl;
    double rdisp = 2;
    double i = 1;
    std::vector<double> zetas;
    int theta_count = 91;
    double theta_max_deg = 90;
    // The Dahl solver's target |r - r(dtau -> 0)| (SteadyOptions::ode_tolerance); 0: the default. The map
    // uses kMapTolerance: a colour map needs no more, and it is the 1e-6 (ratio --tolerance 1e-6
    // gives every cell).
    double ode_tolerance = 0;
    Start start = Start::rest; // as in SceneFigure
    // A family (render --figure map --rdisp 1,3,10 --i 0.5,1): one map per entry on the same grid (the
    // fields above but model, rdisp and i), as small multiples on `columns` columns with one colour scale
    // and one legend; empty: the one map of model, rdisp and i.
    std::vector<MapPanelSpec> family;
    int columns = 0;
};

// The figure, computed (data read and fitted) when the spec was made, the fit behind it, and the sentence
// naming its parameters (figure_parameters).
struct MeasurementsFigure {
    std::shared_ptr<const FigureData> precomputed;
    std::shared_ptr<const FitResult> fit;
    std::string parameters;
};

using FigureContent =
    std::variant<RatioCurvesFigure, MechanismFigure, DahlCurvesFigure, StepViewFigure, PeriodViewFigure,
                 PeriodForceFigure, SceneFigure, MapFigure, MeasurementsFigure>;

struct FigureSpec {
    std::string id;    // "fig10"
    std::string title; // drawn above the figure (markup: r_{disp}); names the parameters that distinguish it
    std::string caption; // what it shows, in sentences (ID.json, the README table)
    FigureContent content;

    FigureKind kind() const { return static_cast<FigureKind>(content.index()); }
};

// The fixed figures of the registry (those that take no parameters: the paper's, fig5..fig18), in its order.
const std::vector<FigureSpec>& paper_figures();

// A fixed figure; nullptr if unknown.
const FigureSpec* find_figure(const std::string& id);

// zeta grid of the r_x(zeta) figures: 0.02 apart up to 0.5 (where compliant curves turn sharply), 0.025 up
// to 1 (which is on the grid: the rigid curve has its corner there at theta = 0), then 0.1 up to 3; past 3
// up to zeta_max (when larger) in at most 40 steps.
std::vector<double> ratio_zeta_grid(double zeta_max = 3);

// Start grid of the adaptively sampled r_x(zeta) figures: 0.02, then 0.05 apart up to 1 (on the grid: the
// rigid curve's corner at theta = 0), then 0.25 apart up to zeta_max; and their sample budget per curve.
std::vector<double> ratio_zeta_start(double zeta_max = 3);
inline constexpr std::size_t kRatioZetaBudget = 160;

// The (zeta, theta) map of r_x for one r_disp and i: 200 zeta in [0.02, 3] x 91 theta in [0, 90 deg].
FigureSpec map_figure(double rdisp, double i, Start start = Start::rest);

// "ζ = 0.15, θ = 90°, r_{disp} = 2, i = 1" (title markup).
std::string params_title(const Params& p);

// The dashboard of one parameter set: top view, force over a period, r_x(zeta) with the rigid curve.
FigureSpec scene_figure(const Params& p, Start start = Start::rest);

// The sign convention of every force plot (Figs. 15, 16, 18, the scene), named in their captions; their
// y axis reads "F / F_c = (P − T) / z_ss".
inline constexpr const char* kForceConvention =
    " F = (P − T) F_c / z_ss (Eqs. 23–24), the spring's pull on the asperity tip T, towards the body "
    "point P: positive along v_b, so the friction on the body is −F and r_x is the mean of F_x / F_c.";

} // namespace fv
