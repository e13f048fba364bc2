// Seconds for `frictionviz animate` (budget: 2 periods at 640x400, 30 fps, in at most 5 s):
// GIF and MP4, dashboard and scene view, end to end (steady state, frames rendered headless through OSMesa,
// encoding, atomic write). Prints wall time (median of runs), the child's CPU time and the load average,
// since other work on the machine slows the wall time. Not a test: timings never decide pass or fail.
//   usage: fv_animate_speed [--exe FRICTIONVIZ] [--size WxH] [--runs R]
#include "child_peak_rss.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    std::string exe = FV_EXE, size = "640x400";
    int runs = 3;
    for (int a = 1; a + 1 < argc; a += 2) {
        const std::string k = argv[a];
        if (k == "--exe")
            exe = argv[a + 1];
        else if (k == "--size")
            size = argv[a + 1];
        else if (k == "--runs")
            runs = std::max(1, std::atoi(argv[a + 1]));
    }
    char dir[] = "/tmp/fv-animate-speed-XXXXXX";
    if (!mkdtemp(dir)) return 1;
    std::printf(
        "frictionviz animate --zeta 0.15 --theta 60 --rdisp 2 --i 1 --size %s (2 periods, 30 fps, 0.5 "
        "periods/s: 120 frames), median of %d runs\n",
        size.c_str(), runs);
    std::printf("%-6s %-10s %10s %10s %10s\n", "format", "view", "wall s", "cpu s", "load");
    for (const char* ext : {"gif", "mp4"})
        for (const char* view : {"dashboard", "scene"}) {
            std::vector<double> wall, cpu;
            for (int r = 0; r < runs; ++r) {
                const std::string out = std::string(dir) + "/a." + ext;
                const fv::testing::ChildRun c =
                    fv::testing::run_child({exe, "animate", "--zeta", "0.15", "--theta", "60", "--rdisp", "2",
                                            "--i", "1", "--size", size, "--view", view, "--out", out});
                if (c.exit_code != 0) return std::fprintf(stderr, "animate failed (%d)\n", c.exit_code), 1;
                wall.push_back(c.seconds);
                cpu.push_back(c.cpu_seconds);
            }
            std::sort(wall.begin(), wall.end());
            std::sort(cpu.begin(), cpu.end());
            double load[1] = {0};
            getloadavg(load, 1);
            std::printf("%-6s %-10s %10.2f %10.2f %10.2f\n", ext, view, wall[wall.size() / 2],
                        cpu[cpu.size() / 2], load[0]);
        }
    return 0;
}
