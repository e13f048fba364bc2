// Frame times of a benchmark run (gui --bench N): percentiles of the whole frame and the mean of its phases.
#pragma once

#include <string>
#include <vector>

namespace fv::app {

class FrameStats {
  public:
    // One frame: its total, its phases (simulation + controls, dashboard layout, GL drawing) and the CPU time
    // of the thread that ran it, in ms.
    void record(double total_ms, double sim_ui_ms, double layout_ms, double gl_ms, double cpu_ms);
    bool empty() const { return total_.empty(); }
    // Prints three lines to stdout; the first 5 frames (shaders, caches) are left out of the percentiles.
    void print(int width, int height, float scale, const std::string& backend) const;

  private:
    std::vector<double> total_, cpu_;
    double phase_[3] = {0, 0, 0};
};

} // namespace fv::app
