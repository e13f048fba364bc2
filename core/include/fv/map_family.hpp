// A family of (zeta, theta) maps: one map per combination of lists of r_disp, i and models (render --figure
// map --rdisp 1,3,10 --i 0.5,1 --model dahl,rigid), drawn as small multiples in one figure: a grid of panels
// each titled with what varies, the figure's title naming what is fixed, one colour scale and one legend.
// The lists are read and checked as rx's and ry's are (figure_family.hpp); one Dahl map alone is map_figure
// (figures.hpp), the figure as it was before families.
#pragma once

#include "fv/figures.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace fv {

struct FigureInputs;

// Maps in one figure at most: each is 200 x 91 steady states (about 5 s of one core at i <= 2, several
// times that at i = 10), and 2 x 3 panels are as small as a 1280 x 800 page shows the cells, the theta*
// lines and the tick labels legibly.
inline constexpr std::size_t kMaxFamilyMaps = 6;

// What varies over a family of maps (every list given: with_defaults applied; the rigid model ignores
// r_disp and i, so it adds one map).
struct MapFamily {
    std::vector<Model> models{Model::dahl};
    std::vector<double> rdisp{2}, i{1};
    Start start = Start::rest;
};

// The family the inputs of the map describe (no model given: the Dahl model alone).
MapFamily map_family_of(const FigureInputs& in);

// The maps of a family: the Dahl maps row by row (a row per i, r_disp along it; where only Dahl maps are
// drawn and i has more values than r_disp, a row per r_disp, i along it), then the rigid map; each titled
// with what varies.
std::vector<MapPanelSpec> map_family_panels(const MapFamily& f);

// "" when the family has at most kMaxFamilyMaps maps, else one line naming the count and the cap.
std::string map_family_size_error(const MapFamily& f);

// map_family_size_error of the inputs' family (FigureEntry::check of the map).
std::string map_family_check(const FigureInputs& in);

// The figure: map_figure for one Dahl map (byte for byte the figure of before families), else the family
// on a grid: where r_disp and i both vary (Dahl maps only) a column per value of the longer list, else as
// square as the count allows (up to 3 across: 1 x 2, 1 x 3, 2 x 2, 2 x 3).
FigureSpec map_family_figure(const MapFamily& f);

} // namespace fv
