// The app's background curves in steps (RatioJob) and the worker without a thread (the browser build's time
// slices): the steps give what the batch paths give (sweep() for the curve, compute_figure for the map), and
// the sliced worker publishes only complete results, the newest request's, equal to the threaded worker's.
#include "gui/ratio_worker.hpp"

#include "fv/figure_data.hpp"
#include "fv/figures.hpp"
#include "fv/rigid.hpp"
#include "fv/sweep.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstring>

using namespace fv;
using namespace fv::app;

namespace {

// Bit for bit, NaN equal to NaN (a failed point is NaN in the drawn curve).
bool same(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

bool same(const std::vector<double>& a, const std::vector<double>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t k = 0; k < a.size(); ++k)
        if (!same(a[k], b[k])) return false;
    return true;
}

RatioRequest request_at(double zeta, double theta_deg, bool map) {
    RatioRequest r;
    r.model = Model::dahl;
    r.params = {zeta, theta_deg * kPi / 180, 8, 0};
    r.map = map;
    return r;
}

void check_curves_equal(const RatioCurves& a, const RatioCurves& b) {
    CHECK(a.request == b.request);
    CHECK(same(a.zetas, b.zetas));
    CHECK(same(a.model_rx, b.model_rx));
    CHECK(same(a.rigid_rx, b.rigid_rx));
    CHECK(a.model_failed == b.model_failed);
    CHECK(same(a.current.rx, b.current.rx));
    CHECK(same(a.current.ry, b.current.ry));
    CHECK(a.map.has_value() == b.map.has_value());
}

} // namespace

TEST_CASE("Ratio job: the curve is sweep()'s and the map compute_figure's, point for point",
          "[gui][ratio][long]") {
    const RatioRequest req = request_at(0.45, 30, true);
    RatioJob job(req, true);
    int steps = 0;
    while (job.step()) ++steps;
    REQUIRE(job.done());
    const RatioCurves& out = job.result();

    const std::vector<double> zetas = ratio_zeta_grid(req.zeta_max);
    REQUIRE(same(out.zetas, zetas));
    const auto rows = sweep(Model::dahl, zetas, {req.params.theta}, {req.params.rdisp}, {req.params.i});
    REQUIRE(rows.size() == zetas.size());
    int failed = 0;
    for (std::size_t k = 0; k < zetas.size(); ++k) {
        const bool good = ok(shown_status(rows[k].result));
        failed += !good;
        CHECK(same(out.model_rx[k], good ? rows[k].result.rx : std::nan("")));
        CHECK(same(out.rigid_rx[k], rigid_ratio(zetas[k], req.params.theta).rx));
    }
    CHECK(out.model_failed == failed);
    const SteadyResult here = steady_ratio(req.model, req.params);
    CHECK(same(out.current.rx, here.rx));

    // The map: every cell and both best-angle lines as the figure computes them (all cores).
    const FigureData fig = compute_figure(map_figure(req.params.rdisp, req.params.i));
    REQUIRE(out.map.has_value());
    REQUIRE(out.map->heatmap.has_value());
    const HeatmapData& want = *fig.panels.front().heatmap;
    CHECK(out.map->heatmap->nx == want.nx);
    CHECK(out.map->heatmap->ny == want.ny);
    CHECK(same(out.map->heatmap->values, want.values));
    REQUIRE(out.map->series.size() == fig.panels.front().series.size());
    for (std::size_t s = 0; s < out.map->series.size(); ++s) {
        CHECK(same(out.map->series[s].x, fig.panels.front().series[s].x));
        CHECK(same(out.map->series[s].y, fig.panels.front().series[s].y));
    }
    // One step for the start, one per point of the curve and per cell of the map, one for the panel.
    CHECK(steps == 1 + static_cast<int>(zetas.size()) + want.nx * want.ny + 1);
}

TEST_CASE("Ratio worker without a thread: one step a slice at a zero budget, the newest request's result "
          "published whole",
          "[gui][ratio]") {
    const RatioRequest first = request_at(0.3, 60, false), second = request_at(0.45, 30, false);
    const std::size_t points = ratio_zeta_grid(second.zeta_max).size();

    RatioWorker sliced(false);
    sliced.request(first);
    sliced.run_slice(std::chrono::microseconds(0)); // the start and nothing else: nothing published yet
    CHECK(sliced.busy());
    CHECK_FALSE(sliced.latest().has_value());
    sliced.request(second); // supersedes the first, which is never published
    std::size_t slices = 0;
    while (sliced.busy()) {
        CHECK_FALSE(sliced.latest().has_value());
        sliced.run_slice(std::chrono::microseconds(0));
        ++slices;
    }
    CHECK(slices == 1 + points);
    const auto got = sliced.latest();
    REQUIRE(got.has_value());

    RatioWorker threaded(true);
    threaded.request(second);
    threaded.wait_idle();
    const auto want = threaded.latest();
    REQUIRE(want.has_value());
    check_curves_equal(*got, *want);

    // run_slice does nothing on a threaded worker; wait_idle finishes a sliced one at once.
    sliced.request(first);
    sliced.wait_idle();
    CHECK_FALSE(sliced.busy());
    REQUIRE(sliced.latest().has_value());
    CHECK(sliced.latest()->request == first);
}

TEST_CASE("Ratio job: the start's state at the current point, every stable state listed, the curve from that "
          "start",
          "[gui][ratio][start]") {
    // zeta 0.075, theta 90 deg, rdisp 0.1, i 5: r_x = 0.034177 from rest, 0.997508 from sliding (the
    // brute-force RK4 reference, tests/data/steady_reference.csv).
    RatioRequest req;
    req.model = Model::dahl;
    req.params = {0.075, kPi / 2, 0.1, 5};
    req.start = Start::sliding;
    CHECK_FALSE(req == RatioRequest{req.model, req.params, req.map, req.zeta_max, Start::rest});
    RatioJob job(req, false);
    job.step(); // the current point and the rigid curve
    const SteadyResult& here = job.result().current;
    CHECK(ok(shown_status(here)));
    CHECK(here.start == Start::sliding);
    CHECK(here.rx == Approx(0.997507926210302).margin(1e-3));
    REQUIRE(coexisting_states(job.result()).size() == 2);
    const std::vector<SteadyState>& states = here.states;
    CHECK(states[0].rx == Approx(0.034177137581669).margin(1e-3));
    CHECK(states[1].rx == Approx(0.997507926210302).margin(1e-3));
    CHECK(std::string(reached_from(states[0])) == "from rest");
    CHECK(std::string(reached_from(states[1])) == "from sliding");
    // The curve: each point as steady_ratio gives it from the same start.
    while (job.step()) {
    }
    const RatioCurves& out = job.result();
    SteadyOptions opt;
    opt.start = Start::sliding;
    for (std::size_t k : {std::size_t{1}, out.zetas.size() / 2}) {
        INFO(out.zetas[k]);
        const SteadyResult r = steady_ratio(Model::dahl, {out.zetas[k], kPi / 2, 0.1, 5}, opt);
        CHECK(same(out.model_rx[k], ok(shown_status(r)) ? r.rx : std::nan("")));
    }
    // From rest the same point reports the rest state, and lists the same two.
    req.start = Start::rest;
    RatioJob rest(req, false);
    rest.step();
    CHECK(rest.result().current.rx == Approx(0.034177137581669).margin(1e-3));
    CHECK(coexisting_states(rest.result()).size() == 2);
}
