// Fig. 19: measured friction ratios against the rigid model and the Dahl model fitted to them, from a data
// file (with the angle of points without one, the vibration's amplitude and frequency, as `fit` takes them).
// Registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"
#include "fv/fit_figure.hpp"
#include "fv/format.hpp"
#include "fv/units.hpp"

namespace fv {
namespace {

// Reads and fits the file when the spec is made: a file that cannot be read or fitted is an error of the
// input (DataError, FitError), before anything is rendered. The vibration (amplitude, frequency; else the
// paper's experiment, 0.7 um at 60 kHz) converts a vb column, puts v_b = zeta v_v in m/s on a top axis and
// z_ss = A/r_disp in um into the caption.
FigureSpec fig19(const FigureInputs& in) {
    ReadOptions ro;
    FitOptions fo;
    ro.amplitude_um = in.amplitude_um;
    ro.frequency_khz = in.frequency_khz;
    if (!in.theta_deg.empty()) fo.theta_deg = in.theta_deg.front();
    const double amplitude = in.amplitude_um.value_or(units::kLittmannAmplitudeUm);
    const double frequency = in.frequency_khz.value_or(units::kLittmannFrequencyKhz);
    fo.amplitude_um = amplitude;
    const MeasurementSet data = read_measurements(in.data, ro);
    auto fit = std::make_shared<FitResult>();
    auto fig = std::make_shared<FigureData>(measurement_figure(data, fo, fit.get()));
    const double vv = units::vibration_velocity(amplitude, frequency);
    const std::string a_text = format_number("%g", amplitude), f_text = format_number("%g", frequency);
    const bool paper_vibration = !in.amplitude_um || !in.frequency_khz;
    for (PanelData& p : fig->panels) {
        p.top_scale = vv;
        p.top_title = "v_{b} [m/s] at A = " + a_text + " µm, f = " + f_text + " kHz";
    }
    FigureSpec f;
    f.id = "fig19";
    f.title = fig->title;
    const FitCandidate& b = fit->best;
    const std::string what =
        data.synthetic ? "synthetic example data (made from the model, not measurements)" : "measurements";
    f.caption =
        "Model vs. " + what + ": the " + std::to_string(data.points.size()) + " points of " + in.data +
        " with the rigid model and the Dahl model with i = 0 and i = 1, each at the one r_disp fitted to "
        "all points of all panels; the best fit is i = " +
        format_number("%g", b.i) + ", r_disp = " + format_number("%.3g", b.rdisp) + " ± " +
        format_number("%.2g", b.rdisp_sigma) +
        (b.zss_um ? " (z_ss = A/r_disp = " + format_number("%.3g", *b.zss_um) + " µm)" : "") +
        ". The top axis is v_b = ζ v_v with v_v = 2π f A = " + format_number("%.4g", vv) + " m/s.";
    MeasurementsFigure m;
    m.parameters =
        "rigid model (Eqs. 9–11, quadrature) and Dahl model with i = 0 and i = 1 at each panel's θ, "
        "r_disp fitted by least squares in ln r_disp over [0.1, 100] (" +
        std::string(b.weighted ? "weights 1/σ²" : "unweighted") +
        "), model curves at 120 evenly spaced ζ from the continuous-time solver (tolerance 1e-8)" +
        (!in.theta_deg.empty()
             ? "; θ = " + format_number("%g", in.theta_deg.front()) + "° for points without one"
             : "") +
        "; vibration A = " + a_text + " µm, f = " + f_text + " kHz" +
        (paper_vibration
             ? " (where --amplitude or --frequency is not given: the paper's experiment, Littmann "
               "et al., 0.7 µm at 60 kHz)"
             : "");
    m.precomputed = std::move(fig);
    m.fit = std::move(fit);
    f.content = std::move(m);
    return f;
}

FigureEntry fig19_entry() {
    FigureEntry e;
    e.id = "fig19";
    e.title = "model vs. measured r_x(ζ), r_disp fitted for i = 0 and i = 1";
    e.kind = FigureKind::measurements;
    e.params = {
        {FigureParam::data, true}, {FigureParam::theta}, {FigureParam::amplitude}, {FigureParam::frequency}};
    // No example data file (core names no path in the source tree): `render --figure all` draws fig19 only
    // when a file is given.
    e.example.amplitude_um = 0.7;
    e.make = fig19;
    e.summary =
        "Model vs. measurements: one r_disp fitted for i = 0 and one for i = 1 to all points, one panel per "
        "vibration angle (up to 4, in the file's order, like the paper's (a) θ = 90°, (b) θ = 0°): the "
        "points with ±σ error bars over the rigid curve and both fitted Dahl curves; its table lists each "
        "point with its angle, both models and residuals. The top axis is v_b in m/s for the vibration's "
        "amplitude and frequency (default: the paper's experiment, 0.7 µm at 60 kHz).";
    return e;
}

const RegisterFigure register_fig19{fig19_entry()};

} // namespace
} // namespace fv
