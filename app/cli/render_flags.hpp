// render's figure flags: --zeta NUMBER or FROM:TO, --theta/--rdisp/--i as comma-separated lists, --model
// dahl,rigid, --data, --start and the unit alternatives (--vb, --zss with --amplitude, --frequency), turned
// into fv::FigureInputs. Each list is read by core (fv/figure_family.hpp), as a spec file's and the Python
// module's are; which figure takes a list and which one value is the registry's (fv::input_error).
#pragma once

#include "unit_options.hpp"

#include "fv/figure_registry.hpp"

#include <CLI/CLI.hpp>

#include <string>

namespace fv::cli {

struct RenderFlags {
    std::string zeta, theta, rdisp, i, model, data, start;
    UnitArgs units; // --amplitude, --frequency (fig19, rx), --vb, --zss (scene, map)
    CLI::Option *zeta_opt = nullptr, *theta_opt = nullptr, *rdisp_opt = nullptr, *i_opt = nullptr,
                *model_opt = nullptr, *data_opt = nullptr, *start_opt = nullptr;
};

// Adds the flags to `cmd`.
void add_render_flags(CLI::App& cmd, RenderFlags& f);

// The inputs the flags give (--vb and --zss converted); UsageError for a conversion that fails or both
// alternatives given.
FigureInputs inputs_of(const RenderFlags& f);

// The first figure flag given ("--theta"), empty if none (--spec takes none of them).
std::string first_given(const RenderFlags& f);

// The command line's name of parameter `p` in messages: "--theta", "--zeta".
std::string flag_name(FigureParam p);

} // namespace fv::cli
