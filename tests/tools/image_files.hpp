// PNG files and 2x2 downsampling for the tests that compare pictures (Catch2 REQUIREs inside).
#pragma once

#include "fv/gfx/image.hpp"
#include "fv/gfx/png.hpp"

#include <catch2/catch.hpp>

#include <fstream>
#include <iterator>
#include <string>

namespace fv::test {

inline gfx::Image load_png(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
    REQUIRE_FALSE(bytes.empty());
    return gfx::decode_png(reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
}

inline void write_png(const std::string& path, const gfx::Image& img) {
    const auto bytes = gfx::encode_png(img);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

// Mean of each 2x2 block.
inline gfx::Image half(const gfx::Image& a) {
    gfx::Image h(a.width / 2, a.height / 2);
    for (int y = 0; y < h.height; ++y)
        for (int x = 0; x < h.width; ++x)
            for (int c = 0; c < 4; ++c) {
                const int s = a.pixel(2 * x, 2 * y)[c] + a.pixel(2 * x + 1, 2 * y)[c] +
                              a.pixel(2 * x, 2 * y + 1)[c] + a.pixel(2 * x + 1, 2 * y + 1)[c];
                h.pixel(x, y)[c] = static_cast<std::uint8_t>((s + 2) / 4);
            }
    return h;
}

} // namespace fv::test
