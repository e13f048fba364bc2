// frictionviz._core's figures: the registry's ids and titles, and one figure rendered headless (OSMesa, as
// `frictionviz render`) to PNG, SVG or PDF bytes. Kept thin on purpose: it reads only FigureEntry's id,
// title, params and make(), and FigureInputs, so that the registry's inner shapes (FigureSpec) may change.
#include "render.hpp"

#include "figures/figure_renderer.hpp"

#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/fit.hpp"
#include "fv/measurements.hpp"
#include "fv/param_ranges.hpp"
#include "fv/read_number.hpp"

#include <pybind11/stl.h>

#include <memory>
#include <mutex>
#include <string>

namespace py = pybind11;

namespace fvpy {
namespace {

void check(const std::string& why) {
    if (!why.empty()) throw py::value_error(why);
}

// The Python keyword of each figure parameter (the command line's flag without "--", with the unit where the
// flag has one in its help: theta_deg, amplitude_um, frequency_khz).
struct Keyword {
    fv::FigureParam param;
    const char* name;
};
constexpr Keyword kKeywords[] = {
    {fv::FigureParam::zeta, "zeta"},
    {fv::FigureParam::theta, "theta_deg"},
    {fv::FigureParam::rdisp, "rdisp"},
    {fv::FigureParam::i, "i"},
    {fv::FigureParam::data, "data"},
    {fv::FigureParam::amplitude, "amplitude_um"},
    {fv::FigureParam::frequency, "frequency_khz"},
    {fv::FigureParam::start, "start"},
};

std::string keyword_of(fv::FigureParam p) {
    for (const Keyword& k : kKeywords)
        if (k.param == p) return k.name;
    return "";
}

std::string keywords_of(const fv::FigureEntry& e) {
    std::string s;
    for (const fv::FigureParamUse& u : e.params) s += (s.empty() ? "" : ", ") + keyword_of(u.param);
    return s.empty() ? "none" : s;
}

double number(const char* name, const py::handle& v, fv::ParamRange r) {
    const double x = v.cast<double>();
    check(fv::range_message(name, x, r));
    return x;
}

} // namespace

py::list figures() {
    py::list out;
    for (const fv::FigureEntry& e : fv::figure_registry()) {
        py::list params;
        for (const fv::FigureParamUse& u : e.params) params.append(keyword_of(u.param));
        out.append(py::make_tuple(e.id, e.title, params));
    }
    return out;
}

py::bytes render(const std::string& id, const py::dict& params, int width, int height, double scale,
                 const std::string& format) {
    const fv::FigureEntry* e = fv::find_registered(id);
    if (!e) throw py::value_error("unknown figure '" + id + "'; allowed: " + fv::figure_ids());
    if (format != "png" && format != "svg" && format != "pdf")
        throw py::value_error("format = '" + format + "'; allowed: png, svg, pdf");
    const fv::app::PictureSize size{width, height, scale}; // the limits of `render --size` and `--scale`
    check(fv::app::picture_size_error(size));
    // The figure's parameters, checked as the command line checks its flags; one the figure does not take is
    // an error (the command line ignores it, but a keyword typed in vain is better said).
    fv::FigureInputs in;
    for (const auto& [key, value] : params) {
        const std::string k = key.cast<std::string>();
        bool taken = false;
        for (const fv::FigureParamUse& u : e->params) taken = taken || keyword_of(u.param) == k;
        if (!taken)
            throw py::value_error("figure " + id + " takes no parameter '" + k +
                                  "'; allowed: " + keywords_of(*e));
        if (k == "zeta")
            in.zeta = number("zeta", value, fv::kZetaRange);
        else if (k == "theta_deg")
            in.theta_deg = number("theta", value, fv::kThetaRange);
        else if (k == "rdisp")
            in.rdisp = number("rdisp", value, fv::kRdispRange);
        else if (k == "i")
            in.i = number("i", value, fv::kIRange);
        else if (k == "amplitude_um")
            in.amplitude_um = number("amplitude_um", value, fv::kAmplitudeRange);
        else if (k == "frequency_khz")
            in.frequency_khz = number("frequency_khz", value, fv::kFrequencyRange);
        else if (k == "data")
            in.data = py::str(value).cast<std::string>();
        else if (k == "start") {
            fv::Start s = fv::Start::rest;
            if (!fv::parse_start(value.cast<std::string>(), s))
                throw py::value_error("start = '" + value.cast<std::string>() + "'; allowed: rest, sliding");
            in.start = s;
        } else
            throw py::value_error("figure " + id + ": parameter '" + k +
                                  "' is not supported from Python yet");
    }
    // No parameter given: the figure's example (as `render --figure all`); some given: every required one.
    const bool none = params.empty();
    if (none && !e->params.empty()) in = e->example;
    if (const std::optional<fv::FigureParam> p = fv::missing_param(*e, in))
        throw py::value_error("figure " + id + " needs " + keyword_of(*p) + " (it takes " + keywords_of(*e) +
                              ")");
    std::string bytes;
    {
        py::gil_scoped_release unlocked;
        fv::FigureSpec spec;
        try {
            spec = e->make(in);
        } catch (const fv::DataError& err) {
            py::gil_scoped_acquire locked;
            throw py::value_error(err.what());
        } catch (const fv::FitError& err) {
            py::gil_scoped_acquire locked;
            throw py::value_error(std::string("data: ") + err.what());
        }
        const fv::FigureData data = fv::compute_figure(spec);
        // One GL context at a time: OSMesa's are per thread, and drawing is not the slow part.
        static std::mutex gl;
        std::lock_guard<std::mutex> lock(gl);
        fv::app::FigureRenderer renderer(size);
        bytes = renderer.render(data, format == "png"   ? fv::app::PictureFormat::png
                                      : format == "svg" ? fv::app::PictureFormat::svg
                                                        : fv::app::PictureFormat::pdf);
    }
    return py::bytes(bytes);
}

} // namespace fvpy
