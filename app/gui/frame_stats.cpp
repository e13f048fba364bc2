#include "frame_stats.hpp"

#include <algorithm>
#include <cstdio>

namespace fv::app {

void FrameStats::record(double total_ms, double sim_ui_ms, double layout_ms, double gl_ms, double cpu_ms) {
    total_.push_back(total_ms);
    cpu_.push_back(cpu_ms);
    phase_[0] += sim_ui_ms;
    phase_[1] += layout_ms;
    phase_[2] += gl_ms;
}

void FrameStats::print(int width, int height, float scale, const std::string& backend) const {
    if (total_.empty()) return;
    auto sorted = [](const std::vector<double>& all) {
        std::vector<double> v(all.begin() + std::min<std::size_t>(5, all.size() - 1), all.end());
        std::sort(v.begin(), v.end());
        return v;
    };
    auto quantile = [](const std::vector<double>& v, double q) {
        return v[std::min(v.size() - 1,
                          static_cast<std::size_t>(q * static_cast<double>(v.size() - 1) + 0.5))];
    };
    const std::vector<double> v = sorted(total_), cpu = sorted(cpu_);
    auto at = [&](double q) { return quantile(v, q); };
    std::printf(
        "frame time over %zu frames at %dx%d scale %g (%s, a slider changing every frame): p50 %.1f ms, "
        "p95 %.1f ms, p99 %.1f ms, max %.1f ms\n",
        v.size(), width, height, static_cast<double>(scale), backend.c_str(), at(0.5), at(0.95), at(0.99),
        v.back());
    const double n = static_cast<double>(total_.size());
    std::printf(
        "mean per frame: simulation + controls %.1f ms, dashboard layout %.1f ms, GL drawing %.1f ms\n",
        phase_[0] / n, phase_[1] / n, phase_[2] / n);
    // With LP_NUM_THREADS=0 llvmpipe rasterises on the app's thread, so this is the whole frame's cost and
    // hardly depends on what else the machine runs (scripts/bench-gui.sh prints it too).
    std::printf("CPU time of the app's thread per frame: p50 %.1f ms, p95 %.1f ms\n", quantile(cpu, 0.5),
                quantile(cpu, 0.95));
}

} // namespace fv::app
