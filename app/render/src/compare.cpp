#include "fv/gfx/compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace fv::gfx {

ImageComparison compare_images(const Image& actual, const Image& expected, int max_channel_diff,
                               double max_diff_share) {
    ImageComparison r;
    if (actual.width != expected.width || actual.height != expected.height) {
        r.same_size = false;
        r.max_channel_diff = 255;
        r.differing_share = 1.0;
        r.passed = false;
        return r;
    }
    r.diff = Image(expected.width, expected.height);
    std::size_t differing = 0;
    const std::size_t npx =
        static_cast<std::size_t>(expected.width) * static_cast<std::size_t>(expected.height);
    for (std::size_t i = 0; i < npx; ++i) {
        const std::uint8_t* a = &actual.rgba[i * 4];
        const std::uint8_t* e = &expected.rgba[i * 4];
        int d = 0;
        for (int c = 0; c < 4; ++c) d = std::max(d, std::abs(int(a[c]) - int(e[c])));
        r.max_channel_diff = std::max(r.max_channel_diff, d);
        std::uint8_t* o = &r.diff.rgba[i * 4];
        if (d > max_channel_diff) {
            ++differing;
            o[0] = 255, o[1] = 0, o[2] = 0;
        } else {
            // Faint greyscale of the expected image as context.
            const int lum = (299 * e[0] + 587 * e[1] + 114 * e[2]) / 1000;
            const auto g = static_cast<std::uint8_t>(191 + lum / 4);
            o[0] = o[1] = o[2] = g;
        }
        o[3] = 255;
    }
    r.differing_share = npx ? static_cast<double>(differing) / static_cast<double>(npx) : 0.0;
    r.passed = r.differing_share <= max_diff_share;
    return r;
}

} // namespace fv::gfx
