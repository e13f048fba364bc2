// Fig. 19: measured friction ratios against the rigid model and the Dahl model fitted to them, from --data
// (with --theta, --amplitude, --frequency as `fit` takes them). Registers itself (figure_registry.hpp).
#include "fv/figure_registry.hpp"
#include "fv/fit_figure.hpp"
#include "fv/format.hpp"

namespace fv {
namespace {

// Reads and fits the file when the spec is made: a file that cannot be read or fitted is an error of the
// input (DataError, FitError), before anything is rendered.
FigureSpec fig19(const FigureInputs& in) {
    ReadOptions ro;
    FitOptions fo;
    ro.amplitude_um = fo.amplitude_um = in.amplitude_um;
    ro.frequency_khz = in.frequency_khz;
    fo.theta_deg = in.theta_deg;
    const MeasurementSet data = read_measurements(in.data, ro);
    auto fit = std::make_shared<FitResult>();
    auto fig = std::make_shared<FigureData>(measurement_figure(data, fo, fit.get()));
    FigureSpec f;
    f.id = "fig19";
    f.kind = FigureKind::measurements;
    f.title = fig->title;
    const FitCandidate& b = fit->best;
    f.caption = "Model vs. measurements: the " + std::to_string(data.points.size()) + " points of " +
                in.data +
                " with the rigid model and the Dahl model with i = 0 and i = 1, each at the r_disp fitted to "
                "all points; the best fit is i = " +
                format_number("%g", b.i) + ", r_disp = " + format_number("%.3g", b.rdisp) + " ± " +
                format_number("%.2g", b.rdisp_sigma) + ".";
    f.parameters =
        "rigid model (Eqs. 9–11, quadrature) and Dahl model with i = 0 and i = 1 at each panel's θ, "
        "r_disp fitted by least squares in ln r_disp over [0.1, 100] (" +
        std::string(b.weighted ? "weights 1/σ²" : "unweighted") +
        "), model curves at 120 evenly spaced ζ from the continuous-time solver (tolerance 1e-8)" +
        (in.theta_deg ? "; θ = " + format_number("%g", *in.theta_deg) + "° for points without one" : "") +
        (in.amplitude_um ? "; A = " + format_number("%g", *in.amplitude_um) + " µm" : "") +
        (in.frequency_khz ? ", f = " + format_number("%g", *in.frequency_khz) + " kHz" : "");
    f.precomputed = std::move(fig);
    f.fit = std::move(fit);
    return f;
}

FigureEntry fig19_entry() {
    FigureEntry e;
    e.id = "fig19";
    e.title = "model vs. measured r_x(ζ), r_disp fitted for i = 0 and i = 1 (needs --data)";
    e.kind = FigureKind::measurements;
    e.flags = {
        {"--data", "", true}, {"--theta", "", false}, {"--amplitude", "", false}, {"--frequency", "", false}};
    e.example.data = "tests/data/synthetic_two_angles_rdisp2_i0.csv";
    e.example.amplitude_um = 0.7;
    e.all_needs_flags = true;
    e.make = fig19;
    e.summary =
        "Model vs. measurements: `render --figure fig19 --data FILE [--theta DEG] [--amplitude UM "
        "--frequency "
        "KHZ]` fits one r_disp for i = 0 and one for i = 1 to all points and draws one panel per vibration "
        "angle "
        "(up to 4, in the file's order, like the paper's (a) θ = 90°, (b) θ = 0°): the points with ±σ error "
        "bars "
        "over the rigid curve and both fitted Dahl curves; `fig19.csv` lists each point with its angle, both "
        "models and residuals. Shown here for the **synthetic** example "
        "`tests/data/synthetic_two_angles_rdisp2_i0.csv` (made from the model with r_disp = 2, i = 0 at both "
        "angles plus noise σ = 0.008): the fit gives r_disp = 1.97 ± 0.016 and picks i = 0.";
    return e;
}

const RegisterFigure register_fig19{fig19_entry()};

} // namespace
} // namespace fv
