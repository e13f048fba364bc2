// Families of r_x(zeta) curves (the data behind Figs. 5 and 10-13), spread over all cores.
#pragma once

#include "fv/steady_state.hpp"

#include <cstddef>
#include <functional>
#include <vector>

namespace fv {

struct SweepPoint {
    Model model = Model::dahl;
    Params params;
    SteadyResult result; // period samples are not kept
};

// zeta values: count points evenly from `from` to `to` inclusive (count == 1 -> from).
std::vector<double> linspace(double from, double to, int count);

// The points of a sweep, not yet computed: every combination model x i x theta x rdisp x zeta, in that
// nesting order (zeta fastest); for the rigid model one point per (theta, zeta), rdisp and i NaN.
std::vector<SweepPoint> sweep_grid(Model model, const std::vector<double>& zetas,
                                   const std::vector<double>& thetas, const std::vector<double>& rdisps,
                                   const std::vector<double>& is);

// The sweep_grid points, computed (steady_ratio), spread over the threads.
// For the rigid model, rdisp and i do not matter and each (theta, zeta) is computed once.
std::vector<SweepPoint> sweep(Model model, const std::vector<double>& zetas,
                              const std::vector<double>& thetas, const std::vector<double>& rdisps,
                              const std::vector<double>& is, const SteadyOptions& opt = {}, int threads = 0);

// The number of points sweep_grid would make (computed without making them; saturates at SIZE_MAX).
std::size_t sweep_size(Model model, std::size_t zetas, std::size_t thetas, std::size_t rdisps,
                       std::size_t is);

// The same points as sweep(), computed block by block in grid order: `emit` gets the rows of each block of
// at most `block` points, in order, and may return false to stop. Memory holds one block, whatever the grid
// (the CLI's sweep streams its rows this way). Returns the number of points computed.
std::size_t sweep_blocks(Model model, const std::vector<double>& zetas, const std::vector<double>& thetas,
                         const std::vector<double>& rdisps, const std::vector<double>& is,
                         const SteadyOptions& opt, int threads, std::size_t block,
                         const std::function<bool(const std::vector<SweepPoint>&)>& emit);

// Runs f(k) for k in [0, count) on `threads` threads (0: hardware concurrency). Work is handed out one
// index at a time, so uneven costs (slow steady states) balance out.
template <class F> void parallel_for(int count, F&& f, int threads = 0);

} // namespace fv

#include "fv/detail/parallel_for.hpp"
