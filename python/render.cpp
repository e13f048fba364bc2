// frictionviz._core's figures: the registry's ids, titles and parameter keys, and one figure rendered
// headless (OSMesa for PNG, cairo for SVG and PDF) from a spec: the same JSON object `render --spec` reads
// and every ID.json's "parameters" holds (figures/figure_spec_file.hpp), made by
// python/frictionviz/__init__.py from the keyword arguments. So the checks, the messages, the defaults and
// the pictures are the command line's, and the parameters object handed back reproduces the figure with
// `frictionviz render --spec`.
#include "render.hpp"

#include "figures/figure_renderer.hpp"
#include "figures/figure_spec_file.hpp"

#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/fit.hpp"
#include "fv/measurements.hpp"

#include <mutex>
#include <string>
#include <vector>

namespace py = pybind11;

namespace fvpy {

py::list figures() {
    py::list out;
    for (const fv::FigureEntry& e : fv::figure_registry()) {
        py::list params;
        for (const fv::FigureParamUse& u : e.params) {
            const std::string key = fv::param_key(u.param);
            bool seen = false; // zeta and zeta_range share their key
            for (const auto& p : params) seen = seen || p.cast<std::string>() == key;
            if (!seen) params.append(key);
        }
        out.append(py::make_tuple(e.id, e.title, params));
    }
    return out;
}

py::tuple render(const std::string& spec_text, bool example, int width, int height, double scale,
                 const std::string& format) {
    if (format != "png" && format != "svg" && format != "pdf")
        throw py::value_error("format = '" + format + "'; allowed: png, svg, pdf");
    const fv::app::PictureSize size{width, height, scale}; // the limits of `render --size` and `--scale`
    if (const std::string why = fv::app::picture_size_error(size); !why.empty()) throw py::value_error(why);
    fv::app::FigureSpecFile spec;
    try {
        spec = fv::app::parse_spec_file(spec_text);
    } catch (const fv::app::SpecError& e) {
        throw py::value_error(e.what());
    }
    // No parameter given: the figure's example inputs (as `render --figure all` draws it).
    if (example) spec.inputs = spec.entry->example;
    fv::app::PictureFormats formats;
    formats.png = format == "png", formats.svg = format == "svg", formats.pdf = format == "pdf";
    const std::string parameters =
        fv::app::parameters_json(*spec.entry, spec.inputs, width, height, scale, formats);
    std::string bytes, title, caption;
    std::vector<fv::app::FigureTableFile> tables;
    {
        py::gil_scoped_release unlocked;
        std::string error;
        fv::FigureSpec figure;
        try {
            figure = spec.entry->make(spec.inputs);
        } catch (const fv::DataError& e) {
            error = e.what();
        } catch (const fv::FitError& e) {
            error = std::string("data: ") + e.what();
        }
        if (!error.empty()) {
            py::gil_scoped_acquire locked;
            throw py::value_error(error);
        }
        title = fv::plain_text(figure.title);
        caption = figure.caption + " " + fv::figure_parameters(figure);
        const fv::FigureData data = fv::compute_figure(figure);
        tables = fv::app::figure_tables(data); // the command line's CSV files, byte for byte
        // One GL context at a time: OSMesa's are per thread, and drawing is not the slow part.
        static std::mutex gl;
        std::lock_guard<std::mutex> lock(gl);
        fv::app::FigureRenderer renderer(size);
        bytes = renderer.render(data, format == "png"   ? fv::app::PictureFormat::png
                                      : format == "svg" ? fv::app::PictureFormat::svg
                                                        : fv::app::PictureFormat::pdf);
    }
    py::list csv;
    for (const fv::app::FigureTableFile& t : tables) csv.append(py::make_tuple(t.name, t.csv));
    return py::make_tuple(py::bytes(bytes), title, caption, parameters, csv);
}

} // namespace fvpy
