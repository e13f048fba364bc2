// Fig. 19 for any data set: measured friction ratios against the rigid model and the Dahl model with i = 0
// and i = 1, each at the r_disp fitted to the data.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/fit.hpp"
#include "fv/measurements.hpp"

#include <optional>
#include <vector>

namespace fv {

// Fits both exponents (FitError if the points do not share one angle or the fit cannot run) and returns the
// figure: one panel, the data with error bars where sigma is given, three model curves; a table with the
// measured points, both models' values and residuals. `fit` receives the fit when not null.
// The measured points as markers (with error bars where sigma is given). With `theta_deg`, points measured
// at another angle (their theta_deg differs by more than 0.5 deg) form a second, faded series, so that a
// plot of r_x(zeta) at one angle does not pass them off as its own.
std::vector<SeriesData> measured_series(const MeasurementSet& data,
                                        std::optional<double> theta_deg = std::nullopt);

FigureData measurement_figure(const MeasurementSet& data, const FitOptions& opt, FitResult* fit = nullptr);

} // namespace fv
