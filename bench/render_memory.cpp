// Memory of `frictionviz render` against the number of figures: peak RSS (wait4, per child process) of one
// fig8 and of N in one call, the increment per added figure, and the wall time per figure, at 1280x800
// and 7680x4320. Medians of a few runs. When every figure kept its frame (fixed), each added one cost
// (4 MB at 1280x800, 133 MB at 7680x4320); now the increment is what does not scale with N, spread over N.
//   usage: fv_render_memory [--exe FRICTIONVIZ] [--runs R] [--count N] [--big-count N] [--figure ID]
#include "child_peak_rss.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

struct Sample {
    double peak_mib, seconds;
};

// Median peak RSS and median wall time of `runs` calls rendering `count` figures.
Sample measure(const std::string& exe, const std::string& dir, const std::string& figure,
               const std::string& size, int count, int runs) {
    std::vector<double> peak, seconds;
    for (int r = 0; r < runs; ++r) {
        const fv::testing::ChildRun c =
            fv::testing::run_child({exe, "render", "--figure", fv::testing::repeated_figure(figure, count),
                                    "--size", size, "--out", dir});
        if (c.exit_code != 0) {
            std::fprintf(stderr, "render exited %d\n", c.exit_code);
            std::exit(1);
        }
        peak.push_back(static_cast<double>(c.peak_rss_kb) / 1024.0);
        seconds.push_back(c.seconds);
    }
    return {median(peak), median(seconds)};
}

} // namespace

int main(int argc, char** argv) {
    std::string exe = FV_EXE, figure = "fig8";
    int runs = 3, count = 40, big_count = 8;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string k = argv[a];
        if (k == "--exe") exe = argv[a + 1];
        if (k == "--runs") runs = std::max(1, std::atoi(argv[a + 1]));
        if (k == "--count") count = std::max(2, std::atoi(argv[a + 1]));
        if (k == "--big-count") big_count = std::max(2, std::atoi(argv[a + 1]));
        if (k == "--figure") figure = argv[a + 1];
    }
    char tmpl[] = "/tmp/fv_render_memory_XXXXXX";
    const char* dir = mkdtemp(tmpl);
    if (!dir) {
        std::perror("mkdtemp");
        return 1;
    }
    std::printf("render --figure %s x N, peak RSS (MiB) and wall time, medians of %d runs\n\n",
                figure.c_str(), runs);
    std::printf("| size | frame | 1 figure | N | N figures | per added figure | s per figure (N) |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    struct Case {
        const char* size;
        int w, h, count;
    };
    for (const Case& c : {Case{"1280x800", 1280, 800, count}, Case{"7680x4320", 7680, 4320, big_count}}) {
        const Sample one = measure(exe, dir, figure, c.size, 1, runs);
        const Sample many = measure(exe, dir, figure, c.size, c.count, runs);
        const double frame = static_cast<double>(c.w) * c.h * 4 / (1024.0 * 1024.0);
        std::printf("| %s | %.1f | %.1f | %d | %.1f | %+.2f | %.3f |\n", c.size, frame, one.peak_mib, c.count,
                    many.peak_mib, (many.peak_mib - one.peak_mib) / (c.count - 1), many.seconds / c.count);
        std::fflush(stdout);
    }
    std::system(("rm -rf '" + std::string(dir) + "'").c_str());
    return 0;
}
