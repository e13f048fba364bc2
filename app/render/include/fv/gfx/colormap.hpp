#pragma once
// Colour maps for heat maps: perceptually uniform and colour-blind friendly (viridis).
#include "fv/gfx/image.hpp"
#include "fv/gfx/types.hpp"

#include <cstddef>

namespace fv::gfx {

/// Viridis at t in [0,1] (clamped), piecewise linear through matplotlib's key colours.
Color viridis(double t);

/// Image of nx*ny values (row-major, row 0 = lowest y, so it is flipped to top-down), mapped through
/// viridis over [vmin, vmax]. Non-finite values become transparent.
Image heatmap_image(const double* values, int nx, int ny, double vmin, double vmax);

} // namespace fv::gfx
