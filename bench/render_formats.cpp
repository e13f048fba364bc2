// Time of each output format per registered figure, in process: the figure's data
// (computed once, its own column), then per format the drawing and encoding: png = paint + GL replay +
// readback + PNG encoding, svg / pdf = paint (display list) + cairo replay into the document. Then the whole
// command end to end, `frictionviz render --figure all --format F` for png, svg, pdf and png,svg,pdf (wall
// time, median of runs).
//   usage: fv_render_formats [--exe FRICTIONVIZ] [--size WxH] [--scale S] [--runs R]
#include "figures/render_session.hpp"

#include "figure_examples.hpp"
#include "fv/figure_data.hpp"
#include "fv/figure_registry.hpp"
#include "fv/figures.hpp"
#include "fv/gfx/png.hpp"
#include "fv/gfx/vector_output.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

} // namespace

int main(int argc, char** argv) {
    std::string exe = FV_EXE, size = "1280x800";
    double scale = 1;
    int runs = 3;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string k = argv[a];
        if (k == "--exe") exe = argv[a + 1];
        if (k == "--size") size = argv[a + 1];
        if (k == "--scale") scale = std::atof(argv[a + 1]);
        if (k == "--runs") runs = std::max(1, std::atoi(argv[a + 1]));
    }
    int w = 1280, h = 800;
    std::sscanf(size.c_str(), "%dx%d", &w, &h);
    fv::gfx::ContextOptions co;
    co.width = w;
    co.height = h;
    co.scale = static_cast<float>(scale);
    fv::app::RenderSession session(co);

    // Every registered figure with the inputs of its README rendering (fig19 with the synthetic example
    // data), so that a new figure is timed without touching this file.
    std::vector<fv::FigureSpec> specs;
    for (const fv::FigureEntry& e : fv::figure_registry())
        specs.push_back(e.make(fv::test::example_inputs(e)));
    std::printf("%s at --scale %g, seconds per figure (data: once; formats: median of %d)\n", size.c_str(),
                scale, runs);
    std::printf("%-8s %8s %8s %8s %8s %10s %10s\n", "figure", "data", "png", "svg", "pdf", "svg bytes",
                "pdf bytes");
    double total[3] = {0, 0, 0}, total_data = 0;
    for (const fv::FigureSpec& spec : specs) {
        const auto td = Clock::now();
        const fv::FigureData data = fv::compute_figure(spec);
        const double data_s = seconds_since(td);
        total_data += data_s;
        std::vector<double> t[3];
        std::size_t bytes[2] = {0, 0};
        for (int r = 0; r < runs; ++r) {
            auto t0 = Clock::now();
            const auto png = fv::gfx::encode_png(session.render_figure(data));
            t[0].push_back(seconds_since(t0));
            for (int f = 0; f < 2; ++f) {
                t0 = Clock::now();
                const std::string doc =
                    fv::gfx::render_vector(session.record_figure(data),
                                           f == 0 ? fv::gfx::VectorFormat::Svg : fv::gfx::VectorFormat::Pdf);
                t[1 + f].push_back(seconds_since(t0));
                bytes[f] = doc.size();
            }
        }
        const double m[3] = {median(t[0]), median(t[1]), median(t[2])};
        for (int f = 0; f < 3; ++f) total[f] += m[f];
        std::printf("%-8s %8.3f %8.3f %8.3f %8.3f %10zu %10zu\n", spec.id.c_str(), data_s, m[0], m[1], m[2],
                    bytes[0], bytes[1]);
    }
    std::printf("%-8s %8.3f %8.3f %8.3f %8.3f\n\n", "sum", total_data, total[0], total[1], total[2]);

    std::printf("frictionviz render --figure all --size %s --scale %g (wall seconds, median of %d)\n",
                size.c_str(), scale, runs);
    char tmpl[] = "/tmp/fv_render_formats_XXXXXX";
    const char* dir = mkdtemp(tmpl);
    if (!dir) return 1;
    for (const char* formats : {"png", "svg", "pdf", "png,svg,pdf"}) {
        std::vector<double> t;
        for (int r = 0; r < runs; ++r) {
            const std::string cmd = exe + " render --figure all --format " + formats + " --size " + size +
                                    " --scale " + std::to_string(scale) + " --out " + dir + " >/dev/null";
            const auto t0 = Clock::now();
            if (std::system(cmd.c_str()) != 0) {
                std::fprintf(stderr, "failed: %s\n", cmd.c_str());
                return 1;
            }
            t.push_back(seconds_since(t0));
        }
        std::printf("  --format %-12s %6.2f s\n", formats, median(t));
    }
    std::system((std::string("rm -rf ") + dir).c_str());
    return 0;
}
