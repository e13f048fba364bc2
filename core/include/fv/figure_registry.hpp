// The figure registry: every figure registers itself once, where it is defined (core/src/figures/*.cpp),
// with a static registrar object, as Box2D's samples do with RegisterSample:
//
//   static const RegisterFigure fig10{{"fig10", "friction ratio, i = 1, θ = 90°", FigureKind::ratio_curves,
//                                      {}, {}, [](const FigureInputs&) { return ...; }}};
//
// The command line (render --figure, --list, --help, the README's table), the app's presets, the snapshot
// tests and scripts/run.sh read this registry; adding a figure is one registration. The registry holds what
// defines a figure (id, title, the parameters it takes, a function from them to its FigureSpec); the command
// line names the parameters' flags. compute_figure (figure_data.hpp) turns a spec into numbers.
#pragma once

#include "fv/figures.hpp"
#include "fv/param_ranges.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fv {

// What a caller (the command line, a spec file, the Python module) gives a figure that takes parameters.
// Unset or empty: not given. theta_deg, rdisp, i and models hold one value, or a list where the figure
// takes lists (FigureParamUse::list: rx, ry, map); figure_family.hpp reads and checks lists.
struct FigureInputs {
    std::optional<double> zeta;        // one velocity ratio (fig4, scene)
    std::optional<ZetaSpan> zeta_span; // a range of them (rx, ry)
    std::vector<double> theta_deg, rdisp, i;
    std::vector<Model> models;
    std::string data; // a measurements file (fig19, rx)
    std::optional<double> amplitude_um, frequency_khz;
    std::optional<Start> start; // the history (scene, map, rx, ry)
};

// One input of FigureInputs, by what it means (the command line maps each to its flags, a spec file and the
// Python module to its key: param_key). zeta_range is the zeta_span; it shares zeta's key and flag.
enum class FigureParam { zeta, zeta_range, theta, rdisp, i, model, data, amplitude, frequency, start };

// A parameter a figure takes, required or not, one value or a list of them.
struct FigureParamUse {
    FigureParam param;
    bool required = false;
    bool list = false;
    // A list of one value is written to ID.json's parameters as that number (the map: its files as they
    // were before it took lists); else a list as a list, even of one (rx, ry).
    bool one_as_number = false;
};

// The key of `p` in a spec file and ID.json's parameters (and the Python module's keyword): "zeta",
// "theta", "rdisp", "i", "model", "data", "amplitude", "frequency", "start" (zeta_range: "zeta").
const char* param_key(FigureParam p);

// The range of a numeric parameter (theta in degrees, amplitude in um, frequency in kHz); nullptr for the
// others (data, model, start, zeta_range: checked as a span).
const ParamRange* param_range(FigureParam p);

// The one value of a parameter that takes one (its list's first), or `otherwise` when not given.
inline double one(const std::vector<double>& values, double otherwise) {
    return values.empty() ? otherwise : values.front();
}

// Whether `in` gives `p`.
bool given(const FigureInputs& in, FigureParam p);

// `top`'s inputs over `base`'s: every input `top` gives replaces `base`'s.
FigureInputs over(FigureInputs base, const FigureInputs& top);

struct FigureEntry {
    std::string id;    // "fig10"
    std::string title; // one line, plain text: `render --list`
    FigureKind kind = FigureKind::ratio_curves;
    std::vector<FigureParamUse> params; // empty: a fixed figure (defined by its spec alone)
    // The values of the parameters it takes where they are not given (those without one change what the
    // figure says when not given: fig19's amplitude names the paper's experiment then). ID.json's
    // parameters object holds them resolved (with_defaults), so that a spec file names every value.
    FigureInputs defaults;
    // Checks of the whole set of inputs beyond each value's own (the family's number of curves): "" or one
    // line; empty: none.
    std::function<std::string(const FigureInputs&)> check;
    // The inputs of the rendering shown in README.md and screenshots/ and checked by the snapshot tests.
    // `render --figure all` uses them for a figure whose required parameters are not given; a figure whose
    // example lacks one of them (fig19: a data file) is rendered there only when it is given.
    FigureInputs example;
    // The figure's definition for these inputs (required parameters checked already, with_defaults applied:
    // the registrar wraps it so). May throw DataError or FitError (a file that cannot be read or fitted).
    std::function<FigureSpec(const FigureInputs&)> make;
    // What the figure shows, in plain sentences, where the caption of make(example) does not say it well
    // enough for a list of figures; empty: that caption.
    std::string summary;
};

// The first required parameter of `e` that `in` does not give; nullopt if none.
std::optional<FigureParam> missing_param(const FigureEntry& e, const FigureInputs& in);

// The inputs `e` is made from: `given`'s over e.defaults, the parameters `e` does not take dropped.
FigureInputs with_defaults(const FigureEntry& e, const FigureInputs& given);

// "" when every input `e` takes is admissible, else one line: a list where `e` takes one value, a value out
// of its range or given twice, an empty list, a reversed zeta range, then e.check. `name` says each
// parameter as the caller's user knows it (the command line: "--theta"; a spec file: "theta").
std::string input_error(const FigureEntry& e, const FigureInputs& in,
                        const std::function<std::string(FigureParam)>& name);

// What of `in` fits `e` as `render --figure all` hands the same inputs to every figure: a list only to a
// figure that takes lists, a zeta range only to one that takes a range (and one zeta only to one that takes
// one), and the data file (with the vibration that reads it) only to a figure that needs one (fig19; rx
// draws data where asked by name, not in every figure).
FigureInputs fitting(const FigureEntry& e, FigureInputs in);

// "rx, ry": the figures that take a list of `p`.
std::string figures_taking_lists(FigureParam p);

// Registers at static initialisation; a second entry with the same id aborts the program.
struct RegisterFigure {
    explicit RegisterFigure(FigureEntry entry);
};

// Every registered figure: the paper's (figN, by number; fig14, fig14a, fig14b) first, then the others by id.
const std::vector<FigureEntry>& figure_registry();

// nullptr if unknown.
const FigureEntry* find_registered(const std::string& id);

// The registered ids, comma separated (for messages).
std::string figure_ids();

// One sentence naming every parameter behind a figure: model(s), ζ, θ, r_disp, i, the solver and its
// tolerance, the sampling. Goes into the caption of ID.json.
std::string figure_parameters(const FigureSpec& spec);

// Markup of titles and labels (r_{disp}, F_{x}) as plain text (r_disp, F_x).
std::string plain_text(const std::string& markup);

} // namespace fv
