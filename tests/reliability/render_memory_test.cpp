// Render memory is flat in the number of figures: `frictionviz render` with one figure and then with 40 in
// one call, each a child process whose peak RSS is read with wait4; the 40-figure peak may exceed the
// 1-figure peak by at most the encoding budget, one frame of the requested size and a slack.
//   usage: fv_render_memory_test FRICTIONVIZ OUT_DIR [--size WxH] [--count N] [--figure ID]
//
// Why the bound: render draws figure k while the frames before it are PNG-encoded on other threads, as many
// as fit in kEncodeBudget (app/cli/cmd_render.cpp, 16 MiB: two at 1280x800, one from 2^20 pixels up), so
// more is alive than in a 1-figure run: those encoders' frames and the frame drawn meanwhile (at most the
// budget plus one frame). The slack covers what does not scale with the figure count (malloc arenas of the
// encoder threads, page granularity). A render path that keeps anything per figure (frames, contexts,
// textures) grows by that much per figure: the frames alone, 39 x 3.9 MiB = 152 MiB here.
#include "child_peak_rss.hpp"

#include <sys/stat.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

constexpr double kEncodeBudgetMiB = 16; // kEncodeBudget in app/cli/cmd_render.cpp
constexpr double kSlackMiB = 8;

double mib(long kib) {
    return static_cast<double>(kib) / 1024.0;
}

} // namespace

int main(int argc, char** argv) {
    if (argc < 3) {
        std::fprintf(stderr, "usage: %s FRICTIONVIZ OUT_DIR [--size WxH] [--count N] [--figure ID]\n",
                     argv[0]);
        return 2;
    }
    const std::string exe = argv[1], dir = argv[2];
    std::string size = "1280x800", figure = "fig8";
    int count = 40;
    for (int a = 3; a + 1 < argc; a += 2) {
        const std::string k = argv[a];
        if (k == "--size") size = argv[a + 1];
        if (k == "--count") count = std::atoi(argv[a + 1]);
        if (k == "--figure") figure = argv[a + 1];
    }
    int w = 0, h = 0;
    if (std::sscanf(size.c_str(), "%dx%d", &w, &h) != 2 || count < 2) {
        std::fprintf(stderr, "bad --size or --count\n");
        return 2;
    }
#ifdef FV_SANITIZED
    // AddressSanitizer holds freed memory in a quarantine (256 MiB) that would count against the bound.
    const char* asan = std::getenv("ASAN_OPTIONS");
    setenv("ASAN_OPTIONS", (std::string(asan ? asan : "") + ":quarantine_size_mb=0").c_str(), 1);
#endif
    ::mkdir(dir.c_str(), 0755);
    auto render = [&](int n) {
        return fv::testing::run_child({exe, "render", "--figure", fv::testing::repeated_figure(figure, n),
                                       "--size", size, "--out", dir});
    };
    const fv::testing::ChildRun one = render(1);
    fv::testing::ChildRun many = render(count);
    if (one.exit_code != 0 || many.exit_code != 0) {
        std::fprintf(stderr, "FAIL: render exited %d (1 figure) and %d (%d figures)\n", one.exit_code,
                     many.exit_code, count);
        return 1;
    }
    const double frame_mib = static_cast<double>(w) * h * 4 / (1024.0 * 1024.0);
    const double bound_mib = kEncodeBudgetMiB + frame_mib + kSlackMiB;
    auto excess = [&](const fv::testing::ChildRun& r) { return mib(r.peak_rss_kb - one.peak_rss_kb); };
    // A genuine per-figure cost shows on every run; one unlucky run (another process's memory pressure
    // does not count, but allocator timing does) gets a second chance.
    if (excess(many) > bound_mib) {
        const fv::testing::ChildRun again = render(count);
        if (again.exit_code == 0 && again.peak_rss_kb < many.peak_rss_kb) many = again;
    }
    std::printf(
        "%s %s: peak RSS 1 figure %.1f MiB, %d figures %.1f MiB: +%.1f MiB (%.2f MiB per added figure); "
        "bound +%.1f MiB (%.0f MiB encoding, a %.1f MiB frame, %.0f MiB slack)\n",
        figure.c_str(), size.c_str(), mib(one.peak_rss_kb), count, mib(many.peak_rss_kb), excess(many),
        excess(many) / (count - 1), bound_mib, kEncodeBudgetMiB, frame_mib, kSlackMiB);
    if (excess(many) > bound_mib) {
        std::printf("FAIL: memory grows with the number of figures\n");
        return 1;
    }
    return 0;
}
