// frictionviz ratio: r_x and r_y of one parameter set (Eq. (33) / Eq. (9)).
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "test_hook.hpp"

#include <memory>

namespace fv::cli {

Command add_ratio_command(CLI::App& root) {
    struct Args {
        ModelArgs model;
        std::string format = "text";
        std::string out;
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd =
        root.add_subcommand("ratio", "friction ratios r_x, r_y of one parameter set in steady state");
    add_model_options(*cmd, a->model, true);
    add_unit_options(*cmd, a->model.units, UnitShape::single,
                     "the output also shows v_b, v_v (A and f) and z_ss (A)");
    cmd->add_option("--format", a->format, "output format")
        ->check(CLI::IsMember({"text", "csv", "json"}))
        ->capture_default_str();
    add_out_option(*cmd, a->out);
    return {cmd, [a] {
                check_out(a->out);
                SweepPoint row;
                row.model = model_of(a->model);
                row.params = to_params(a->model);
                const Vibration v = vibration_of(a->model.units, row.model == Model::dahl
                                                                     ? std::vector<double>{row.params.rdisp}
                                                                     : std::vector<double>{});
                row.result = steady_ratio(row.model, row.params, steady_options(a->model));
                if (row.model == Model::rigid) {
                    row.params.rdisp = std::numeric_limits<double>::quiet_NaN();
                    row.params.i = std::numeric_limits<double>::quiet_NaN();
                }
                apply_test_hook(row);
                const Format f = parse_format(a->format);
                deliver(f == Format::text ? ratio_text(row, v) : ratio_table({row}, f, v), a->out);
                // Written with its status; the exit status says it is not a result (3).
                if (!ok(status_of(row))) throw NumericalFailure(describe_failure(row));
            }};
}

} // namespace fv::cli
