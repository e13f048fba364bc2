// Adaptive Gauss-Kronrod (7-15) quadrature with break points, for the rigid-model integrals.
#pragma once

#include <functional>
#include <vector>

namespace fv {

struct QuadResult {
    double value = 0;
    double error = 0; // Kronrod-Gauss difference summed over the final intervals (an upper estimate)
    int evaluations = 0;
    bool converged = true; // error <= tolerance before the interval budget ran out
};

// Integrates f over [a, b] split first at `breaks` (points inside (a, b) where f has kinks or jumps),
// then bisecting the interval with the largest error until the summed error is <= abs_tol.
QuadResult integrate(const std::function<double(double)>& f, double a, double b, std::vector<double> breaks,
                     double abs_tol = 1e-13, int max_intervals = 20000);

} // namespace fv
