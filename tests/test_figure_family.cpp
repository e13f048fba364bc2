// Families of curves (fv/figure_family.hpp, the rx and ry figures): the lists as every door reads them, the
// combinations and their cap, the registry's verdict on lists, the legend naming only what varies, styles
// that keep every curve apart, the log axis, the data overlay; the rigid curves against Eq. (10).
#include "fv/figure_data.hpp"
#include "fv/figure_family.hpp"
#include "fv/figure_registry.hpp"
#include "fv/map_family.hpp"
#include "fv/measurements.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace {

constexpr double kPi = 3.14159265358979323846;

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

fv::FigureInputs family_inputs(std::vector<double> theta, std::vector<double> rdisp, std::vector<double> i,
                               std::vector<fv::Model> models = {fv::Model::dahl, fv::Model::rigid}) {
    fv::FigureInputs in;
    in.theta_deg = std::move(theta);
    in.rdisp = std::move(rdisp);
    in.i = std::move(i);
    in.models = std::move(models);
    return in;
}

// The curves' series of a family figure (the first spec.curves.size() series of its panel) without
// computing it: the styles alone.
std::vector<fv::SeriesData> styles_of(const fv::FigureInputs& in) {
    fv::FigureSpec spec = fv::find_registered("rx")->make(in);
    auto& c = std::get<fv::RatioCurvesFigure>(spec.content);
    c.zetas = {0.5}; // one point each: the styles do not depend on the values
    c.zeta_budget = 0;
    const fv::FigureData d = fv::compute_figure(spec, 1);
    return {d.panels.at(0).series.begin(),
            d.panels.at(0).series.begin() + static_cast<std::ptrdiff_t>(c.curves.size())};
}

} // namespace

TEST_CASE("Family lists: numbers through the shared reader, empty items, repeats and bad ranges refused",
          "[figures][family]") {
    std::vector<double> v;
    CHECK(fv::read_number_list("theta", "30,60,90", fv::kThetaRange, v).empty());
    CHECK(v == std::vector<double>{30, 60, 90});
    CHECK(fv::read_number_list("theta", "-0", fv::kThetaRange, v).empty());
    CHECK(v == std::vector<double>{0});
    for (const char* bad : {"30,,60", "30,", ",30", ""})
        CHECK(has(fv::read_number_list("theta", bad, fv::kThetaRange, v), "empty item"));
    CHECK(has(fv::read_number_list("theta", "30,60,30", fv::kThetaRange, v), "30 twice (items 1 and 3)"));
    CHECK(has(fv::read_number_list("theta", "30,3e1", fv::kThetaRange, v), "twice"));
    CHECK(has(fv::read_number_list("theta", "30,200", fv::kThetaRange, v), "out of range"));
    CHECK(has(fv::read_number_list("rdisp", "0", fv::kRdispRange, v), "(0, 10000]"));
    CHECK(has(fv::read_number_list("i", "0x1", fv::kIRange, v), "not a decimal number"));
    CHECK(has(fv::read_number_list("i", "nan", fv::kIRange, v), "not a decimal number"));
    CHECK(has(fv::check_number_list("i", {}, fv::kIRange), "empty list"));
    CHECK(v == std::vector<double>{0}); // untouched by the refused ones

    std::vector<fv::Model> m;
    CHECK(fv::read_model_list("model", "rigid,dahl", m).empty());
    CHECK(m == std::vector<fv::Model>{fv::Model::rigid, fv::Model::dahl});
    CHECK(has(fv::read_model_list("model", "dahl,dahl", m), "dahl twice"));
    CHECK(has(fv::read_model_list("model", "dahl,soft", m), "'soft' is not a model; allowed: dahl, rigid"));
    CHECK(has(fv::read_model_list("model", "dahl,", m), "empty item"));

    fv::ZetaSpan s;
    CHECK(fv::read_zeta_span("zeta", "0.01:10", s).empty());
    CHECK((s.from == 0.01 && s.to == 10));
    CHECK(has(fv::read_zeta_span("zeta", "10:0.01", s), "reversed"));
    CHECK(has(fv::read_zeta_span("zeta", "1:1", s), "empty"));
    CHECK(has(fv::read_zeta_span("zeta", "0.5", s), "not a range"));
    CHECK(has(fv::read_zeta_span("zeta", "0:1:5", s), "not a range"));
    CHECK(has(fv::read_zeta_span("zeta", "0:200", s), "out of range"));
    CHECK(has(fv::read_zeta_span("zeta", "a:1", s), "not a decimal number"));
    // Every message is one line that names the parameter.
    for (const std::string& msg :
         {fv::read_number_list("theta", "1,,2", fv::kThetaRange, v), fv::read_zeta_span("zeta", "3:1", s),
          fv::read_model_list("model", "x", m)}) {
        CHECK(msg.find('\n') == std::string::npos);
        CHECK((has(msg, "theta") || has(msg, "zeta") || has(msg, "model")));
    }
}

TEST_CASE("Family curves: one per combination, the rigid ones once per angle, at most 12",
          "[figures][family]") {
    fv::FigureFamily f;
    f.theta_deg = {30, 60};
    f.rdisp = {1, 3, 10};
    f.i = {0.5, 1};
    const std::vector<fv::Curve> curves = fv::family_curves(f);
    REQUIRE(curves.size() == 2 * 3 * 2 + 2);
    std::set<std::tuple<int, double, double, double>> distinct;
    for (const fv::Curve& c : curves) distinct.insert({static_cast<int>(c.model), c.theta, c.rdisp, c.i});
    CHECK(distinct.size() == curves.size());
    CHECK(curves.back().model == fv::Model::rigid);
    CHECK(curves.back().theta == Approx(60 * kPi / 180));
    CHECK(has(fv::family_size_error(f), "= 14 curves; allowed: at most 12"));
    f.i = {0.5};
    CHECK(fv::family_size_error(f).empty()); // 6 + 2
    f.models = {fv::Model::rigid};
    CHECK(fv::family_curves(f).size() == 2); // r_disp and i do not apply
}

TEST_CASE("Registry: lists only where a figure takes them, checked as a spec file or Python gives them",
          "[figures][family]") {
    auto key = [](fv::FigureParam p) { return std::string(fv::param_key(p)); };
    const fv::FigureEntry& scene = *fv::find_registered("scene");
    fv::FigureInputs in = family_inputs({30, 60}, {2}, {1});
    in.zeta = 0.3;
    CHECK(fv::input_error(scene, in, key) == "theta has 2 values; scene takes one (lists: rx, ry)");
    const fv::FigureEntry& map = *fv::find_registered("map");
    CHECK(fv::input_error(map, family_inputs({}, {1, 2}, {1}, {}), key).empty()); // a family of maps
    const fv::FigureEntry& rx = *fv::find_registered("rx");
    CHECK(fv::input_error(rx, family_inputs({30, 60}, {1, 3, 10}, {0.5, 1}, {fv::Model::dahl}), key)
              .empty()); // 12
    CHECK(has(fv::input_error(rx, family_inputs({30, 60, 90}, {1, 3, 10}, {0.5, 1}), key), "at most 12"));
    CHECK(has(fv::input_error(rx, family_inputs({30, 30}, {1}, {1}), key), "theta has 30 twice"));
    CHECK(has(fv::input_error(rx, family_inputs({30}, {-1}, {1}), key), "rdisp = -1 is out of range"));
    fv::FigureInputs reversed = family_inputs({30}, {1}, {1});
    reversed.zeta_span = fv::ZetaSpan{3, 1};
    CHECK(has(fv::input_error(rx, reversed, key), "reversed"));
    // Defaults fill what is not given; given values win.
    const fv::FigureInputs d = fv::with_defaults(rx, family_inputs({}, {5}, {}));
    CHECK(d.theta_deg == std::vector<double>{45});
    CHECK(d.rdisp == std::vector<double>{5});
    CHECK(d.zeta_span == fv::kPaperZetaSpan);
}

TEST_CASE("rx: the legend names what varies and the title what does not, every curve in its own style",
          "[figures][family]") {
    // The README's example: theta and i fixed, three r_disp and the rigid curve.
    const fv::FigureSpec spec = fv::find_registered("rx")->make({});
    CHECK(spec.title == "friction ratio r_{x}(ζ), Dahl (i = 0.5) and rigid, θ = 45°");
    std::vector<std::string> labels;
    for (const fv::SeriesData& s : styles_of({})) labels.push_back(s.label);
    CHECK(labels == std::vector<std::string>{"r_{disp} = 1", "r_{disp} = 3", "r_{disp} = 10", "rigid"});

    // Two angles and two r_disp: both named; the angle by the dash, the same dash for the rigid curve.
    const std::vector<fv::SeriesData> two = styles_of(family_inputs({30, 60}, {1, 3}, {1}));
    REQUIRE(two.size() == 6);
    CHECK(two[0].label == "θ = 30°, r_{disp} = 1");
    CHECK(two[5].label == "θ = 60°, rigid");
    CHECK(two[0].palette == two[2].palette); // r_disp = 1 at both angles
    CHECK(two[0].dash != two[2].dash);
    CHECK(two[5].dash == two[2].dash); // rigid at 60 as Dahl at 60

    // One curve: no legend entry, the title says it all.
    CHECK(styles_of(family_inputs({45}, {2}, {1}, {fv::Model::dahl})).at(0).label.empty());

    // Families of 1 to 12 curves of every shape: no two curves look alike, no two labels are the same.
    for (const fv::FigureInputs& in :
         {family_inputs({10, 20, 30, 40, 50, 60}, {2}, {1}),
          family_inputs({45}, {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}, {1}, {fv::Model::dahl}),
          family_inputs({30, 60}, {1, 3}, {0.5, 1}, {fv::Model::dahl}),
          family_inputs({30, 60, 90}, {1, 3, 10}, {1}),
          family_inputs({0, 30, 60, 90}, {2}, {1}, {fv::Model::rigid}),
          family_inputs({45}, {1, 3}, {0, 0.5, 1})}) {
        const std::vector<fv::SeriesData> s = styles_of(in);
        std::set<std::tuple<int, int, int>> looks;
        std::set<std::string> names;
        for (const fv::SeriesData& c : s) {
            looks.insert({static_cast<int>(c.ink), c.palette, static_cast<int>(c.dash)});
            names.insert(c.label);
        }
        CAPTURE(s.size());
        CHECK(looks.size() == s.size());
        CHECK(names.size() == s.size());
    }
}

TEST_CASE("rx: rigid curves are Eq. (10) at theta = 0, over a log axis that spans exactly --zeta",
          "[figures][family]") {
    fv::FigureInputs in = family_inputs({0}, {2}, {1}, {fv::Model::rigid});
    in.zeta_span = fv::ZetaSpan{0.01, 10};
    const fv::FigureData d = fv::compute_figure(fv::find_registered("rx")->make(in));
    const fv::PanelData& p = d.panels.at(0);
    CHECK(p.log_x);
    CHECK(*p.x_min == 0.01);
    CHECK(*p.x_max == 10);
    const fv::SeriesData& s = p.series.at(0);
    REQUIRE(s.x.size() > 40);
    CHECK(s.x.front() == 0.01);
    CHECK(s.x.back() == 10);
    for (std::size_t k = 0; k < s.x.size(); ++k) {
        const double z = s.x[k], eq10 = z < 1 ? 2 / kPi * std::asin(z) : 1.0;
        CHECK(s.y[k] == Approx(eq10).margin(1e-9));
    }
    // Linear below two decades.
    in.zeta_span = fv::ZetaSpan{0.1, 9};
    CHECK_FALSE(std::get<fv::RatioCurvesFigure>(fv::find_registered("rx")->make(in).content).log_zeta);
}

TEST_CASE("rx: --data draws the file's points over the curves, one marker per angle", "[figures][family]") {
    fv::FigureInputs in = family_inputs({0, 90}, {2}, {0}, {fv::Model::rigid});
    in.data = std::string(FV_TEST_DATA_DIR) + "/synthetic_two_angles_rdisp2_i0.csv";
    const fv::MeasurementSet file = fv::read_measurements(in.data);
    fv::FigureSpec spec = fv::find_registered("rx")->make(in);
    CHECK(has(spec.caption, "synthetic example data"));
    auto& c = std::get<fv::RatioCurvesFigure>(spec.content);
    c.zetas = {0.5};
    c.zeta_budget = 0;
    const fv::FigureData d = fv::compute_figure(spec, 1);
    std::size_t points = 0, series = 0;
    for (const fv::SeriesData& s : d.panels.at(0).series)
        if (s.label.rfind("synthetic data", 0) == 0) {
            ++series;
            points += s.x.size();
            CHECK(s.width == 0);
        }
    CHECK(series == 2);
    CHECK(points == file.points.size());
}

TEST_CASE("Map families: one map per combination on a grid, titles naming what varies, at most 6 maps",
          "[figures][family][map]") {
    fv::MapFamily f;
    f.rdisp = {1, 3, 10};
    f.i = {0.5, 1};
    // Rows of i, columns of r_disp; each panel titled with both (both vary), the figure with neither.
    const std::vector<fv::MapPanelSpec> panels = fv::map_family_panels(f);
    REQUIRE(panels.size() == 6);
    CHECK(panels[0].rdisp == 1);
    CHECK(panels[0].i == 0.5);
    CHECK(panels[2].rdisp == 10);
    CHECK(panels[3].i == 1);
    CHECK(panels[4].title == "r_{disp} = 3, i = 1");
    fv::FigureSpec spec = fv::map_family_figure(f);
    const auto& m = std::get<fv::MapFigure>(spec.content);
    CHECK(m.columns == 3);
    CHECK(m.family.size() == 6);
    CHECK(spec.title == "friction ratio r_{x}(ζ, θ), Dahl model");
    CHECK(fv::map_family_size_error(f).empty());
    // More values of i than of r_disp: i along the rows (the grid wider than tall, as the page).
    fv::MapFamily t;
    t.rdisp = {1, 3};
    t.i = {0.5, 1, 2};
    const std::vector<fv::MapPanelSpec> across = fv::map_family_panels(t);
    REQUIRE(across.size() == 6);
    CHECK((across[1].rdisp == 1 && across[1].i == 1));
    CHECK((across[3].rdisp == 3 && across[3].i == 0.5));
    CHECK(std::get<fv::MapFigure>(fv::map_family_figure(t).content).columns == 3);
    // The rigid model adds one map (r_disp and i do not apply): 7 is over the cap, named in one line.
    f.models = {fv::Model::dahl, fv::Model::rigid};
    CHECK(fv::map_family_size_error(f) ==
          "r_disp 3 × i 2 = 6 Dahl maps + 1 rigid = 7 maps; allowed: at most 6 maps in one figure (each is "
          "200 × 91 steady states; split the family into several figures)");
    f.i = {1};
    const std::vector<fv::MapPanelSpec> with_rigid = fv::map_family_panels(f);
    REQUIRE(with_rigid.size() == 4);
    CHECK(with_rigid[0].title == "Dahl, r_{disp} = 1");
    CHECK(with_rigid[3].model == fv::Model::rigid);
    CHECK(std::isnan(with_rigid[3].rdisp));
    CHECK(std::get<fv::MapFigure>(fv::map_family_figure(f).content).columns == 2); // 2 x 2
    CHECK(fv::map_family_figure(f).title == "friction ratio r_{x}(ζ, θ), Dahl model (i = 1) and rigid model");
    // One Dahl map is the map as it was before families: no family, the same title and caption.
    fv::MapFamily single;
    single.rdisp = {2};
    single.i = {1};
    const fv::FigureSpec a = fv::map_family_figure(single), b = fv::map_figure(2, 1);
    CHECK(std::get<fv::MapFigure>(a.content).family.empty());
    CHECK(a.title == b.title);
    CHECK(a.caption == b.caption);
    // Through the registry, as every door gives the inputs.
    const fv::FigureEntry& map = *fv::find_registered("map");
    auto key = [](fv::FigureParam p) { return std::string(fv::param_key(p)); };
    fv::FigureInputs seven;
    seven.rdisp = {1, 2, 3, 4, 5, 6, 7};
    CHECK(has(fv::input_error(map, seven, key), "= 7 maps; allowed: at most 6"));
}

TEST_CASE("Map families: one colour scale over every map, the rigid map's cells Eq. (10) at theta = 0",
          "[figures][family][map]") {
    fv::MapFamily f;
    f.rdisp = {1, 10};
    f.models = {fv::Model::dahl, fv::Model::rigid};
    fv::FigureSpec spec = fv::map_family_figure(f);
    auto& m = std::get<fv::MapFigure>(spec.content);
    m.zetas = {0.25, 0.5, 1.5}; // a coarse grid: the structure, not the picture
    m.theta_count = 4;
    m.theta_max_deg = 90;
    const fv::FigureData d = fv::compute_figure(spec, 1);
    REQUIRE(d.panels.size() == 3);
    CHECK(d.columns == 3);
    double lo = 1e9, hi = -1e9;
    for (const fv::PanelData& p : d.panels)
        for (double v : p.heatmap->values) lo = std::min(lo, v), hi = std::max(hi, v);
    for (const fv::PanelData& p : d.panels) {
        REQUIRE(p.heatmap);
        CHECK(p.heatmap->vmin == lo);
        CHECK(p.heatmap->vmax == hi);
        CHECK_FALSE(p.heatmap->color_bar);
    }
    // The rigid map: theta = 0 is its first row, r_x = (2/pi) asin(zeta) below zeta = 1 and 1 above (Eq. 10);
    // its only theta* line is the rigid one (dashed).
    const fv::HeatmapData& rigid = *d.panels[2].heatmap;
    CHECK(rigid.values[0] == Approx(2 / kPi * std::asin(0.25)).margin(1e-10));
    CHECK(rigid.values[1] == Approx(2 / kPi * std::asin(0.5)).margin(1e-10));
    CHECK(rigid.values[2] == Approx(1).margin(1e-10));
    CHECK(d.panels[2].series.at(0).dash == fv::Dash::dashed);
    CHECK(d.panels[0].series.at(0).dash == fv::Dash::solid);
    // Tables: every map's grid in one (model, rdisp and i columns say which), the best angles with the
    // varying inputs in front.
    REQUIRE(d.tables.size() == 2);
    CHECK(d.tables[0].ratios.size() == 3 * 3 * 4);
    CHECK(d.tables[0].ratios.back().model == fv::Model::rigid);
    CHECK(d.tables[1].suffix == "-best-angle");
    CHECK(d.tables[1].text.rfind("model,rdisp,zeta,theta_star_deg,", 0) == 0);
    CHECK(has(d.tables[1].text, "\ndahl,10,0.5,"));
    CHECK(has(d.tables[1].text, "\nrigid,,1.5,"));
}
