#include "fv/sweep.hpp"

#include <limits>

namespace fv {

std::vector<double> linspace(double from, double to, int count) {
    std::vector<double> v;
    if (count <= 0) return v;
    if (count == 1) return {from};
    v.reserve(static_cast<std::size_t>(count));
    for (int k = 0; k < count; ++k) v.push_back(from + (to - from) * k / (count - 1));
    v.back() = to; // exact end point, free of rounding
    return v;
}

std::vector<SweepPoint> sweep_grid(Model model, const std::vector<double>& zetas,
                                   const std::vector<double>& thetas, const std::vector<double>& rdisps,
                                   const std::vector<double>& is) {
    std::vector<SweepPoint> pts;
    // The rigid model has no rdisp or i: one curve per angle.
    const std::vector<double> one{0};
    const auto& rd = model == Model::rigid ? one : rdisps;
    const auto& ii = model == Model::rigid ? one : is;
    pts.reserve(zetas.size() * thetas.size() * rd.size() * ii.size());
    for (double i : ii)
        for (double th : thetas)
            for (double r : rd)
                for (double z : zetas) {
                    SweepPoint sp;
                    sp.model = model;
                    // rdisp and i mean nothing for the rigid model: NaN, printed as empty fields.
                    const double nan = std::numeric_limits<double>::quiet_NaN();
                    sp.params = {z, th, model == Model::rigid ? nan : r, model == Model::rigid ? nan : i};
                    pts.push_back(sp);
                }
    return pts;
}

std::vector<SweepPoint> sweep(Model model, const std::vector<double>& zetas,
                              const std::vector<double>& thetas, const std::vector<double>& rdisps,
                              const std::vector<double>& is, const SteadyOptions& opt, int threads) {
    // Every point on its own (the default solver starts each one cold, so a row never depends on the grid),
    // spread over the threads one point at a time.
    std::vector<SweepPoint> pts = sweep_grid(model, zetas, thetas, rdisps, is);
    SteadyOptions o = opt;
    o.record_period = false;
    parallel_for(
        static_cast<int>(pts.size()),
        [&](int k) {
            auto& sp = pts[static_cast<std::size_t>(k)];
            sp.result = steady_ratio(sp.model, sp.params, o);
        },
        threads);
    return pts;
}

} // namespace fv
