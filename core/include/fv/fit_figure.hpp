// Fig. 19 for any data set: measured friction ratios against the rigid model and the Dahl model with i = 0
// and i = 1, each at the r_disp fitted to the data.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/fit.hpp"
#include "fv/measurements.hpp"

namespace fv {

// Fits both exponents (FitError if the points do not share one angle or the fit cannot run) and returns the
// figure: one panel, the data with error bars where sigma is given, three model curves; a table with the
// measured points, both models' values and residuals. `fit` receives the fit when not null.
FigureData measurement_figure(const MeasurementSet& data, const FitOptions& opt, FitResult* fit = nullptr);

} // namespace fv
