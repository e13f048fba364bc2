// The figure part of frictionviz._core (render.cpp): kept apart from module.cpp so that the model's bindings
// do not depend on the figure registry's shape.
#pragma once

#include <pybind11/pybind11.h>

#include <string>

namespace fvpy {

// [(id, title, [parameter keywords])] in the registry's order.
pybind11::list figures();

// The figure `id` with `params` (zeta, theta_deg, rdisp, i, data, amplitude_um, frequency_khz, start; none:
// the figure's example inputs) at width x height pixels and `scale`, as png, svg or pdf bytes.
pybind11::bytes render(const std::string& id, const pybind11::dict& params, int width, int height,
                       double scale, const std::string& format);

} // namespace fvpy
