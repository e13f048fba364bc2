#include "fv/fit.hpp"
#include "fv/steady_state.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

namespace {

const std::string kData = FV_TEST_DATA_DIR;

} // namespace

TEST_CASE("fit: recovers r_disp = 3, i = 0 of the synthetic theta = 90 deg data (weighted)", "[fit][long]") {
    const fv::MeasurementSet data = fv::read_measurements(kData + "/synthetic_theta90_rdisp3_i0.csv");
    fv::FitOptions opt;
    opt.amplitude_um = 0.7;
    const fv::FitResult r = fv::fit_rdisp(data, opt);
    REQUIRE(r.candidates.size() == 2);
    const fv::FitCandidate& b = r.best;
    CHECK(b.i == 0);
    CHECK(b.weighted);
    CHECK(b.rdisp == Approx(3).epsilon(0.02));
    CHECK(std::abs(b.rdisp - 3) < 3 * b.rdisp_sigma); // the stated uncertainty is honest
    CHECK(b.rdisp_sigma > 0);
    CHECK(b.rdisp_sigma < 0.1);
    CHECK(b.dof == 15);
    CHECK(b.reduced_chi2 == Approx(1).margin(0.8)); // noise sigma matches the sigma column
    CHECK(b.converged);
    CHECK_FALSE(b.at_bound);
    CHECK(b.unsteady == 0);
    REQUIRE(b.residuals.size() == 16);
    for (std::size_t k = 0; k < 16; ++k) {
        CHECK(std::abs(b.residuals[k]) < 4 * 0.005);
        CHECK(b.residuals[k] == Approx(data.points[k].rx - b.model[k]));
    }
    REQUIRE(b.zss_um);
    CHECK(*b.zss_um == Approx(0.7 / b.rdisp));
    CHECK(*b.zss_um_sigma == Approx(*b.zss_um * b.rdisp_sigma / b.rdisp));
    // The other exponent fits clearly worse.
    const fv::FitCandidate& other = r.candidates[1];
    CHECK(other.i == 1);
    CHECK(other.aic > b.aic + 10);
    WARN("i=0: rdisp = " << b.rdisp << " +- " << b.rdisp_sigma << ", chi2 = " << b.chi2 << ", reduced "
                         << b.reduced_chi2 << ", evaluations " << b.evaluations
                         << "; i=1: rdisp = " << other.rdisp << ", chi2 = " << other.chi2);
}

TEST_CASE("fit: recovers r_disp = 1, i = 1 of the synthetic theta = 0 v_b data (unweighted)", "[fit]") {
    fv::ReadOptions ro;
    ro.amplitude_um = 0.7;
    ro.frequency_khz = 60;
    const fv::MeasurementSet data = fv::read_measurements(kData + "/synthetic_theta0_rdisp1_i1_vb.csv", ro);
    REQUIRE(data.from_vb);
    const fv::FitResult r = fv::fit_rdisp(data, {});
    const fv::FitCandidate& b = r.best;
    CHECK(b.i == 1);
    CHECK_FALSE(b.weighted);
    CHECK(b.rdisp == Approx(1).epsilon(0.02));
    CHECK(std::abs(b.rdisp - 1) < 3 * b.rdisp_sigma);
    // Unweighted: the uncertainty is scaled by the residual variance, which estimates the noise (0.005).
    CHECK(std::sqrt(b.reduced_chi2) == Approx(0.005).epsilon(0.5));
    CHECK_FALSE(b.zss_um);
    CHECK(r.candidates[0].aic > b.aic);
    WARN("i=1: rdisp = " << b.rdisp << " +- " << b.rdisp_sigma << ", RSS = " << b.chi2 << ", evaluations "
                         << b.evaluations << "; i=0: rdisp = " << r.candidates[0].rdisp
                         << ", RSS = " << r.candidates[0].chi2);
}

TEST_CASE("fit: one r_disp and i for points at two angles (the layout of the paper's Fig. 19)",
          "[fit][long]") {
    const fv::MeasurementSet data = fv::read_measurements(kData + "/synthetic_two_angles_rdisp2_i0.csv");
    REQUIRE(data.has_theta);
    REQUIRE(data.points.size() == 24);
    const fv::FitResult r = fv::fit_rdisp(data);
    const fv::FitCandidate& b = r.best;
    CHECK(b.i == 0);
    CHECK(b.rdisp == Approx(2).epsilon(0.02));
    CHECK(std::abs(b.rdisp - 2) < 3 * b.rdisp_sigma);
    CHECK(b.reduced_chi2 == Approx(1).margin(0.8));
    // Each point is held against the model at its own angle: the residuals are noise-sized at both angles
    // (at the other angle's curve they would not be: r_x(zeta = 0.5) is ~0.74 at 90 deg, ~0.6 at 0 deg).
    for (std::size_t k = 0; k < data.points.size(); ++k) CHECK(std::abs(b.residuals[k]) < 4 * 0.008);
}

TEST_CASE("fit: a fixed exponent fits only that one, and exact model data give the exact r_disp", "[fit]") {
    // Noise-free data from the model itself: the fit must land on the generating value (model noise 1e-5).
    fv::MeasurementSet data;
    for (double z : {0.1, 0.3, 0.6, 1.0}) {
        fv::Params p;
        p.zeta = z;
        p.theta = fv::kPi / 2;
        p.rdisp = 5;
        p.i = 1;
        fv::Measurement m;
        m.zeta = z;
        m.rx = fv::steady_ratio(fv::Model::dahl, p).rx;
        data.points.push_back(m);
    }
    fv::FitOptions opt;
    opt.theta_deg = 90;
    opt.shape = fv::ShapeChoice::i1;
    const fv::FitResult r = fv::fit_rdisp(data, opt);
    REQUIRE(r.candidates.size() == 1);
    CHECK(r.best.i == 1);
    CHECK(r.best.rdisp == Approx(5).epsilon(1e-3));
    CHECK(r.best.chi2 < 1e-8);
}

TEST_CASE("fit: bad inputs are FitErrors", "[fit]") {
    fv::MeasurementSet data;
    CHECK_THROWS_AS(fv::fit_rdisp(data, {}), fv::FitError);
    fv::Measurement m;
    m.zeta = 0.5;
    m.rx = 0.5;
    data.points.push_back(m);
    CHECK_THROWS_WITH(fv::fit_rdisp(data, {}), Catch::Contains("theta"));
    fv::FitOptions opt;
    opt.theta_deg = 200;
    CHECK_THROWS_WITH(fv::fit_rdisp(data, opt), Catch::Contains("[0, 180]"));
    opt.theta_deg = 90;
    opt.rdisp_min = 10;
    opt.rdisp_max = 1;
    CHECK_THROWS_AS(fv::fit_rdisp(data, opt), fv::FitError);
    opt.rdisp_min = 0.1;
    opt.rdisp_max = 100;
    opt.amplitude_um = -1;
    CHECK_THROWS_WITH(fv::fit_rdisp(data, opt), Catch::Contains("amplitude"));
}
