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

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace fv {

// What a caller (the command line) gives a figure that takes parameters. Unset: not given.
struct FigureInputs {
    std::optional<double> zeta, theta_deg, rdisp, i;
    std::string data; // a measurements file (fig19)
    std::optional<double> amplitude_um, frequency_khz;
    std::optional<Start> start; // the history (scene, map)
};

// One input of FigureInputs, by what it means (the command line maps each to its flags).
enum class FigureParam { zeta, theta, rdisp, i, data, amplitude, frequency, start };

// A parameter a figure takes, required or not.
struct FigureParamUse {
    FigureParam param;
    bool required = false;
};

// Whether `in` gives `p`.
bool given(const FigureInputs& in, FigureParam p);

struct FigureEntry {
    std::string id;    // "fig10"
    std::string title; // one line, plain text: `render --list`
    FigureKind kind = FigureKind::ratio_curves;
    std::vector<FigureParamUse> params; // empty: a fixed figure (defined by its spec alone)
    // The inputs of the rendering shown in README.md and screenshots/ and checked by the snapshot tests.
    // `render --figure all` uses them for a figure whose required parameters are not given; a figure whose
    // example lacks one of them (fig19: a data file) is rendered there only when it is given.
    FigureInputs example;
    // The figure's definition for these inputs (required parameters checked already). May throw DataError
    // or FitError (a file that cannot be read or fitted).
    std::function<FigureSpec(const FigureInputs&)> make;
    // What the figure shows, in plain sentences, where the caption of make(example) does not say it well
    // enough for a list of figures; empty: that caption.
    std::string summary;
};

// The first required parameter of `e` that `in` does not give; nullopt if none.
std::optional<FigureParam> missing_param(const FigureEntry& e, const FigureInputs& in);

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
