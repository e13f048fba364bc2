#include "fv/adaptive_sampling.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace fv {

std::vector<SampledCurve>
adaptive_sample(std::size_t curves, const std::vector<double>& start, const AdaptiveSampling& options,
                const std::function<std::vector<double>(const std::vector<SampleRequest>&)>& eval) {
    AdaptiveSampling o = options;
    std::vector<SampledCurve> out(curves);
    std::vector<SampleRequest> requests;
    for (std::size_t c = 0; c < curves; ++c)
        for (double x : start) requests.push_back({c, x});
    const double min_dx = o.min_dx * o.x_span;
    for (int round = 0; !requests.empty(); ++round) {
        const std::vector<double> values = eval(requests);
        for (std::size_t k = 0; k < requests.size(); ++k) {
            SampledCurve& s = out[requests[k].curve];
            s.x.push_back(requests[k].x);
            s.y.push_back(values[k]);
        }
        requests.clear();
        if (!(o.y_span > 0)) { // the range of the start grid's values
            double lo = 1e300, hi = -1e300;
            for (const SampledCurve& s : out)
                for (double v : s.y)
                    if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
            o.y_span = hi > lo ? hi - lo : 1;
        }
        for (std::size_t c = 0; c < curves; ++c) {
            SampledCurve& s = out[c];
            // Sorted by x (the new samples were appended).
            std::vector<std::size_t> order(s.x.size());
            for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
            std::sort(order.begin(), order.end(),
                      [&](std::size_t a, std::size_t b) { return s.x[a] < s.x[b]; });
            SampledCurve sorted;
            for (std::size_t k : order) sorted.x.push_back(s.x[k]), sorted.y.push_back(s.y[k]);
            s = std::move(sorted);
            if (round + 1 >= o.max_rounds || s.x.size() >= o.budget) continue;
            // Deviation of each sample from the chord of its neighbours, on the page's scale; the intervals
            // either side of it inherit it (the larger of their two samples').
            const std::size_t n = s.x.size();
            std::vector<double> split(n > 0 ? n - 1 : 0, 0.0);
            for (std::size_t k = 1; k + 1 < n; ++k) {
                const double ax = s.x[k - 1] / o.x_span, ay = s.y[k - 1] / o.y_span;
                const double bx = s.x[k + 1] / o.x_span, by = s.y[k + 1] / o.y_span;
                const double px = s.x[k] / o.x_span, py = s.y[k] / o.y_span;
                if (!std::isfinite(ay) || !std::isfinite(by) || !std::isfinite(py)) continue;
                const double len = std::hypot(bx - ax, by - ay);
                const double d = len > 0 ? std::fabs((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / len : 0;
                if (d <= o.tolerance) continue;
                split[k - 1] = std::max(split[k - 1], d);
                split[k] = std::max(split[k], d);
            }
            std::vector<std::pair<double, double>> wanted; // (deviation, midpoint)
            for (std::size_t k = 0; k + 1 < n; ++k)
                if (split[k] > 0 && s.x[k + 1] - s.x[k] > 2 * min_dx)
                    wanted.push_back({split[k], 0.5 * (s.x[k] + s.x[k + 1])});
            // The largest deviations first, as far as the budget goes; then in x order.
            std::stable_sort(wanted.begin(), wanted.end(),
                             [](const auto& a, const auto& b) { return a.first > b.first; });
            wanted.resize(std::min(wanted.size(), o.budget - n));
            std::sort(wanted.begin(), wanted.end(),
                      [](const auto& a, const auto& b) { return a.second < b.second; });
            for (const auto& w : wanted) requests.push_back({c, w.second});
        }
    }
    return out;
}

} // namespace fv
