#include "fv/sweep.hpp"

#include <algorithm>
#include <cstdint>
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

namespace {

// The rigid model has no rdisp or i: one curve per angle.
std::size_t family_size(Model model, std::size_t n) {
    return model == Model::rigid ? 1 : n;
}

// Point k of the grid, nesting i x theta x rdisp x zeta (zeta fastest).
SweepPoint grid_point(Model model, const std::vector<double>& zetas, const std::vector<double>& thetas,
                      const std::vector<double>& rdisps, const std::vector<double>& is, std::size_t k) {
    const std::size_t nz = zetas.size(), nr = family_size(model, rdisps.size()), nt = thetas.size();
    const std::size_t z = k % nz, r = k / nz % nr, t = k / nz / nr % nt, i = k / nz / nr / nt;
    SweepPoint sp;
    sp.model = model;
    // rdisp and i mean nothing for the rigid model: NaN, printed as empty fields.
    const double nan = std::numeric_limits<double>::quiet_NaN();
    sp.params = {zetas[z], thetas[t], model == Model::rigid ? nan : rdisps[r],
                 model == Model::rigid ? nan : is[i]};
    return sp;
}

} // namespace

std::size_t sweep_size(Model model, std::size_t zetas, std::size_t thetas, std::size_t rdisps,
                       std::size_t is) {
    std::size_t n = 1;
    for (const std::size_t f : {zetas, thetas, family_size(model, rdisps), family_size(model, is)}) {
        if (f != 0 && n > SIZE_MAX / f) return SIZE_MAX;
        n *= f;
    }
    return n;
}

std::vector<SweepPoint> sweep_grid(Model model, const std::vector<double>& zetas,
                                   const std::vector<double>& thetas, const std::vector<double>& rdisps,
                                   const std::vector<double>& is) {
    const std::size_t n = sweep_size(model, zetas.size(), thetas.size(), rdisps.size(), is.size());
    std::vector<SweepPoint> pts;
    pts.reserve(n);
    for (std::size_t k = 0; k < n; ++k) pts.push_back(grid_point(model, zetas, thetas, rdisps, is, k));
    return pts;
}

std::size_t sweep_blocks(Model model, const std::vector<double>& zetas, const std::vector<double>& thetas,
                         const std::vector<double>& rdisps, const std::vector<double>& is,
                         const SteadyOptions& opt, int threads, std::size_t block,
                         const std::function<bool(const std::vector<SweepPoint>&)>& emit) {
    const std::size_t n = sweep_size(model, zetas.size(), thetas.size(), rdisps.size(), is.size());
    SteadyOptions o = opt;
    o.record_period = false;
    block = std::max<std::size_t>(block, 1);
    std::vector<SweepPoint> rows;
    for (std::size_t from = 0; from < n; from += block) {
        const std::size_t count = std::min(block, n - from);
        rows.clear();
        for (std::size_t k = 0; k < count; ++k)
            rows.push_back(grid_point(model, zetas, thetas, rdisps, is, from + k));
        parallel_for(
            static_cast<int>(count),
            [&](int k) {
                auto& sp = rows[static_cast<std::size_t>(k)];
                sp.result = steady_ratio(sp.model, sp.params, o);
            },
            threads);
        if (!emit(rows)) return from + count;
    }
    return n;
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
