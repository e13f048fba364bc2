// A family of (zeta, theta) maps (map_family.hpp): the panels, their grid, the title naming what is fixed
// and the caption naming everything. The maps are computed by compute_figure (figure_data.cpp).
#include "fv/map_family.hpp"

#include "fv/figure_family.hpp"
#include "fv/figure_registry.hpp"
#include "fv/format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv {
namespace {

std::string g(double v) {
    return format_number("%g", v);
}

bool has(const std::vector<Model>& models, Model m) {
    return std::find(models.begin(), models.end(), m) != models.end();
}

std::size_t dahl_maps(const MapFamily& f) {
    return has(f.models, Model::dahl) ? f.rdisp.size() * f.i.size() : 0;
}

// The figure's title: the quantity, the models and what every Dahl map shares (what varies titles the
// panels).
std::string family_title(const MapFamily& f) {
    std::string t = "friction ratio r_{x}(ζ, θ)";
    if (has(f.models, Model::dahl)) {
        std::string fixed;
        if (f.rdisp.size() == 1) fixed = "r_{disp} = " + g(f.rdisp[0]);
        if (f.i.size() == 1) fixed += (fixed.empty() ? "" : ", ") + std::string("i = ") + g(f.i[0]);
        if (has(f.models, Model::rigid))
            t += fixed.empty() ? ", Dahl and rigid models" : ", Dahl model (" + fixed + ") and rigid model";
        else
            t += ", Dahl model" + (fixed.empty() ? "" : ", " + fixed);
    } else {
        t += ", rigid model";
    }
    if (f.start == Start::sliding) t += ", vibration switched on while sliding";
    return t;
}

std::string family_caption(const MapFamily& f) {
    const bool dahl = has(f.models, Model::dahl), rigid = has(f.models, Model::rigid);
    const bool several = dahl_maps(f) + (rigid ? 1 : 0) > 1;
    std::string c = "Beyond the paper: r_x over velocity ratio ζ and vibration angle θ";
    c += several ? ", one map per combination, of " : ", of ";
    if (dahl) c += "the Dahl model at r_disp = " + list_text(f.rdisp) + " and i = " + list_text(f.i);
    if (rigid) c += std::string(dahl ? ", and " : "") + "the rigid model (Eq. 9; r_disp and i do not apply)";
    c += several
             ? ", all on one colour scale, each with the angle of strongest friction reduction θ*(ζ) of its "
               "model (solid: Dahl) and that of the rigid model (dashed)"
             : ", with its angle of strongest friction reduction θ*(ζ) (dashed)";
    c += ": the question the paper's conclusion answers only for 0° and 90°.";
    if (several)
        c += " The panels' titles name what varies from map to map, the figure's title what does not.";
    if (dahl)
        c += " Marked cells: where the motion settles into a period of 2, 4, … vibration periods (the mean "
             "over "
             "them is shown), where a second stable steady state coexists (the other start reaches it), and "
             "where no steady state could be vouched for.";
    return c;
}

// Where r_disp and i both vary (Dahl maps only): a column per value of the longer list, a row per value of
// the other (the grid wider than tall, as the page).
bool by_rows_and_columns(const MapFamily& f) {
    return f.models == std::vector<Model>{Model::dahl} && f.rdisp.size() > 1 && f.i.size() > 1;
}

// Columns of the grid: the longer list's values (by_rows_and_columns), else as square as the count allows,
// up to 3 across.
int grid_columns(const MapFamily& f, std::size_t maps) {
    if (by_rows_and_columns(f)) return static_cast<int>(std::max(f.rdisp.size(), f.i.size()));
    return static_cast<int>(maps <= 3 ? maps : maps == 4 ? 2 : 3);
}

} // namespace

MapFamily map_family_of(const FigureInputs& in) {
    MapFamily f;
    if (!in.models.empty()) f.models = in.models;
    if (!in.rdisp.empty()) f.rdisp = in.rdisp;
    if (!in.i.empty()) f.i = in.i;
    f.start = in.start.value_or(Start::rest);
    return f;
}

std::vector<MapPanelSpec> map_family_panels(const MapFamily& f) {
    const bool both = has(f.models, Model::dahl) && has(f.models, Model::rigid);
    std::vector<MapPanelSpec> out;
    const auto add = [&](double r, double i) {
        std::string t;
        if (f.rdisp.size() > 1) t = "r_{disp} = " + g(r);
        if (f.i.size() > 1) t += (t.empty() ? "" : ", ") + std::string("i = ") + g(i);
        if (both) t = t.empty() ? "Dahl model" : "Dahl, " + t;
        out.push_back({Model::dahl, r, i, t});
    };
    // Row by row: the longer list along a row (i along it only where it has more values than r_disp).
    const bool i_across = by_rows_and_columns(f) && f.i.size() > f.rdisp.size();
    if (has(f.models, Model::dahl))
        for (std::size_t a = 0; a < (i_across ? f.rdisp.size() : f.i.size()); ++a)
            for (std::size_t b = 0; b < (i_across ? f.i.size() : f.rdisp.size()); ++b)
                i_across ? add(f.rdisp[a], f.i[b]) : add(f.rdisp[b], f.i[a]);
    if (has(f.models, Model::rigid)) {
        const double nan = std::numeric_limits<double>::quiet_NaN();
        out.push_back({Model::rigid, nan, nan, both ? "rigid model (Eq. 9)" : ""});
    }
    return out;
}

std::string map_family_size_error(const MapFamily& f) {
    const std::size_t dahl = dahl_maps(f), n = dahl + (has(f.models, Model::rigid) ? 1 : 0);
    if (n <= kMaxFamilyMaps) return {};
    std::string s;
    if (dahl > 0)
        s = "r_disp " + std::to_string(f.rdisp.size()) + " × i " + std::to_string(f.i.size()) + " = " +
            std::to_string(dahl) + " Dahl maps";
    if (has(f.models, Model::rigid)) s += std::string(dahl > 0 ? " + " : "") + "1 rigid";
    return s + " = " + std::to_string(n) + " maps; allowed: at most " + std::to_string(kMaxFamilyMaps) +
           " maps in one figure (each is 200 × 91 steady states; split the family into several figures)";
}

std::string map_family_check(const FigureInputs& in) {
    return map_family_size_error(map_family_of(in));
}

FigureSpec map_family_figure(const MapFamily& f) {
    if (f.models == std::vector<Model>{Model::dahl} && f.rdisp.size() == 1 && f.i.size() == 1)
        return map_figure(f.rdisp[0], f.i[0], f.start);
    FigureSpec spec = map_figure(2, 1, f.start); // the grid, the tolerance and the start of every map
    MapFigure& m = std::get<MapFigure>(spec.content);
    m.family = map_family_panels(f);
    m.columns = grid_columns(f, m.family.size());
    m.model = m.family.front().model, m.rdisp = m.family.front().rdisp, m.i = m.family.front().i;
    spec.title = family_title(f);
    spec.caption = family_caption(f);
    return spec;
}

} // namespace fv
