// The app's physical units and measured data, without a window: the state changes the panel, the File menu,
// a drop and the script all lead to (measured_data.hpp), the ratio plot they produce (dashboard.hpp) and
// the script actions (script.hpp). Expected values come from the formulas, not from the code under test.
#include "gui/dashboard.hpp"
#include "gui/measured_data.hpp"
#include "gui/script.hpp"

#include "fv/figures.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>

using namespace fv;
using namespace fv::app;

namespace {

constexpr double kTwoPi = 2 * 3.14159265358979323846;

// v_v in m/s from um and kHz, written out here rather than taken from fv::units.
double vv(double amplitude_um, double frequency_khz) {
    return kTwoPi * (frequency_khz * 1e3) * (amplitude_um * 1e-6);
}

std::string write_temp(const std::string& name, const std::string& text) {
    static const std::string dir = [] {
        char tmpl[] = "/tmp/fv-gui-data-XXXXXX";
        return std::string(::mkdtemp(tmpl));
    }();
    const std::string path = dir + "/" + name;
    std::ofstream(path) << text;
    return path;
}

// The v_b column of a data file, read here with a plain parser (header "vb,..." and '#' comments).
std::vector<double> vb_column(const std::string& path) {
    std::ifstream in(path);
    std::string line;
    std::vector<double> v;
    bool header = true;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        if (header) {
            REQUIRE(line.rfind("vb,", 0) == 0);
            header = false;
            continue;
        }
        v.push_back(std::stod(line.substr(0, line.find(','))));
    }
    return v;
}

const std::string kVbFile = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta0_rdisp1_i1_vb.csv";
const std::string kZetaFile = std::string(FV_TEST_DATA_DIR) + "/synthetic_theta90_rdisp3_i0.csv";

} // namespace

TEST_CASE("app units: a new amplitude or frequency keeps v_b and z_ss, zeta and r_disp follow",
          "[gui][units]") {
    UiState ui;
    ui.session.params.zeta = 0.3;
    ui.session.params.rdisp = 2;
    ui.session.amplitude_um = 0.7;
    ui.session.frequency_khz = 60;
    const double vb = 0.3 * vv(0.7, 60), zss = 0.7 / 2;
    CHECK(vb_of(ui) == Approx(vb).epsilon(1e-14));
    CHECK(zss_of(ui) == Approx(zss).epsilon(1e-14));

    REQUIRE(set_vibration(ui, 1.4, std::nullopt).empty());
    CHECK(ui.session.params.zeta == Approx(vb / vv(1.4, 60)).epsilon(1e-14)); // = 0.15
    CHECK(ui.session.params.zeta == Approx(0.15).epsilon(1e-14));
    CHECK(ui.session.params.rdisp == Approx(1.4 / zss).epsilon(1e-14)); // = 4
    REQUIRE(set_vibration(ui, std::nullopt, 20).empty());
    CHECK(ui.session.params.zeta == Approx(vb / vv(1.4, 20)).epsilon(1e-14));
    CHECK(ui.session.params.rdisp == Approx(4).epsilon(1e-14)); // z_ss does not depend on f
    CHECK(vb_of(ui) == Approx(vb).epsilon(1e-13));

    SECTION("a result outside the ranges changes nothing and says why") {
        const UiState before = ui;
        const std::string err = set_vibration(ui, 1e-6, std::nullopt); // zeta ~ 1e5
        CHECK(err.find("zeta") != std::string::npos);
        CHECK(err.find("[0, 100]") != std::string::npos);
        CHECK(ui.session.amplitude_um == before.session.amplitude_um);
        CHECK(ui.session.params.zeta == before.session.params.zeta);
        CHECK(ui.session.params.rdisp == before.session.params.rdisp);
        CHECK(!set_vibration(ui, 1e300, 1e300).empty()); // v_v overflows
        CHECK(ui.session.amplitude_um == before.session.amplitude_um);
    }
}

TEST_CASE("app data: a v_b file is converted with the app's A and f, and again when they change",
          "[gui][data]") {
    UiState ui;
    const std::vector<double> vbs = vb_column(kVbFile);
    REQUIRE(vbs.size() == 16);
    const std::string status = load_measured(ui, kVbFile);
    REQUIRE(ui.data);
    CHECK(status.find("16 points") != std::string::npos);
    CHECK(status.find("A = 0.7 µm, f = 60 kHz") != std::string::npos);
    REQUIRE(ui.data->points.size() == vbs.size());
    for (std::size_t k = 0; k < vbs.size(); ++k)
        CHECK(ui.data->points[k].zeta == Approx(vbs[k] / vv(0.7, 60)).epsilon(1e-14));

    REQUIRE(set_vibration(ui, 0.35, 120).empty());
    for (std::size_t k = 0; k < vbs.size(); ++k)
        CHECK(ui.data->points[k].zeta == Approx(vbs[k] / vv(0.35, 120)).epsilon(1e-14));

    SECTION("a zeta file does not depend on A and f") {
        load_measured(ui, kZetaFile);
        REQUIRE(ui.data);
        const double z0 = ui.data->points.front().zeta;
        REQUIRE(set_vibration(ui, 2.0, std::nullopt).empty());
        CHECK(ui.data->points.front().zeta == z0);
    }
    SECTION("an A that would put a point past zeta = 100 is refused with the file's line") {
        const std::string err = set_vibration(ui, 1e-5, std::nullopt);
        CHECK(!err.empty());
        CHECK(ui.session.amplitude_um == 0.35);
        CHECK(ui.data->points.front().zeta == Approx(vbs[0] / vv(0.35, 120)).epsilon(1e-14));
    }
}

TEST_CASE("app data: a malformed or missing file keeps what was shown and names file, line and column",
          "[gui][data]") {
    UiState ui;
    load_measured(ui, kZetaFile);
    REQUIRE(ui.data);
    const std::string bad = write_temp("bad.csv", "zeta,r_x\n0.1,0.5\n0.2,abc\n");
    const std::string err = load_measured(ui, bad);
    CHECK(err.rfind(bad + ":3:5: ", 0) == 0);
    CHECK(err.find('\n') == std::string::npos);
    REQUIRE(ui.data);
    CHECK(ui.data->file == kZetaFile);
    CHECK(load_measured(ui, "/nonexistent/x.csv").rfind("/nonexistent/x.csv: does not exist", 0) == 0);
    CHECK(load_measured(ui, write_temp("empty.csv", "zeta,r_x\n")).find("no data rows") != std::string::npos);
    CHECK(ui.data->file == kZetaFile);
}

TEST_CASE("app ratio plot: measured points with error bars, faded at another angle, axes widened to show "
          "them",
          "[gui][data]") {
    const std::string path = write_temp("pts.csv", "zeta,r_x,sigma,theta_deg\n"
                                                   "0.5,0.6,0.02,90\n"
                                                   "1.0,0.8,0.03,90\n"
                                                   "5.0,1.3,0.05,0\n");
    const MeasurementSet d = read_measurements(path);
    RatioCurves c;
    c.request.params = Params{0.5, kPi / 2, 2, 1};
    c.zetas = {0.1, 1, 5.25};
    c.model_rx = {0.2, 0.8, 0.99};
    c.rigid_rx = {0.1, 0.7, 0.99};
    const PanelData p = ratio_panel_live(c, false, {&d, 0.2639});
    std::vector<const SeriesData*> measured;
    for (const SeriesData& s : p.series)
        if (s.label.find("measured") == 0) measured.push_back(&s);
    REQUIRE(measured.size() == 2);
    CHECK(measured[0]->x == std::vector<double>{0.5, 1.0});
    CHECK(measured[0]->y_err == std::vector<double>{0.02, 0.03});
    CHECK(measured[0]->opacity == 1.0f);
    CHECK(measured[1]->x == std::vector<double>{5.0});
    CHECK(measured[1]->opacity < 0.5f);
    CHECK(p.x_max == Approx(5.25)); // 5 % past the furthest point
    CHECK(*p.y_max >= 1.3 + 0.05);  // the point and its error bar
    CHECK(p.x_title.find("v_{v} = 0.264 m/s") != std::string::npos);
    CHECK(ratio_zeta_max(&d) == Approx(5.25));
    CHECK(ratio_zeta_max(nullptr) == 3);

    // Without data the plot is the plain [0, 3] x [0, 1.05] one.
    const PanelData q = ratio_panel_live(c, false);
    CHECK(q.x_max == 3);
    CHECK(*q.y_max == 1.05);
    for (const SeriesData& s : q.series) CHECK(s.label.find("measured") == std::string::npos);
}

TEST_CASE("app ratio plot: a failed steady state is marked NOT VERIFIED, failed curve points are gaps",
          "[gui][status]") {
    RatioCurves c;
    c.request.params = Params{0.5, kPi / 2, 2, 1};
    c.zetas = {0.1, 0.5, 1};
    c.model_rx = {0.2, std::nan(""), 0.8}; // as the worker leaves a failed point
    c.model_failed = 1;
    c.rigid_rx = {0.1, 0.4, 0.7};
    c.current.rx = 0.45;
    c.current.status = SteadyStatus::not_converged;
    PanelData p = ratio_panel_live(c, false);
    CHECK(p.title.find("NOT VERIFIED: not_converged") != std::string::npos);
    REQUIRE(!p.series.empty());
    CHECK(p.series[0].label.find("1 failed points not drawn") != std::string::npos);
    CHECK(std::isnan(p.series[0].y[1]));
    REQUIRE(p.points.size() == 1);
    CHECK(p.points[0].mark == Mark::cross);
    // A converged result that is not a finite number is not verified either.
    c.current.status = SteadyStatus::converged;
    c.current.ry = std::nan("");
    CHECK(shown_status(c.current) == SteadyStatus::non_finite);
    CHECK(ratio_panel_live(c, false).title.find("NOT VERIFIED: non_finite") != std::string::npos);
    // Verified: no badge, the diamond.
    c.current.ry = 0;
    c.model_failed = 0;
    p = ratio_panel_live(c, false);
    CHECK(p.title.find("NOT VERIFIED") == std::string::npos);
    CHECK(p.points[0].mark == Mark::diamond);
}

TEST_CASE("ratio_zeta_grid reaches zeta_max past 3 in at most 40 more increasing steps", "[gui][data]") {
    const std::vector<double> base = ratio_zeta_grid();
    CHECK(base.back() == Approx(3));
    for (double zmax : {3.0, 3.05, 5.25, 100.0}) {
        const std::vector<double> g = ratio_zeta_grid(zmax);
        REQUIRE(g.size() >= base.size());
        CHECK(g.size() <= base.size() + 40);
        CHECK(std::equal(base.begin(), base.end(), g.begin()));
        CHECK(g.back() == Approx(zmax));
        for (std::size_t k = 1; k < g.size(); ++k) CHECK(g[k] > g[k - 1]);
    }
}

TEST_CASE("app script: unit and data actions, checked when loaded", "[gui][script]") {
    const std::string good = write_temp("good.txt", "0 amplitude 1.4\n"
                                                    "0 frequency 30\n"
                                                    "1 vb 0.1\n"
                                                    "1 zss 0.5\n"
                                                    "2 load pts.csv\n"
                                                    "3 fit\n"
                                                    "4 clear\n");
    const Script s = load_script(good);
    UiState ui;
    ui.session.amplitude_um = 1.4;
    ui.session.frequency_khz = 30;
    const UiEdits e0 = script_edits(s, 0, ui);
    CHECK(e0.amplitude_um == 1.4);
    CHECK(e0.frequency_khz == 30);
    // v_b and z_ss go to the edits' own fields: AppState::sync converts them with the A and f in effect
    // before the frame's A and f edits, as for the panel's inputs.
    const UiEdits e1 = script_edits(s, 1, ui);
    CHECK(e1.vb_m_s == 0.1);
    CHECK(e1.zss_um == 0.5);
    CHECK_FALSE(e1.params);
    const UiEdits e2 = script_edits(s, 2, ui);
    REQUIRE(e2.load_data);
    CHECK(*e2.load_data == good.substr(0, good.rfind('/')) + "/pts.csv"); // next to the script
    CHECK(script_edits(s, 3, ui).fit_data);
    CHECK(script_edits(s, 4, ui).clear_data);

    for (const char* bad : {"0 amplitude 0\n", "0 frequency -1\n", "0 zss 0\n", "0 vb -0.1\n", "0 vb x\n",
                            "0 load\n", "0 fit now\n"}) {
        const std::string path = write_temp("bad.txt", bad);
        CHECK_THROWS_WITH(load_script(path), Catch::StartsWith(path + ":1: "));
    }
}

TEST_CASE("app fit: r_disp and i of the synthetic data are set, off the UI thread", "[gui][fit]") {
    UiState ui;
    ui.session.params.theta = kPi / 2; // the file has theta_deg = 90 per point anyway
    load_measured(ui, kZetaFile);
    REQUIRE(ui.data);
    DataFit fit;
    fit.start(ui);
    CHECK(fit.running());
    const auto done = fit.poll(ui, true);
    REQUIRE(done);
    CHECK(!fit.running());
    REQUIRE(done->params);
    // Generated with r_disp = 3 and i = 0 (tests/data/make_synthetic.cpp).
    CHECK(done->params->rdisp == Approx(3).epsilon(0.02));
    CHECK(done->params->i == 0);
    CHECK(done->params->zeta == ui.session.params.zeta);
    CHECK(done->status.find("r_disp = ") != std::string::npos);
    CHECK(done->status.find("z_ss = ") != std::string::npos);
    CHECK(!fit.poll(ui, true)); // nothing more to collect
}
