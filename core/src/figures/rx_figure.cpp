// r_x(zeta) for a family of your own (beyond the paper's Figs. 5, 10-13): one curve per combination of lists
// of theta, r_disp, i and models over a range of zeta, measured points over them (figure_family.hpp).
// Registers itself (figure_registry.hpp).
#include "fv/figure_family.hpp"
#include "fv/figure_registry.hpp"
#include "fv/measurements.hpp"

#include <memory>

namespace fv {
namespace {

FigureEntry rx_entry() {
    FigureEntry e;
    e.id = "rx";
    e.title = "friction ratio r_x(ζ), one curve per combination of θ, r_disp, i and model, beyond the paper";
    e.kind = FigureKind::ratio_curves;
    e.params = {
        {FigureParam::theta, false, true}, {FigureParam::rdisp, false, true}, {FigureParam::i, false, true},
        {FigureParam::model, false, true}, {FigureParam::zeta_range},         {FigureParam::data},
        {FigureParam::amplitude},          {FigureParam::frequency},          {FigureParam::start}};
    // The example family: one angle, three compliances, one exponent, and the rigid limit.
    e.defaults.theta_deg = {45};
    e.defaults.rdisp = {1, 3, 10};
    e.defaults.i = {0.5};
    e.defaults.models = {Model::dahl, Model::rigid};
    e.defaults.zeta_span = kPaperZetaSpan;
    e.defaults.start = Start::rest;
    e.check = family_check;
    // The data file is read when the spec is made: a file that cannot be read is an error of the input
    // (DataError), before anything is computed. A vb column needs --amplitude and --frequency.
    e.make = [](const FigureInputs& in) {
        std::shared_ptr<const MeasurementSet> data;
        if (!in.data.empty()) {
            ReadOptions ro;
            ro.amplitude_um = in.amplitude_um;
            ro.frequency_khz = in.frequency_khz;
            data = std::make_shared<const MeasurementSet>(read_measurements(in.data, ro));
        }
        return family_figure("rx", family_of(in, false), std::move(data));
    };
    e.summary =
        "Beyond the paper: r_x(ζ) for a family of your own, one curve per combination of lists of θ, r_disp, "
        "i and model (the rigid model ignores r_disp and i: one rigid curve per θ), at most 12 curves, over "
        "a "
        "range of ζ (logarithmic from two decades on); the legend names only what varies, the title what "
        "does not; measured points (a file as fit and fig19 read it) drawn over the curves. Shown: θ = 45°, "
        "r_disp = 1, 3, 10, i = 0.5 and the rigid curve.";
    return e;
}

const RegisterFigure register_rx{rx_entry()};

} // namespace
} // namespace fv
