#include "fv/units.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <string>

using namespace fv::units;

TEST_CASE("units: the paper's Littmann et al. example, 0.7 um at 60 kHz", "[units]") {
    // 2 pi * 60e3 /s * 0.7e-6 m = 0.263893782901543 m/s (hand computed)
    CHECK(vibration_velocity(0.7, 60) == Approx(0.263893782901543).epsilon(1e-14));
    CHECK(zeta_from_vb(0.263893782901543, 0.7, 60) == Approx(1.0).epsilon(1e-14));
    // v_b = 0.05 m/s: zeta = 0.05 / 0.2638937829 = 0.18947017035
    CHECK(zeta_from_vb(0.05, 0.7, 60) == Approx(0.18947017035).epsilon(1e-10));
    CHECK(vb_from_zeta(0.5, 0.7, 60) == Approx(0.131946891450771).epsilon(1e-14));
    CHECK(zeta_from_vb(0, 0.7, 60) == 0);
}

TEST_CASE("units: rdisp = A / z_ss both ways", "[units]") {
    CHECK(rdisp_from_zss(0.7, 0.35) == Approx(2.0).epsilon(1e-15));
    CHECK(zss_from_rdisp(2.0, 0.7) == Approx(0.35).epsilon(1e-15));
    CHECK(zss_from_rdisp(rdisp_from_zss(1.3, 0.17), 1.3) == Approx(0.17).epsilon(1e-15));
    CHECK(vb_from_zeta(zeta_from_vb(0.123, 2.5, 20), 2.5, 20) == Approx(0.123).epsilon(1e-15));
}

TEST_CASE("units: non-finite or out-of-range arguments throw UnitError naming them", "[units]") {
    const double nan = std::numeric_limits<double>::quiet_NaN(),
                 inf = std::numeric_limits<double>::infinity();
    CHECK_THROWS_WITH(vibration_velocity(0, 60), Catch::Contains("amplitude") && Catch::Contains("> 0"));
    CHECK_THROWS_WITH(vibration_velocity(0.7, -1), Catch::Contains("frequency"));
    CHECK_THROWS_WITH(vibration_velocity(nan, 60), Catch::Contains("amplitude"));
    CHECK_THROWS_WITH(vibration_velocity(0.7, inf), Catch::Contains("frequency"));
    CHECK_THROWS_WITH(zeta_from_vb(-0.1, 0.7, 60), Catch::Contains("v_b") && Catch::Contains(">= 0"));
    CHECK_THROWS_WITH(zeta_from_vb(nan, 0.7, 60), Catch::Contains("v_b"));
    CHECK_THROWS_WITH(vb_from_zeta(-1, 0.7, 60), Catch::Contains("zeta"));
    CHECK_THROWS_WITH(rdisp_from_zss(0.7, 0), Catch::Contains("z_ss"));
    CHECK_THROWS_WITH(zss_from_rdisp(0, 0.7), Catch::Contains("rdisp"));
    CHECK_THROWS_AS(zss_from_rdisp(inf, 0.7), UnitError);
    CHECK_THROWS_AS(zss_from_rdisp(2, -0.7), std::invalid_argument);
}

// Found by fuzzing (tests/fuzz/fuzz_measurements): 1e-300 um at 1e-300 kHz passed the argument checks, v_v
// underflowed to 0, and vb = 0 became zeta = NaN, which the CSV reader then accepted.
TEST_CASE("units: results beyond the doubles throw UnitError instead of giving 0, NaN or infinity",
          "[units]") {
    CHECK_THROWS_WITH(vibration_velocity(1e-300, 1e-300), Catch::Contains("v_v"));
    CHECK_THROWS_AS(vibration_velocity(1e300, 1e300), UnitError);
    CHECK_THROWS_AS(zeta_from_vb(0, 1e-300, 1e-300), UnitError);
    CHECK_THROWS_WITH(zeta_from_vb(1e300, 1e-10, 1e-10), Catch::Contains("zeta"));
    CHECK_THROWS_AS(vb_from_zeta(1e300, 1e10, 1e10), UnitError);
    CHECK_THROWS_AS(rdisp_from_zss(1e300, 1e-300), UnitError);
    CHECK_THROWS_AS(zss_from_rdisp(1e300, 1e-300), UnitError);
    CHECK(zeta_from_vb(0, 0.7, 60) == 0);
}
