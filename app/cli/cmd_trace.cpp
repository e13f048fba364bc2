// frictionviz trace: P, T, z and F over one steady-state period (continuous-time solver: 1024 samples at
// tau = 2 pi k/1024; --scheme paper: every step of the paper's scheme).
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "test_hook.hpp"

#include <memory>

namespace fv::cli {

Command add_trace_command(CLI::App& root) {
    struct Args {
        ModelArgs model;
        std::string format = "csv";
        std::string out;
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd = root.add_subcommand(
        "trace", "one steady-state period of the Dahl model: tau,Px,Py,Tx,Ty,z,Fx,Fy (dimensionless)");
    add_model_options(*cmd, a->model, false);
    add_unit_options(*cmd, a->model.units, UnitShape::single, "");
    cmd->add_option("--format", a->format, "output format")
        ->check(CLI::IsMember({"csv", "json"}))
        ->capture_default_str();
    add_out_option(*cmd, a->out);
    return {cmd, [a] {
                check_out(a->out);
                SweepPoint row;
                row.params = to_params(a->model);
                SteadyOptions o = steady_options(a->model);
                o.record_period = true;
                row.result = steady_ratio(Model::dahl, row.params, o);
                if (ok(row.result.status) && !all_finite(row.result.period))
                    row.result.status = SteadyStatus::non_finite;
                apply_test_hook(row);
                deliver(trace_table(row, parse_format(a->format)), a->out);
                // The period is written all the same; it is not the steady state the solver vouches for.
                if (!ok(status_of(row)))
                    throw NumericalFailure("the steady state behind the trace failed: " +
                                           describe_failure(row));
            }};
}

} // namespace fv::cli
