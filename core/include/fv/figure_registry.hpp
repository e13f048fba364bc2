// The figure registry: every figure registers itself once, where it is defined (core/src/figures/*.cpp),
// with a static registrar object, as Box2D's samples do with RegisterSample:
//
//   static const RegisterFigure fig10{{"fig10", "friction ratio, i = 1, θ = 90°", FigureKind::ratio_curves,
//                                      {}, {}, [](const FigureInputs&) { return ...; }}};
//
// The command line (render --figure, --list, --help, the unknown-id message), the app's presets, the
// snapshot tests, scripts/run.sh and the README's figure table all read this registry; adding a figure is
// one registration. The registry holds what defines a figure (id, title, the flags it takes, a function
// from those inputs to its FigureSpec); compute_figure (figure_data.hpp) turns a spec into numbers, and the
// kind selects the painter's layout.
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
    std::optional<Start> start; // --start (scene, map)
};

// A command-line flag a figure takes: "--zeta" (or its alternative "--vb"), required or not.
struct FigureFlag {
    std::string name;
    std::string alt; // empty: none
    bool required = false;
};

struct FigureEntry {
    std::string id;    // "fig10"
    std::string title; // one line, plain text: `render --list`
    FigureKind kind = FigureKind::ratio_curves;
    std::vector<FigureFlag> flags; // empty: a fixed figure (defined by its spec alone)
    // The inputs of the rendering shown in README.md and screenshots/ and checked by the snapshot tests; a
    // relative `data` path is relative to the source tree. `render --figure all` uses them for a figure
    // whose required flags are not given, unless `all_needs_flags` (fig19: only with --data).
    FigureInputs example;
    bool all_needs_flags = false;
    // The figure's definition for these inputs (flags checked already). May throw DataError or FitError
    // (a file that cannot be read or fitted).
    std::function<FigureSpec(const FigureInputs&)> make;
    // The README's row (markdown, no line breaks); empty: the caption of make(example).
    std::string summary;
};

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

// `render --list`: "ID<TAB>TITLE" per line.
std::string figure_list_tsv();

// One sentence naming every parameter behind a figure: model(s), ζ, θ, r_disp, i, the solver and its
// tolerance, the sampling. Goes into the caption of ID.json.
std::string figure_parameters(const FigureSpec& spec);

// Markup of titles and labels (r_{disp}, F_{x}) as plain text (r_disp, F_x).
std::string plain_text(const std::string& markup);

} // namespace fv
