// Adaptive sampling of curves y(x) for plotting: more samples where a curve turns (a kink, a jump, a sharp
// bend), few where it is straight, under a budget of samples per curve.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

namespace fv {

struct AdaptiveSampling {
    // The plotted extent: distances are measured as shares of it, so that x and y weigh as on the page;
    // y_span 0: the range of the start grid's values (an axis fitted to the curves).
    double x_span = 1, y_span = 1;
    // A sample further than this (a share of the spans) from the chord of its two neighbours splits both of
    // its intervals in half: 5e-4 is a third of a pixel on a 700-pixel-high plot.
    double tolerance = 5e-4;
    // Intervals are not split below this (a share of x_span).
    double min_dx = 1e-6;
    // Samples per curve at most, the start grid included; where the budget does not reach, the largest
    // deviations are refined first.
    std::size_t budget = 200;
    int max_rounds = 24;
};

// One value to compute: curve `curve` at `x`.
struct SampleRequest {
    std::size_t curve = 0;
    double x = 0;
};

// The samples of one curve, x ascending.
struct SampledCurve {
    std::vector<double> x, y;
};

// Samples `curves` curves on the start grid `start` (ascending), then adds the midpoints of the intervals
// next to every sample that lies further than the tolerance from the chord of its neighbours, round after
// round, until none does, the intervals reach min_dx or the budget is spent. `eval` computes the values of
// one round's requests (all curves together, so that it can spread them over threads); a non-finite value
// is kept but not refined around.
std::vector<SampledCurve>
adaptive_sample(std::size_t curves, const std::vector<double>& start, const AdaptiveSampling& options,
                const std::function<std::vector<double>(const std::vector<SampleRequest>&)>& eval);

} // namespace fv
