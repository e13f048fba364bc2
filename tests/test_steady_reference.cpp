// The solver against an independent brute-force integrator (tests/reference/brute_force.hpp: classical RK4
// on a fixed grid, period after period from the start until the section state repeats; no fv:: code).
// tests/data/steady_reference.csv holds its results for the hard points and 60 random points of the
// domain, both starts (the command that made it is its first line; some rows take 10^8 RK4 steps, too slow
// for a test). A few fast points are also integrated here, so the reference code itself runs in CI.
//
// What is asserted, row by row (docs/model.md, "Which steady state" and "Error estimate"):
//  * where the reference settled into a period-k orbit and the solver answers ok, the same k, and
//    |r - r_ref| <= kErrorSafety * error_estimate + err_ref (both r_x and r_y);
//  * where the solver does not answer ok, its status says why (exit 3) - allowed only at the points listed as
//    slow creeps, whose fixed point lies where Newton's linear model describes one side only;
//  * where the reference found no periodic motion, the solver does not claim one (not_periodic, or a
//  failure).
#include "fv/ode_solver.hpp"
#include "fv/steady_state.hpp"
#include "reference/brute_force.hpp"
#include "reference/theta0_exact.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

constexpr double kDeg = fv::kPi / 180;

struct RefRow {
    double zeta = 0, theta_deg = 0, rdisp = 0, i = 0;
    fv::Start start = fv::Start::rest;
    std::string status; // period_1, period_2, ..., unsettled, not_periodic, capped
    int k = 0;
    int periods = 0; // integrated until the section repeated
    double rx = 0, ry = 0, rx_err = 0, ry_err = 0;
    double contraction = 0; // per period, near the state the reference ended in
};

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::string cell;
    bool quoted = false;
    for (char c : line) {
        if (c == '"')
            quoted = !quoted;
        else if (c == ',' && !quoted) {
            out.push_back(cell);
            cell.clear();
        } else
            cell += c;
    }
    out.push_back(cell);
    return out;
}

std::vector<RefRow> reference_rows() {
    std::ifstream in(std::string(FV_TEST_DATA_DIR) + "/steady_reference.csv");
    REQUIRE(in);
    std::vector<RefRow> rows;
    std::string line;
    bool header = false;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (!header) {
            header =
                true; // zeta,theta_deg,rdisp,i,start,status,k,periods,rx,ry,rx_err_estimate,...,ry_err_estimate
            REQUIRE(line.rfind("zeta,theta_deg,rdisp,i,start,status,k,periods,rx,ry,rx_err_estimate,", 0) ==
                    0);
            continue;
        }
        const std::vector<std::string> c = split(line);
        REQUIRE(c.size() >= 15);
        RefRow r;
        r.zeta = std::stod(c[0]), r.theta_deg = std::stod(c[1]), r.rdisp = std::stod(c[2]),
        r.i = std::stod(c[3]);
        r.start = c[4] == "sliding" ? fv::Start::sliding : fv::Start::rest;
        r.status = c[5];
        r.k = std::stoi(c[6]);
        r.periods = std::stoi(c[7]);
        r.rx = std::stod(c[8]), r.ry = std::stod(c[9]);
        r.rx_err = std::stod(c[10]), r.ry_err = std::stod(c[13]); // "inf" reads as infinity
        r.contraction = std::stod(c[14]);
        rows.push_back(r);
    }
    return rows;
}

fv::SteadyResult solve(const RefRow& r) {
    fv::OdeOptions o;
    o.start = r.start;
    return fv::ode_steady({r.zeta, r.theta_deg * kDeg, r.rdisp, r.i}, o);
}

} // namespace

TEST_CASE(
    "The brute-force reference integrator meets the exact 1-D stick-slip result and the mirror symmetry",
    "[reference][states]") {
    // theta = 0, i = 0: the exact r_x of the 1-D stick-slip cycle (tests/reference/theta0_exact.hpp, derived
    // independently), from both starts.
    for (const auto& p : {std::pair{0.3, 2.0}, std::pair{0.05, 5.0}, std::pair{0.8, 1.0}})
        for (const auto start : {fv::ref::BruteStart::rest, fv::ref::BruteStart::sliding}) {
            const fv::ref::BruteForceResult b = fv::ref::brute_force(p.first, 0, p.second, 0, start);
            const double exact = fv::ref::rx_theta0_i0(p.first, p.second);
            CAPTURE(p.first, p.second, b.status, b.rx, exact, b.rx_err);
            CHECK(b.status.rfind("period_", 0) == 0);
            CHECK(std::abs(b.rx - exact) <= std::max(1e-10, 10 * b.rx_err));
            CHECK(std::abs(b.ry) <= 1e-14);
        }
    // theta -> 180 deg - theta: r_x equal, r_y opposite.
    const fv::ref::BruteForceResult a = fv::ref::brute_force(0.3, 30, 2, 1, fv::ref::BruteStart::rest);
    const fv::ref::BruteForceResult b = fv::ref::brute_force(0.3, 150, 2, 1, fv::ref::BruteStart::rest);
    CHECK(std::abs(a.rx - b.rx) <= 1e-9);
    CHECK(std::abs(a.ry + b.ry) <= 1e-9);
}

TEST_CASE("The solver agrees with the brute-force integrator run here (fast points, both starts)",
          "[reference][states]") {
    // Points of the domain the reference settles on in a few periods, one per exponent class.
    const double pts[][4] = {{0.1889, 15.23, 7.7, 10},
                             {0.2718, 30.94, 2.532, 2},
                             {0.8688, 99.94, 1.786, 1},
                             {0.6, 75, 0.2, 0},
                             {0.318, 81.09, 0.1502, 0.5}};
    for (const auto& p : pts)
        for (const auto start : {fv::Start::rest, fv::Start::sliding}) {
            const fv::ref::BruteForceResult b = fv::ref::brute_force(
                p[0], p[1], p[2], p[3],
                start == fv::Start::rest ? fv::ref::BruteStart::rest : fv::ref::BruteStart::sliding);
            RefRow r;
            r.zeta = p[0], r.theta_deg = p[1], r.rdisp = p[2], r.i = p[3], r.start = start;
            const fv::SteadyResult s = solve(r);
            CAPTURE(p[0], p[1], p[2], p[3], fv::to_string(start), b.status, b.rx, b.rx_err, s.rx,
                    s.error_estimate, fv::status_word(s));
            REQUIRE(b.status == "period_1");
            REQUIRE(fv::ok(s.status));
            CHECK(s.period_k == 1);
            CHECK(std::abs(s.rx - b.rx) <= fv::kErrorSafety * s.error_estimate + b.rx_err);
            CHECK(std::abs(s.ry - b.ry) <= fv::kErrorSafety * s.error_estimate + b.ry_err);
        }
}

TEST_CASE("A state found from one start is credited to the other only where the other's motion reaches it",
          "[reference][states]") {
    // Two stable states along the edge of the stick region at i = 5, r_disp = 0.1: the motion from rest
    // settles into the small one, the motion from sliding stays on the circle. The push test along the slow
    // direction alone once credited the small state to sliding too (at the first point, through the map's
    // shortcut; at the second, in every map cell: the map showed one state). Each point from sliding is run
    // here with the brute-force integrator; the listing (full searches from both starts, and the map's
    // shortcut for the other start) must mark the state the reference reaches, and only that, as reached
    // from sliding.
    const double pts[][2] = {{0.154773869347, 83}, {0.319497487437, 72}};
    for (const auto& p : pts) {
        const fv::ref::BruteForceResult b =
            fv::ref::brute_force(p[0], p[1], 0.1, 5, fv::ref::BruteStart::sliding);
        REQUIRE(b.status == "period_1");
        for (const bool only_reached : {false, true}) {
            fv::OdeOptions o;
            o.tolerance = 1e-6; // the map's
            o.list_states = true;
            o.list_only_reached = only_reached;
            const fv::SteadyResult s = fv::ode_steady({p[0], p[1] * kDeg, 0.1, 5}, o);
            CAPTURE(p[0], p[1], only_reached, b.rx, s.rx, s.states.size());
            REQUIRE(fv::ok(s.status));
            int credited = 0;
            for (const fv::SteadyState& st : s.states) {
                CAPTURE(st.rx, st.from_rest, st.from_sliding);
                if (!st.from_sliding) continue;
                ++credited;
                CHECK(std::abs(st.rx - b.rx) <= fv::kErrorSafety * st.error_estimate + b.rx_err);
            }
            CHECK(credited == 1);
            CHECK(s.states.size() == 2);
        }
    }
}

TEST_CASE("The solver against the brute-force reference set: same state, error within its bound",
          "[reference][states][slow][long]") {
    const std::vector<RefRow> rows = reference_rows();
    // 13 hard points and 60 random ones, both starts; three slow approaches the solver coasts over (from rest
    // at zeta 0.001, theta 30 deg, rdisp 1e-3, i = 2: 3751 periods of the reference; from sliding at 0.00422,
    // 90 deg, 0.01, 2: 13697; from sliding at 0.316, 60 deg, 1e-5, 10: 186345); a near miss that ended
    // not_converged at 1e-8 until the solver retried it 4x tighter (zeta 0.0274, theta 1.37 deg, rdisp 0.232,
    // i 0.5 from rest); next to an unstable period-1 state at zeta 0.45 and 0.448, theta 8.1 deg, rdisp 37,
    // i 10 from rest, a period-4 orbit and an irregular motion (both once reported unsettled, with the
    // unstable state's values); a period-2 orbit closing in at 0.992 per period next to an unstable period-1
    // state (zeta 0.244623, theta 62 deg, rdisp 2, i 10 from rest, a cell of the i = 10 map; once unsettled)
    REQUIRE(rows.size() == 153);
    int compared = 0, creeps = 0;
    double worst_ratio = 0;
    for (const RefRow& r : rows) {
        const fv::SteadyResult s = solve(r);
        CAPTURE(r.zeta, r.theta_deg, r.rdisp, r.i, fv::to_string(r.start), r.status, r.rx, r.ry, r.rx_err,
                fv::status_word(s), s.rx, s.ry, s.error_estimate, s.detail);
        const bool ref_periodic = r.status.rfind("period_", 0) == 0 && std::isfinite(r.rx_err);
        if (r.status == "not_periodic") {
            // No periodic motion over 20 000 periods: none may be claimed, nor an unstable state's values
            // given for the motion's; the long-time mean within three combined standard errors.
            REQUIRE(s.status == fv::SteadyStatus::not_periodic);
            CHECK(std::abs(s.rx - r.rx) <= 3 * std::hypot(s.mean_standard_error, r.rx_err));
            continue;
        }
        if (!ref_periodic) continue; // the reference did not settle: nothing to hold the solver to
        // Every state the reference settles into is found, the slow creeps at i = 10 included (the reference
        // needs 14 000 and 32 000 periods for the first two hard points; the solver skips the creep,
        // core/src/solver/creep_skip.hpp).
        REQUIRE(fv::ok(s.status));
        ++compared;
        CHECK(s.period_k == r.k);
        // Where the solver projected a slow creep, its count of the creep's periods is the reference's count
        // of periods to the steady state, less those it takes to settle once the creep ends: from O(1) to the
        // reference's 1e-11 at its contraction per period (34 of 14 137 at zeta 0.285, theta 90 deg, rdisp 2;
        // 57 of 141 for the period-4 orbit at zeta 0.45, theta 8.1 deg, rdisp 37, after a creep of 84).
        if (s.creep_periods_skipped > 0) {
            ++creeps;
            const double settle =
                r.contraction > 0 && r.contraction < 1 ? std::log(1e-11) / std::log(r.contraction) : 0.0;
            CHECK(s.creep_periods_skipped <= r.periods);
            CHECK(s.creep_periods_skipped >= 0.9 * (r.periods - settle));
        }
        const double dx = std::abs(s.rx - r.rx), dy = std::abs(s.ry - r.ry);
        CHECK(dx <= fv::kErrorSafety * s.error_estimate + r.rx_err);
        CHECK(dy <= fv::kErrorSafety * s.error_estimate + r.ry_err);
        worst_ratio = std::max(worst_ratio, std::max(dx - r.rx_err, dy - r.ry_err) / s.error_estimate);
    }
    // Printed, not asserted: how close the worst point comes to the documented factor.
    WARN(compared << " rows compared, " << creeps
                  << " through a slow creep; the largest (error - reference error) / estimate: "
                  << worst_ratio);
    CHECK(creeps >= 3);
    CHECK(compared >= 110);
}
