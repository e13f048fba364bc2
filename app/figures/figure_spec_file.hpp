// A figure's spec file: ID.json's "parameters" object (render writes it beside every figure) names the figure
// and every input behind it, so that `render --spec ID.json` draws the same files byte for byte. The keys are
// the registry's (fv::param_key): id; the figure's own parameters (zeta, theta, rdisp, i, model, data,
// amplitude, frequency, start; lists as arrays, the zeta range of rx and ry as [FROM, TO]); size [W, H],
// scale, format [png, svg, pdf], and page and caption where given. Numbers are written so that they read back
// exactly. A spec file may be the whole ID.json (its parameters are read) or the parameters object alone;
// keys not given take the defaults of the command line.
#pragma once

#include "figures/render_figures.hpp"

#include "fv/figure_registry.hpp"

#include <stdexcept>
#include <string>

namespace fv::app {

// The parameters object (JSON text, one line) of figure `e` made from `inputs` (with_defaults applied).
// page and caption (render --page, --caption) are written only when given.
std::string parameters_json(const FigureEntry& e, const FigureInputs& inputs, int width, int height,
                            double scale, const PictureFormats& formats, PaperPage page = PaperPage::none,
                            bool caption = false);

// What a spec file asks for. size and format as the command line's --size and --format take them ("WxH",
// "png,svg"), for the caller to check as it checks those flags.
struct FigureSpecFile {
    const FigureEntry* entry = nullptr;
    FigureInputs inputs; // given; input_error checked, required parameters present
    std::string size = "1280x800";
    double scale = 1;
    std::string format = "png";
    PaperPage page = PaperPage::none; // "page": "a4" | "letter" | "column"
    bool caption = false;             // "caption": true
};

// Thrown by parse_spec_file: one line naming the key and what is allowed.
struct SpecError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// Reads a spec file's text: JSON, an object, a known id, only keys that figure takes (and size, scale,
// format), each of its type, each value admissible (fv::input_error), every required parameter given.
FigureSpecFile parse_spec_file(const std::string& text);

} // namespace fv::app
