// An r_x(zeta) curve kept on the ratio plot to compare with others, with the parameters it shows.
#pragma once

#include "fv/params.hpp"
#include "fv/steady_state.hpp" // Start

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace fv {

struct RatioCurves;

// What a pinned curve was computed at: the model, the three parameters the curve depends on (not zeta, its
// abscissa) and the start. A share link carries pins as these (pins=, fv/share_link.hpp) and the page that
// opens it computes the curves again; for the rigid model only theta counts.
struct PinSource {
    Model model = Model::dahl;
    double theta = 0, rdisp = 1, i = 1; // theta in radians, as in Params
    Start start = Start::rest;
};

struct PinnedCurve {
    std::string label; // "Dahl, θ = 60°, r_{disp} = 2, i = 0" (plot markup)
    std::vector<double> zeta, rx;
    // Where the curve came from, when known (pinned in the app, or opened from a link or a session that
    // says); a curve without it (an older session file) cannot go into a share link.
    std::optional<PinSource> source;
};
inline constexpr std::size_t kMaxPins = 6;

// The pin's source for a state: the model, its parameters and the start.
PinSource pin_source(Model model, const Params& params, Start start);
// "Dahl, θ = 60°, r_{disp} = 2, i = 0[, from sliding]" or "rigid, θ = 60°".
std::string pin_label(const PinSource& s);
// The pin of `curves` (the model's curve, or the rigid one for the rigid model), labelled, with its source.
PinnedCurve pin_of(const PinSource& s, const RatioCurves& curves);
// The pin computed afresh on the calling thread (compute_ratio_curves, the curves reaching zeta_max): what
// a share link's pins become.
PinnedCurve compute_pin(const PinSource& s, double zeta_max);

} // namespace fv
