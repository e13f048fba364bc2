// fv_png_compare ACTUAL EXPECTED [MAX_CHANNEL_DIFF MAX_SHARE [DIFF.png [X,Y,W,H]]]: exit 0 if the images
// match within the tolerance (default: identical), else 1 with a one-line report. Used by the
// window-vs-headless test. X,Y,W,H: compare only that rectangle of both (a page's static part where the rest
// moves).
#include "fv/gfx/compare.hpp"
#include "fv/gfx/png.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace {
std::vector<unsigned char> read(const char* path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw std::runtime_error(std::string("cannot read ") + path);
    return {std::istreambuf_iterator<char>(f), std::istreambuf_iterator<char>()};
}

fv::gfx::Image crop(const fv::gfx::Image& im, const std::string& rect) {
    int x = 0, y = 0, w = 0, h = 0;
    if (std::sscanf(rect.c_str(), "%d,%d,%d,%d", &x, &y, &w, &h) != 4 || x < 0 || y < 0 || w <= 0 || h <= 0 ||
        x + w > im.width || y + h > im.height)
        throw std::runtime_error("region " + rect + " is not X,Y,W,H inside the " + std::to_string(im.width) +
                                 "x" + std::to_string(im.height) + " image");
    fv::gfx::Image out(w, h);
    for (int r = 0; r < h; ++r)
        std::copy_n(im.pixel(x, y + r), static_cast<std::size_t>(w) * 4, out.pixel(0, r));
    return out;
}
} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(
            stderr,
            "usage: fv_png_compare ACTUAL EXPECTED [MAX_CHANNEL_DIFF MAX_SHARE [DIFF.png [X,Y,W,H]]]\n");
        return 2;
    }
    try {
        const int max_diff = argc > 3 ? std::atoi(argv[3]) : 0;
        const double max_share = argc > 4 ? std::atof(argv[4]) : 0.0;
        auto a = fv::gfx::decode_png(read(argv[1])), b = fv::gfx::decode_png(read(argv[2]));
        if (argc > 6) a = crop(a, argv[6]), b = crop(b, argv[6]);
        const auto cmp = fv::gfx::compare_images(a, b, max_diff, max_share);
        std::printf("%s vs %s: max channel difference %d, %.4f%% of pixels differ -> %s\n", argv[1], argv[2],
                    cmp.max_channel_diff, 100 * cmp.differing_share, cmp.passed ? "match" : "DIFFER");
        if (!cmp.passed && argc > 5 && !cmp.diff.empty()) {
            const auto png = fv::gfx::encode_png(cmp.diff);
            std::ofstream(argv[5], std::ios::binary)
                .write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
        }
        return cmp.passed ? 0 : 1;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fv_png_compare: %s\n", e.what());
        return 2;
    }
}
