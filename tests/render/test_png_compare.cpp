#include "fv/gfx/compare.hpp"
#include "fv/gfx/png.hpp"

#include <catch2/catch.hpp>

using namespace fv::gfx;

static Image gradient(int w, int h) {
    Image img(w, h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            std::uint8_t* p = img.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(x * 7), p[1] = static_cast<std::uint8_t>(y * 11), p[2] = 128,
            p[3] = 255;
        }
    return img;
}

TEST_CASE("PNG encode/decode round-trips RGBA8 exactly") {
    const Image a = gradient(37, 23);
    const Image b = decode_png(encode_png(a));
    CHECK(b.width == 37);
    CHECK(b.height == 23);
    CHECK(b.rgba == a.rgba);
}

TEST_CASE("decode_png rejects garbage with a message") {
    const std::vector<unsigned char> junk = {1, 2, 3, 4};
    CHECK_THROWS_AS(decode_png(junk), std::runtime_error);
}

TEST_CASE("compare_images counts pixels beyond the channel threshold") {
    const Image a = gradient(10, 10);
    Image b = a;
    CHECK(compare_images(a, b, 0, 0.0).passed);
    b.pixel(3, 4)[1] = static_cast<std::uint8_t>(b.pixel(3, 4)[1] + 5);
    b.pixel(5, 5)[0] = static_cast<std::uint8_t>(b.pixel(5, 5)[0] + 1);
    const ImageComparison r = compare_images(b, a, 2, 0.0);
    CHECK(r.max_channel_diff == 5);
    CHECK(r.differing_share == Approx(0.01));
    CHECK_FALSE(r.passed);
    CHECK(r.diff.pixel(3, 4)[0] == 255);
    CHECK(r.diff.pixel(3, 4)[1] == 0);
    CHECK(compare_images(b, a, 2, 0.02).passed);
    CHECK_FALSE(compare_images(b, gradient(10, 11), 255, 1.0).passed); // Size mismatch never passes.
}

#include "fv/gfx/fonts.hpp"

TEST_CASE("a missing font file gives a one-line error") {
    FontSetOptions o;
    o.path = "/nonexistent/font.ttf";
    CHECK_THROWS_WITH(FontSet(o), Catch::Contains("font not found"));
}
