// frictionviz sweep: r_x(zeta) for families of theta, rdisp and i (the data behind Figs. 5, 10-13).
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "test_hook.hpp"

#include "fv/sweep.hpp"

#include <memory>

namespace fv::cli {

Command add_sweep_command(CLI::App& root) {
    struct Args {
        std::string model = "dahl";
        std::string zeta;
        std::vector<double> theta_deg, rdisp, i;
        SolverArgs solver;
        UnitArgs units;
        int threads = 0;
        std::string format = "csv";
        std::string out;
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd =
        root.add_subcommand("sweep", "r_x, r_y over a grid of zeta for families of theta, rdisp, i");
    auto* zo = cmd->add_option("--zeta", a->zeta,
                               "zeta values FROM:TO:COUNT (evenly spaced, both ends included; or --vb)")
                   ->check(range_spec(kZetaRange, kMaxSweepPoints));
    add_number_list(*cmd, "--theta", a->theta_deg, kThetaRange,
                    "vibration angles in degrees, comma separated")
        ->required();
    auto* rd = add_number_list(*cmd, "--rdisp", a->rdisp, kRdispRange,
                               "displacement ratios, comma separated (or --zss; Dahl only)");
    auto* ii = add_number_list(*cmd, "--i", a->i, kIRange, "Dahl exponents, comma separated (Dahl only)");
    cmd->add_option("--model", a->model, "friction model")
        ->check(CLI::IsMember({"dahl", "rigid"}))
        ->capture_default_str();
    add_solver_options(*cmd, a->solver);
    add_unit_options(*cmd, a->units, UnitShape::sweep, "the output also has vb_m_s (A and f) and zss_um (A)");
    cmd->add_option("--threads", a->threads, "worker threads (default: all cores)")
        ->check(integer_in(1, 256));
    cmd->add_option("--format", a->format, "output format")
        ->check(CLI::IsMember({"csv", "json"}))
        ->capture_default_str();
    add_out_option(*cmd, a->out);
    return {cmd, [a, zo, rd, ii] {
                const Model model = a->model == "rigid" ? Model::rigid : Model::dahl;
                const RangeSpec z = zeta_range_of(zo, a->zeta, a->units);
                // The rigid model ignores r_disp, but a given --zss is still checked like a given --rdisp.
                const std::vector<double> rdisps = rdisps_of(rd, a->rdisp, a->units, model == Model::dahl);
                if (model == Model::dahl && ii->count() == 0)
                    throw UsageError("--i is required for the Dahl model; allowed: numbers in " +
                                     describe(kIRange));
                const Vibration v =
                    vibration_of(a->units, model == Model::dahl ? rdisps : std::vector<double>{});
                check_out(a->out);
                std::vector<double> thetas;
                for (double t : a->theta_deg) thetas.push_back(t * kPi / 180);
                const SteadyOptions o = solver_options(a->solver);
                auto rows =
                    sweep(model, linspace(z.from, z.to, z.count), thetas, rdisps, a->i, o, a->threads);
                apply_test_hook(rows);
                deliver(ratio_table(rows, parse_format(a->format), v), a->out);
                // Every row is written, failed ones with their reason in the status column; then exit 3.
                if (const Failures f = failures_of(rows); f.count > 0) {
                    print_failures(rows);
                    throw NumericalFailure(std::to_string(f.count) + " of " + std::to_string(rows.size()) +
                                           " rows failed (" + f.by_reason +
                                           "); all rows are in the output, each with its status");
                }
            }};
}

} // namespace fv::cli
