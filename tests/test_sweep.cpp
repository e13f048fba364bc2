#include "fv/sweep.hpp"

#include <catch2/catch.hpp>

#include <atomic>

TEST_CASE("linspace includes both ends", "[sweep]") {
    const auto v = fv::linspace(0.02, 3, 150);
    REQUIRE(v.size() == 150);
    CHECK(v.front() == 0.02);
    CHECK(v.back() == 3);
    CHECK(fv::linspace(1, 2, 1) == std::vector<double>{1});
}

TEST_CASE("sweep visits every combination once, in order, and matches single calls", "[sweep]") {
    const std::vector<double> z{0.1, 0.6}, th{0, 1.2}, rd{1, 4}, ii{0, 1};
    const auto rows = fv::sweep(fv::Model::dahl, z, th, rd, ii, {}, 2);
    REQUIRE(rows.size() == 16);
    // zeta fastest, then rdisp, theta, i.
    CHECK(rows[1].params.zeta == 0.6);
    CHECK(rows[2].params.rdisp == 4);
    CHECK(rows[4].params.theta == 1.2);
    CHECK(rows[8].params.i == 1);
    // The default sweep warm-starts each zeta from its neighbour: the same steady state as a cold single
    // call, to within the solver's tolerance.
    for (const auto& r : rows)
        CHECK(r.result.rx == Approx(fv::steady_ratio(fv::Model::dahl, r.params).rx).margin(1e-7));
    // With the paper's scheme every point is an independent call: bit-identical.
    fv::SteadyOptions paper;
    paper.scheme = fv::Scheme::paper;
    const auto prow = fv::sweep(fv::Model::dahl, z, th, rd, ii, paper, 2);
    for (const auto& r : prow) CHECK(r.result.rx == fv::dahl_steady(r.params).rx);
    const auto rigid = fv::sweep(fv::Model::rigid, z, th, rd, ii);
    CHECK(rigid.size() == 4); // one curve per angle: rdisp and i do not apply
}

TEST_CASE("parallel_for runs every index exactly once and forwards exceptions", "[sweep]") {
    std::vector<std::atomic<int>> hits(1000);
    fv::parallel_for(
        1000, [&](int k) { hits[static_cast<std::size_t>(k)]++; }, 4);
    for (auto& h : hits) CHECK(h == 1);
    CHECK_THROWS(fv::parallel_for(
        10,
        [](int k) {
            if (k == 7) throw std::runtime_error("x");
        },
        2));
}
