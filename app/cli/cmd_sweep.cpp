// frictionviz sweep: r_x(zeta) for families of theta, rdisp and i (the data behind Figs. 5, 10-13).
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "test_hook.hpp"

#include "fv/atomic_file.hpp"
#include "fv/sweep.hpp"

#include <climits>
#include <cstdint>
#include <cstdio>

#include <memory>

namespace fv::cli {
namespace {

// "zeta 100000 x theta 181 x rdisp 2 x i 1 = 36200000 rows" (the rigid model: zeta x theta).
std::string grid_text(Model model, std::size_t nz, std::size_t nt, std::size_t nr, std::size_t ni) {
    std::string s = "zeta " + std::to_string(nz) + " x theta " + std::to_string(nt);
    if (model == Model::dahl) s += " x rdisp " + std::to_string(nr) + " x i " + std::to_string(ni);
    const std::size_t n = sweep_size(model, nz, nt, nr, ni);
    return s + " = " + (n == SIZE_MAX ? std::string("more than 1.8e19") : std::to_string(n)) + " rows";
}

// Where a sweep's rows go: standard output ("-") or a file by the output-path policy. Text is written in
// pieces of whole rows of at most PIPE_BUF bytes, each one write(2) (atomic on a pipe), so a reader of an
// interrupted run sees whole rows only.
class RowSink {
  public:
    explicit RowSink(const std::string& out) {
        std::fflush(stdout);
        if (const std::string why = stream_.open(out == "-" ? "/dev/stdout" : out); !why.empty())
            throw RuntimeFailure(why);
    }
    void write(const std::string& text) {
        for (std::size_t from = 0; from < text.size();) {
            std::size_t to = text.size();
            if (to - from > PIPE_BUF) {
                const std::size_t nl = text.rfind('\n', from + PIPE_BUF - 1);
                to = nl != std::string::npos && nl >= from ? nl + 1 : from + PIPE_BUF;
            }
            if (const std::string why = stream_.write(std::string_view(text).substr(from, to - from));
                !why.empty())
                throw RuntimeFailure(why);
            from = to;
        }
    }
    void commit() {
        if (const std::string why = stream_.commit(); !why.empty()) throw RuntimeFailure(why);
    }

  private:
    OutputStream stream_;
};

} // namespace

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
    return {
        cmd, [a, zo, rd, ii] {
            const Model model = a->model == "rigid" ? Model::rigid : Model::dahl;
            const RangeSpec z = zeta_range_of(zo, a->zeta, a->units);
            // The rigid model ignores r_disp, but a given --zss is still checked like a given --rdisp.
            const std::vector<double> rdisps = rdisps_of(rd, a->rdisp, a->units, model == Model::dahl);
            if (model == Model::dahl && ii->count() == 0)
                throw UsageError("--i is required for the Dahl model; allowed: numbers in " +
                                 describe(kIRange));
            const Vibration v = vibration_of(a->units, model == Model::dahl ? rdisps : std::vector<double>{});
            check_out(a->out);
            std::vector<double> thetas;
            for (double t : a->theta_deg) thetas.push_back(t * kPi / 180);
            const std::vector<double> zetas = linspace(z.from, z.to, z.count);
            const std::size_t total =
                sweep_size(model, zetas.size(), thetas.size(), rdisps.size(), a->i.size());
            if (total > static_cast<std::size_t>(kMaxSweepRows))
                throw UsageError(grid_text(model, zetas.size(), thetas.size(), rdisps.size(), a->i.size()) +
                                 "; allowed: at most " + std::to_string(kMaxSweepRows) +
                                 " rows in one sweep (split the grid into several runs)");
            // Rows stream out block by block in grid order as they are computed: memory does not grow
            // with the grid, and an interrupted run to standard output leaves whole rows (a file target
            // is replaced only when the last row is written).
            RowSink sink(a->out);
            RatioTableStream table(parse_format(a->format), v, total);
            FailureLog failures;
            sink.write(table.head());
            sweep_blocks(model, zetas, thetas, rdisps, a->i, solver_options(a->solver), a->threads, 256,
                         [&](const std::vector<SweepPoint>& block) {
                             std::vector<SweepPoint> rows = block;
                             apply_test_hook(rows);
                             failures.add(rows);
                             sink.write(table.rows(rows));
                             return true;
                         });
            sink.write(table.tail());
            sink.commit();
            // Every row is written, failed ones with their reason in the status column; then exit 3.
            if (const Failures f = failures.failures(); f.count > 0) {
                failures.print();
                throw NumericalFailure(std::to_string(f.count) + " of " + std::to_string(total) +
                                       " rows failed (" + f.by_reason +
                                       "); all rows are in the output, each with its status");
            }
        }};
}

} // namespace fv::cli
