#pragma once
// Axis tick placement ("nice" 1-2-5 steps, decades on log axes) and number formatting for labels.
#include <string>
#include <vector>

namespace fv::gfx {

struct Tick {
    double value;
    std::string label; ///< Empty for minor ticks. May contain ^{..} markup (powers of ten).
    bool major = true;
};

/// Step of the form {1,2,5}·10^k giving about `target_count` intervals over `range` (> 0).
double nice_step(double range, int target_count);

/// Major ticks at multiples of a nice step inside [lo, hi] (inclusive, with a tiny tolerance).
std::vector<Tick> linear_ticks(double lo, double hi, int target_count);

/// Decade ticks (plus unlabelled minor ticks 2..9 when few decades) inside [lo, hi], lo > 0.
std::vector<Tick> log_ticks(double lo, double hi, int target_count);

/// Label for `value` on an axis whose tick step is `step`: just enough decimals, U+2212 minus,
/// no "-0", and m×10^{e} for very large or very small magnitudes.
std::string format_tick(double value, double step);

/// Replaces ASCII '-' by the typographic minus sign U+2212.
std::string with_unicode_minus(const std::string& s);

} // namespace fv::gfx
