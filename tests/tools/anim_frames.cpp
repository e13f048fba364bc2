// fv_anim_frames FILE.gif|FILE.mp4 OUTDIR [STEP]: writes every STEP-th decoded frame as OUTDIR/frame-NNNN.png
// and prints what the decoder saw (to look at an exported animation).
#include "anim_decode.hpp"

#include "fv/gfx/png.hpp"

#include <cstdio>
#include <cstdlib>
#include <fstream>

namespace {

void save(const std::string& path, const fv::gfx::Image& img) {
    const auto bytes = fv::gfx::encode_png(img);
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: fv_anim_frames FILE.gif|FILE.mp4 OUTDIR [STEP]\n");
        return 2;
    }
    const std::string file = argv[1], dir = argv[2];
    const int step = argc > 3 ? std::max(1, std::atoi(argv[3])) : 1;
    std::vector<fv::gfx::Image> frames;
    if (file.size() > 4 && file.substr(file.size() - 4) == ".gif") {
        fv::test::DecodedGif g = fv::test::decode_gif(file);
        if (!g.error.empty()) return std::fprintf(stderr, "%s\n", g.error.c_str()), 1;
        std::printf("gif %dx%d, %d images, loops %d, first delays %d %d %d cs\n", g.width, g.height,
                    g.image_count, g.loops, g.delays_cs.empty() ? 0 : g.delays_cs[0],
                    g.delays_cs.size() > 1 ? g.delays_cs[1] : 0, g.delays_cs.size() > 2 ? g.delays_cs[2] : 0);
        frames = std::move(g.frames);
    } else {
        fv::test::DecodedVideo v = fv::test::decode_video(file);
        if (!v.error.empty()) return std::fprintf(stderr, "%s\n", v.error.c_str()), 1;
        std::printf("%s %s %s %dx%d %.3f fps, %zu frames\n", v.container.c_str(), v.codec.c_str(),
                    v.pix_fmt.c_str(), v.width, v.height, v.fps, v.frames.size());
        frames = std::move(v.frames);
    }
    for (std::size_t k = 0; k < frames.size(); ++k) {
        if (k % static_cast<std::size_t>(step) != 0 && k + 1 != frames.size()) continue;
        char name[64];
        std::snprintf(name, sizeof name, "/frame-%04zu.png", k);
        save(dir + name, frames[k]);
    }
    for (std::size_t k = 1; k < frames.size(); ++k)
        if (k % 10 == 0 || k + 1 == frames.size())
            std::printf("diff %zu-%zu: %.3f\n", k - 1, k, fv::test::mean_abs_diff(frames[k - 1], frames[k]));
    if (frames.size() > 1)
        std::printf("diff last-first: %.3f\n", fv::test::mean_abs_diff(frames.back(), frames.front()));
    return 0;
}
