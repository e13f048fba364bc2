// An r_x(zeta) curve kept on the ratio plot to compare with others, with the parameters it shows.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace fv {

struct PinnedCurve {
    std::string label; // "Dahl, θ = 60°, r_{disp} = 2, i = 0" (plot markup)
    std::vector<double> zeta, rx;
};
inline constexpr std::size_t kMaxPins = 6;

} // namespace fv
