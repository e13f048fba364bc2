// A family of r_x(zeta) (or r_y) curves: one curve per combination of lists of vibration angles, r_disp, i
// and models over a range of zeta (render --figure rx|ry --theta 30,60 --rdisp 1,3,10 --i 0.5 --model
// dahl,rigid --zeta 0.01:10). The lists are read and checked here, not in the command line, so that every
// door (the CLI's flags, a spec file, the Python module's keyword lists) gives the same verdicts and
// messages: each item through the shared number reader and the range table (read_number.hpp,
// param_ranges.hpp), an empty item, a repeated value and a reversed or empty range refused in one line.
#pragma once

#include "fv/figures.hpp"
#include "fv/param_ranges.hpp"

#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace fv {

struct FigureInputs;

// The paper's range of Figs. 5, 10-13: zeta from 0 to 3.
inline constexpr ZetaSpan kPaperZetaSpan{0, 3};

// A span at least this wide in ratio (to/from, from > 0) is drawn on a logarithmic zeta axis and sampled
// evenly in log zeta: two decades or more would put all but the last decade into a sliver of a linear axis.
inline constexpr double kLogZetaRatio = 100;

// Curves in one family figure at most (after the rigid curves collapse): with more, neither colours nor
// the legend can keep them apart, and the solver's time grows with each (about 160 steady states a curve).
inline constexpr std::size_t kMaxFamilyCurves = 12;

// What varies over a family: the lists and the range (empty lists are resolved by the figure's defaults
// before a family is made).
struct FigureFamily {
    std::vector<Model> models{Model::dahl, Model::rigid};
    std::vector<double> theta_deg, rdisp, i;
    ZetaSpan zeta = kPaperZetaSpan;
    bool side_force = false;   // r_y instead of r_x
    Start start = Start::rest; // the history where steady states coexist
};

// The curves of a family: for each model in the order given, every combination of theta (outermost), r_disp
// and i (innermost); the rigid model ignores r_disp and i, so it gives one curve per theta.
std::vector<Curve> family_curves(const FigureFamily& f);

// The figure of a family (id "rx" or "ry"): its curves, the start grid of zeta (the paper's figures' grid
// for the paper's span, else 41 points evenly spaced, in log zeta for a span of kLogZetaRatio or more), the
// title naming what is fixed and the caption naming everything; `data` (may be null) drawn over the curves.
FigureSpec family_figure(const std::string& id, const FigureFamily& f,
                         std::shared_ptr<const MeasurementSet> data = nullptr);

// The family the inputs of rx or ry describe (with_defaults applied: every list given).
FigureFamily family_of(const FigureInputs& in, bool side_force);

// family_size_error of the inputs' family (FigureEntry::check of rx and ry).
std::string family_check(const FigureInputs& in);

// "" when the family has at most kMaxFamilyCurves curves, else one line naming the product and the limit
// ("theta 3 × r_disp 4 × i 2 = 24 Dahl curves + 3 rigid = 27 curves; allowed: at most 12 curves in one
// figure (split the family)").
std::string family_size_error(const FigureFamily& f);

// --- Reading and checking the lists. Each returns "" or one line that starts with `name`. ---

// "30,60,90": comma-separated numbers, each in `r` (read_number's messages), no empty item, no value twice.
std::string read_number_list(std::string_view name, std::string_view text, ParamRange r,
                             std::vector<double>& out);
// A list already read (a JSON array, a Python list): not empty, each value in `r`, no value twice.
std::string check_number_list(std::string_view name, const std::vector<double>& values, ParamRange r);

// "dahl,rigid": comma-separated model names, no empty item, none twice.
std::string read_model_list(std::string_view name, std::string_view text, std::vector<Model>& out);
std::string check_model_list(std::string_view name, const std::vector<Model>& models);

// "FROM:TO": two numbers in kZetaRange (read_number's messages), FROM < TO.
std::string read_zeta_span(std::string_view name, std::string_view text, ZetaSpan& out);
std::string check_zeta_span(std::string_view name, const ZetaSpan& span);

// "30, 45, 60" (shortest decimals): the values of a list for titles and messages.
std::string list_text(const std::vector<double>& values);

} // namespace fv
