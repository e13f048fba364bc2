#include "fv/gfx/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fv::gfx {

double nice_step(double range, int target_count) {
    if (!(range > 0) || !std::isfinite(range)) return 1.0;
    const double raw = range / std::max(1, target_count);
    const double mag = std::pow(10.0, std::floor(std::log10(raw)));
    const double f = raw / mag;
    const double m = f < 1.5 ? 1 : f < 3.5 ? 2 : f < 7.5 ? 5 : 10;
    return m * mag;
}

std::string with_unicode_minus(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '-')
            out += "\xE2\x88\x92";
        else
            out += c;
    }
    return out;
}

std::string format_tick(double value, double step) {
    if (std::fabs(value) < std::fabs(step) * 1e-9) return "0"; // Kills 1e-17 and "-0".
    const int step_exp = static_cast<int>(std::floor(std::log10(std::fabs(step)) + 1e-9));
    const double mag = std::fabs(value);
    char buf[64];
    if (mag >= 1e5 || mag < 1e-3) {
        int e = static_cast<int>(std::floor(std::log10(mag) + 1e-9));
        double m = value / std::pow(10.0, e);
        const int decimals = std::clamp(e - step_exp, 0, 6);
        std::snprintf(buf, sizeof buf, "%.*f", decimals, m);
        if (std::string(buf) == "1") return with_unicode_minus("10^{" + std::to_string(e) + "}");
        if (std::string(buf) == "-1") return with_unicode_minus("-10^{" + std::to_string(e) + "}");
        return with_unicode_minus(std::string(buf) +
                                  "\xC3\x97"
                                  "10^{" +
                                  std::to_string(e) + "}");
    }
    const int decimals = std::clamp(-step_exp, 0, 9);
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
    return with_unicode_minus(buf);
}

std::vector<Tick> linear_ticks(double lo, double hi, int target_count) {
    std::vector<Tick> ticks;
    if (!(hi > lo) || !std::isfinite(lo) || !std::isfinite(hi)) return ticks;
    // At least two ticks in the range: asked for 2 over [-1.45, 1.45], the nice step 2 left only 0 inside
    // (fig4's top view on a narrow page); a finer step then.
    double step = 0, first = 0, last = -1;
    for (int n = std::max(1, target_count); n <= std::max(1, target_count) + 8 && last - first < 1; ++n) {
        step = nice_step(hi - lo, n);
        const double eps = step * 1e-6;
        // Integer multiples avoid accumulating 0.1 + 0.1 + ... rounding errors.
        first = std::ceil((lo - eps) / step), last = std::floor((hi + eps) / step);
    }
    for (double i = first; i <= last && ticks.size() < 1000; i += 1) {
        const double v = i * step;
        ticks.push_back({v, format_tick(v, step), true});
    }
    return ticks;
}

std::vector<Tick> log_ticks(double lo, double hi, int target_count) {
    std::vector<Tick> ticks;
    if (!(lo > 0) || !(hi > lo) || !std::isfinite(hi)) return ticks;
    const int e0 = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
    const int e1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
    const int decades = std::max(1, e1 - e0);
    const int every =
        std::max(1, static_cast<int>(std::ceil(static_cast<double>(decades) / std::max(1, target_count))));
    const bool minor = every == 1 && decades <= 8;
    // One style for the whole axis: plain numbers when every decade is short, else powers of ten.
    const bool plain = e0 >= -3 && e1 <= 4;
    for (int e = e0; e <= e1; ++e) {
        const double v = std::pow(10.0, e);
        if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9) && (e % every) == 0) {
            std::string label;
            if (plain) {
                char buf[32];
                std::snprintf(buf, sizeof buf, "%.*f", std::max(0, -e), v);
                label = buf;
            } else {
                label = with_unicode_minus("10^{" + std::to_string(e) + "}");
            }
            ticks.push_back({v, label, true});
        }
        if (minor) {
            for (int k = 2; k <= 9; ++k) {
                const double m = k * v;
                if (m >= lo && m <= hi) ticks.push_back({m, "", false});
            }
        }
    }
    std::sort(ticks.begin(), ticks.end(), [](const Tick& a, const Tick& b) { return a.value < b.value; });
    return ticks;
}

} // namespace fv::gfx
