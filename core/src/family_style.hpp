// How the curves of a family figure (figure_family.hpp) look: the legend names only what varies from curve to
// curve, colours and dashes encode it.
//
//   - one Dahl parameter varies (or none): a colour per Dahl curve (6 colours, then dashed); the rigid curve
//     black dashed as in Figs. 10-13, or, where theta varies, dashed in the colour of its theta's Dahl curve
//     (as the ry figure draws them); rigid curves alone take a colour each (Fig. 5);
//   - two vary, one of them with at most 3 values (theta first): colour by the other, dash by it (solid,
//     dashed, dotted); rigid curves black with the dash of their theta;
//   - otherwise: a colour per curve, then dashed; rigid curves black, dashed by theta.
#pragma once

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/measurements.hpp"

#include <vector>

namespace fv::family {

// One series per curve, in the curves' order: label, ink, palette entry, dash (no points yet).
std::vector<SeriesData> curve_styles(const std::vector<Curve>& curves);

// The measured points inside `span`: black markers, one series (and mark) per vibration angle of the file,
// error bars where it gives sigma.
std::vector<SeriesData> data_series(const MeasurementSet& data, const ZetaSpan& span);

} // namespace fv::family
