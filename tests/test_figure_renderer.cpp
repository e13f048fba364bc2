// The figures layer's public entry point (figures/figure_renderer.hpp, installed for frictionviz::figures): a
// registered figure by id, the picture limits, and the pictures' sizes read back from the files' own headers
// (PNG's IHDR, the SVG root's width/height, the PDF MediaBox), so that "size in pixels, page = size / scale
// in points" is what a consumer gets. That the bytes equal the command line's is the install_consumer test's.
#include "figures/figure_renderer.hpp"

#include <catch2/catch.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>

namespace {

using fv::app::PictureFormat;
using fv::app::PictureSize;

std::uint32_t big_endian(const std::string& s, std::size_t at) {
    std::uint32_t v = 0;
    for (std::size_t k = 0; k < 4; ++k) v = v << 8 | static_cast<unsigned char>(s[at + k]);
    return v;
}

} // namespace

TEST_CASE("registered_figure gives a registered figure's definition and names what is wrong", "[figures]") {
    CHECK(fv::app::registered_figure("fig5").id == "fig5");
    try {
        fv::app::registered_figure("fig99");
        FAIL("no exception for an unknown id");
    } catch (const std::invalid_argument& e) {
        CHECK_THAT(e.what(), Catch::Contains("fig99") && Catch::Contains("fig10"));
    }
    try {
        fv::app::registered_figure("scene"); // needs zeta, theta, rdisp, i
        FAIL("no exception for a missing input");
    } catch (const std::invalid_argument& e) {
        CHECK_THAT(e.what(), Catch::Contains("FigureInputs::zeta"));
    }
    fv::FigureInputs in;
    in.zeta = 0.3;
    in.theta_deg = {60};
    in.rdisp = {2};
    in.i = {1};
    CHECK(fv::app::registered_figure("scene", in).kind() == fv::FigureKind::scene);
    // A list where the figure takes one value: the same check as every other door's.
    in.theta_deg = {30, 60};
    CHECK_THROWS_WITH(fv::app::registered_figure("scene", in), Catch::Contains("theta_deg"));
}

TEST_CASE("picture_size_error holds the limits of render --size and --scale", "[figures]") {
    CHECK(fv::app::picture_size_error({}).empty());
    CHECK(fv::app::picture_size_error({320, 240, 1}).empty());
    CHECK(fv::app::picture_size_error({7680, 4320, 1}).empty());
    CHECK_THAT(fv::app::picture_size_error({319, 240, 1}),
               Catch::Contains("319x240") && Catch::Contains("[320"));
    CHECK_THAT(fv::app::picture_size_error({1280, 800, 0.2}),
               Catch::Contains("0.2") && Catch::Contains("0.25"));
    // 640x480 at scale 4 is a 160x120 page, smaller than the layout needs.
    CHECK_THAT(fv::app::picture_size_error({640, 480, 4}), Catch::Contains("160x120"));
    CHECK_THROWS_AS(fv::app::FigureRenderer(PictureSize{100, 100, 1}), std::invalid_argument);
}

TEST_CASE("FigureRenderer: PNG of size pixels, SVG and PDF pages of size / scale points", "[figures]") {
    const fv::FigureData fig6 = fv::compute_figure(fv::app::registered_figure("fig6"));
    fv::app::FigureRenderer renderer({1280, 800, 2});
    const std::string png = renderer.render(fig6, PictureFormat::png);
    REQUIRE(png.size() > 24);
    CHECK(png.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0);
    CHECK(png.compare(12, 4, "IHDR") == 0);
    CHECK(big_endian(png, 16) == 1280);
    CHECK(big_endian(png, 20) == 800);
    const std::string svg = renderer.render(fig6, PictureFormat::svg);
    CHECK(svg.rfind("<?xml", 0) == 0);
    CHECK_THAT(svg, Catch::Contains("width=\"640pt\" height=\"400pt\""));
    const std::string pdf = renderer.render(fig6, PictureFormat::pdf);
    CHECK(pdf.rfind("%PDF-", 0) == 0);
    CHECK_THAT(pdf, Catch::Contains("MediaBox [ 0 0 640 400 ]"));
    // The renderer is reused: the same figure again gives the same bytes. For the SVG too, although cairo
    // names its groups after a count of the surfaces the process created (the PDF above made some more).
    CHECK(renderer.render(fig6, PictureFormat::png) == png);
    CHECK(renderer.render(fig6, PictureFormat::svg) == svg);
    CHECK_THAT(svg, Catch::Contains("id=\"surface1\""));
    CHECK(std::string(fv::app::to_string(PictureFormat::pdf)) == "pdf");
}
