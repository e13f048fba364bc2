// Fig. 19 for any data set: measured friction ratios against the rigid model and the Dahl model with i = 0
// and i = 1, each at the r_disp fitted to the data.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/fit.hpp"
#include "fv/measurements.hpp"

#include <optional>
#include <vector>

namespace fv {

// The measured points as markers (with error bars where sigma is given). With `theta_deg`, points measured
// at another angle (their theta_deg differs by more than 0.5 deg) form a second, faded series, so that a
// plot of r_x(zeta) at one angle does not pass them off as its own.
std::vector<SeriesData> measured_series(const MeasurementSet& data,
                                        std::optional<double> theta_deg = std::nullopt);

// Fits both exponents to all points at once (r_disp and i belong to the contact, not to the angle; FitError
// if the fit cannot run or the points have more than 4 angles) and returns the figure: one panel per angle in
// the order of the file (the paper's Fig. 19 has (a) 90 deg and (b) 0 deg), each with that angle's points
// (error bars where sigma is given), the rigid curve and both fitted Dahl curves; a table with every measured
// point, its angle, both models' values and residuals. `fit` receives the fit when not null.
FigureData measurement_figure(const MeasurementSet& data, const FitOptions& opt, FitResult* fit = nullptr);

} // namespace fv
