// The figure part of frictionviz._core (render.cpp): kept apart from module.cpp so that the model's bindings
// do not depend on the figure registry's shape.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace fvpy {

// [(id, title, [parameter keys])] in the registry's order; the keys are a spec file's (fv::param_key).
pybind11::list figures();

// The figure a spec file's text names (figures/figure_spec_file.hpp: {"id": .., "theta": [30, 60], ..}), or
// with `example` its example inputs, at width x height pixels and `scale`, as png, svg or pdf bytes:
// (bytes, title, caption, parameters JSON, [(CSV file name, CSV text)]: the tables `render` writes beside
// the picture, byte for byte). ValueError with the command line's message for a bad spec.
pybind11::tuple render(const std::string& spec_text, bool example, int width, int height, double scale,
                       const std::string& format);

} // namespace fvpy
