// The model flags shared by every command that computes something (ratio, sweep, trace, render scene).
#pragma once

#include "unit_options.hpp"
#include "validators.hpp"

#include "fv/params.hpp"
#include "fv/steady_state.hpp"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>

namespace fv::cli {

// The parameters' ranges (kZetaRange, kThetaRange, kRdispRange, kIRange) are core's table,
// fv/param_ranges.hpp, shared with the data reader and the app.
inline constexpr long kMinSteps = 8, kMaxSteps = 1L << 24;
inline constexpr int kMaxSweepPoints = 100000; // COUNT of a sweep's FROM:TO:COUNT
// The rows of one sweep (the product of its axes). Rows stream out as they are computed, so memory does not
// grow with the grid; the limit bounds the time and the file: 1e7 rows are ~1.3 GB of CSV and, at the
// domain's median 0.03 ms a point on 2 cores, minutes; at the slow i = 10 bands, hours.
inline constexpr long long kMaxSweepRows = 10000000;

// --scheme ode|paper and --steps-per-period N (which means the paper's scheme as printed).
struct SolverArgs {
    std::string scheme = "ode";
    int steps_per_period = 0;
    double tolerance = 0;       // --tolerance: the ode scheme's target; 0: the default (SteadyOptions)
    std::string start = "rest"; // --start: the history that decides between coexisting steady states
    CLI::Option* scheme_opt = nullptr;
};
void add_solver_options(CLI::App& cmd, SolverArgs& s);
// --lesson N (1 to the number of lesson steps, gui/lessons.hpp): a lesson step's setup in place of the model
// and unit flags (call after they are added; it excludes those the command has). `what`: the help's start.
CLI::Option* add_lesson_option(CLI::App& cmd, int& lesson, const std::string& what);

// --start rest|sliding with this help (add_solver_options; render and gui with their own words), and the
// start given on the command line, if any.
CLI::Option* add_start_option(CLI::App& cmd, std::string& start, const std::string& help);
std::optional<Start> given_start(const CLI::App& cmd, const std::string& start);
// Throws UsageError for --scheme ode together with --steps-per-period.
SteadyOptions solver_options(const SolverArgs& s);

struct ModelArgs {
    std::string model = "dahl";
    double zeta = 0, theta_deg = 0, rdisp = 0, i = 0;
    SolverArgs solver;
    UnitArgs units; // --vb, --zss, --amplitude, --frequency where the command registers them
    CLI::Option* zeta_opt = nullptr;
    CLI::Option* rdisp_opt = nullptr;
    CLI::Option* i_opt = nullptr;
};

// Adds --zeta --theta --rdisp --i (all required for the Dahl model; --vb and --zss of unit_options.hpp,
// added by the command, stand in for --zeta and --rdisp), optionally --model, and the solver options.
void add_model_options(CLI::App& cmd, ModelArgs& a, bool with_model_choice);

// Checks the combination (e.g. --rdisp or --zss is required for the Dahl model) and converts --vb and --zss;
// throws UsageError.
Params to_params(const ModelArgs& a);
Model model_of(const ModelArgs& a);
SteadyOptions steady_options(const ModelArgs& a);

} // namespace fv::cli
