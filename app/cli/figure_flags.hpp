// The command line's names for the figures' parameters (fv::FigureParam): the flag of each, its
// physical-unit alternative (--vb for --zeta, --zss for --rdisp) and the vibration flags that alternative
// needs. The help, the error messages, `render --list` and the README's table all say it from here.
#pragma once

#include "fv/figure_registry.hpp"

#include <functional>
#include <string>
#include <vector>

namespace fv::cli {

// How a flag is written: as is in messages, `--zeta` in markdown.
using FlagQuote = std::function<std::string(const std::string&)>;

// "--zeta or --vb" (quote applied to each flag).
std::string param_flag_text(FigureParam p, const FlagQuote& quote = {});

// The parameters `e` takes on the command line: its own, then the vibration flags its unit alternatives need
// (optional), with the start last.
std::vector<FigureParamUse> command_line_params(const FigureEntry& e);

// "needs --zeta or --vb, --theta; optional --amplitude" or "takes --rdisp or --zss, --i".
std::string flags_text(const FigureEntry& e, const FlagQuote& quote = {});

// " (needs --data; optional --theta)", " (--zeta, --theta)": the figure's own parameters by their main flag,
// for a one-line list; empty for a fixed figure.
std::string flags_summary(const FigureEntry& e);

// "scene, map": the figures that take `p` on the command line.
std::string figures_taking(FigureParam p);

} // namespace fv::cli
