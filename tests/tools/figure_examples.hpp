// The inputs a registered figure is drawn with by the snapshot and layout tests and the format benchmark:
// its example, and for a figure that needs a data file (fig19, whose registration names none) the synthetic
// example data that scripts/run.sh renders the README's picture from. Needs FV_SOURCE_DIR.
#pragma once

#include "fv/figure_registry.hpp"

#include <string>

namespace fv::test {

inline FigureInputs example_inputs(const FigureEntry& e) {
    FigureInputs in = e.example;
    if (missing_param(e, in) == FigureParam::data)
        in.data = std::string(FV_SOURCE_DIR) + "/tests/data/synthetic_two_angles_rdisp2_i0.csv";
    return in;
}

} // namespace fv::test
