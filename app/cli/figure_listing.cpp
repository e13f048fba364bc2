#include "figure_listing.hpp"

#include "figure_flags.hpp"
#include "render_flags.hpp"

#include "fv/figure_registry.hpp"

namespace fv::cli {
namespace {

// What the README's picture of a figure was rendered from, where that is not the figure's example inputs
// (scripts/run.sh renders fig19 from this file).
std::string readme_picture_note(const std::string& id) {
    if (id == "fig19")
        return " Shown here for the **synthetic** example `tests/data/synthetic_two_angles_rdisp2_i0.csv` "
               "(made "
               "from the model with r_disp = 2, i = 0 at both angles plus noise σ = 0.008), labelled as such "
               "on the figure: the fit gives r_disp = 1.97 ± 0.016 and picks i = 0.";
    return {};
}

// One table cell: on one line, '|' escaped.
std::string cell(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '|') out += '\\';
        out += c == '\n' ? ' ' : c;
    }
    return out;
}

std::string code(const std::string& text) {
    return "`" + text + "`";
}

} // namespace

std::string figure_list_tsv() {
    std::string s;
    for (const FigureEntry& e : figure_registry()) s += e.id + "\t" + e.title + flags_summary(e) + "\n";
    return s;
}

std::string figure_table_markdown() {
    std::string s = "| figure | what it shows |\n| --- | --- |\n";
    for (const FigureEntry& e : figure_registry()) {
        std::string text = !e.summary.empty() ? e.summary : e.make(e.example).caption;
        if (!e.params.empty())
            text += " " + code("render --figure " + e.id) + " " + flags_text(e, code) + ".";
        std::string lists;
        for (const FigureParamUse& u : e.params)
            if (u.list) lists += (lists.empty() ? "" : ", ") + code(flag_name(u.param) + " A,B,..");
        if (!lists.empty())
            text += std::string(" Lists, one ") + (e.kind == FigureKind::map ? "map" : "curve") +
                    " per combination: " + lists + ".";
        text += readme_picture_note(e.id);
        s += "| [" + e.id + "](screenshots/" + e.id + ".png) | " + cell(text) + " |\n";
    }
    return s;
}

} // namespace fv::cli
