// frictionviz fit: r_disp (and the exponent i) of the Dahl model fitted to measured r_x(zeta) from a CSV
// file.
#include "commands.hpp"
#include "errors.hpp"
#include "model_options.hpp"
#include "output.hpp"
#include "test_hook.hpp"

#include "fv/fit.hpp"
#include "fv/measurements.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

namespace fv::cli {

namespace {

nlohmann::json jnum(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

nlohmann::json json_of(const FitCandidate& c, const MeasurementSet& data) {
    nlohmann::json j{{"i", c.i},
                     {"rdisp", jnum(c.rdisp)},
                     {"rdisp_sigma", jnum(c.rdisp_sigma)},
                     {"log_rdisp_sigma", jnum(c.log_rdisp_sigma)},
                     {"weighted", c.weighted},
                     {"chi2", jnum(c.chi2)},
                     {"dof", c.dof},
                     {"reduced_chi2", jnum(c.reduced_chi2)},
                     {"aic", jnum(c.aic)},
                     {"zss_um", c.zss_um ? jnum(*c.zss_um) : nullptr},
                     {"zss_um_sigma", c.zss_um_sigma ? jnum(*c.zss_um_sigma) : nullptr},
                     {"at_bound", c.at_bound},
                     {"converged", c.converged},
                     {"evaluations", c.evaluations},
                     {"unsteady", c.unsteady}};
    nlohmann::json pts = nlohmann::json::array();
    for (std::size_t k = 0; k < data.points.size(); ++k)
        pts.push_back({{"line", data.points[k].line},
                       {"zeta", data.points[k].zeta},
                       {"r_x", data.points[k].rx},
                       {"model", jnum(c.model[k])},
                       {"residual", jnum(c.residuals[k])}});
    j["points"] = pts;
    return j;
}

std::string fmt(const char* f, double a, double b = 0, double c = 0) {
    char buf[256];
    std::snprintf(buf, sizeof buf, f, a, b, c);
    return buf;
}

std::string text_of(const FitResult& r, const MeasurementSet& data, const std::optional<double>& theta) {
    const FitCandidate& b = r.best;
    std::string s = "data          " + data.file + " (" + std::to_string(data.points.size()) + " points, " +
                    (b.weighted ? "weights 1/sigma^2" : "unweighted") + ")\n";
    s += "theta         " + (data.has_theta ? std::string("from the file") : fmt("%g deg", *theta)) + "\n";
    s += fmt("exponent      i = %g", b.i) +
         (r.candidates.size() > 1 ? "   (smallest AIC of i = 0 and i = 1)\n" : "   (fixed)\n");
    s += fmt("r_disp        %.4f +- %.4f   (ln r_disp +- %.4f)\n", b.rdisp, b.rdisp_sigma, b.log_rdisp_sigma);
    if (b.zss_um) s += fmt("z_ss          %.4f +- %.4f um\n", *b.zss_um, *b.zss_um_sigma);
    s += fmt(b.weighted ? "chi2          %.6g (dof %g, reduced %.4g)\n"
                        : "RSS           %.6g (dof %g, reduced %.4g)\n",
             b.chi2, b.dof, b.reduced_chi2);
    for (const FitCandidate& c : r.candidates)
        s += fmt("candidate     i = %g: r_disp = %.4f, AIC = %.4f", c.i, c.rdisp, c.aic) +
             (c.at_bound ? " (at the search bound)\n" : "\n");
    if (b.at_bound) s += "warning       r_disp ended at the search bound: the data do not determine it\n";
    s += "\n  line      zeta       r_x     model  residual\n";
    for (std::size_t k = 0; k < data.points.size(); ++k)
        s += fmt("%6.0f  %8.4f  %8.5f", data.points[k].line, data.points[k].zeta, data.points[k].rx) +
             fmt("  %8.5f  %+8.5f\n", b.model[k], b.residuals[k]);
    std::string why;
    const SteadyStatus st = fit_status(r, why);
    s += std::string("\nstatus        ") + to_string(st) + (ok(st) ? "" : " (" + why + ")") + "\n";
    return s;
}

} // namespace

Command add_fit_command(CLI::App& root) {
    struct Args {
        std::string data, shape = "auto", format = "text", out;
        double theta = 0;
        CLI::Option* theta_opt = nullptr;
        UnitArgs units; // --amplitude, --frequency
    };
    auto a = std::make_shared<Args>();
    CLI::App* cmd =
        root.add_subcommand("fit", "fit r_disp of the Dahl model to measured r_x(zeta) read from a CSV file");
    cmd->add_option("--data", a->data, "CSV file: zeta,r_x or vb,r_x [,theta_deg,sigma,label]")
        ->required()
        ->check(file_name());
    a->theta_opt =
        cmd->add_option("--theta", a->theta,
                        "vibration angle in degrees (for rows without theta_deg), " + describe(kThetaRange))
            ->transform(number_in(kThetaRange));
    cmd->add_option("--i", a->shape, "Dahl exponent: 0, 1, or auto (both, smaller AIC)")
        ->check(CLI::IsMember({"0", "1", "auto"}))
        ->capture_default_str();
    add_vibration_options(*cmd, a->units, "for a vb column (A and f) and z_ss (A)");
    cmd->add_option("--format", a->format, "output format")
        ->check(CLI::IsMember({"text", "json"}))
        ->capture_default_str();
    add_out_option(*cmd, a->out);
    return {cmd, [a] {
                check_out(a->out);
                ReadOptions ro;
                FitOptions fo;
                if (*a->units.amplitude_opt) ro.amplitude_um = fo.amplitude_um = a->units.amplitude;
                if (*a->units.frequency_opt) ro.frequency_khz = a->units.frequency;
                if (*a->theta_opt) fo.theta_deg = a->theta;
                fo.shape = a->shape == "0"   ? ShapeChoice::i0
                           : a->shape == "1" ? ShapeChoice::i1
                                             : ShapeChoice::automatic;
                MeasurementSet data;
                try {
                    data = read_measurements(a->data, ro);
                } catch (const DataError& e) {
                    throw UsageError(e.what()); // FILE:LINE:COL: message
                }
                if (!data.has_theta && !fo.theta_deg)
                    throw UsageError("--theta is required: " + a->data + " has no theta_deg column");
                FitResult r;
                try {
                    r = fit_rdisp(data, fo);
                } catch (const FitError& e) {
                    throw UsageError(e.what());
                }
                apply_test_hook(r);
                std::string why;
                const SteadyStatus st = fit_status(r, why);
                std::string content;
                if (a->format == "json") {
                    nlohmann::json j{
                        {"file", data.file}, {"status", to_string(st)}, {"best", json_of(r.best, data)}};
                    j["candidates"] = nlohmann::json::array();
                    for (const FitCandidate& c : r.candidates) j["candidates"].push_back(json_of(c, data));
                    content = j.dump(2) + "\n";
                } else {
                    content = text_of(r, data, fo.theta_deg);
                }
                deliver(content, a->out);
                // Written with its status; a fit on model values the solver does not vouch for exits 3.
                if (!ok(st)) throw NumericalFailure(std::string("fit: ") + to_string(st) + " (" + why + ")");
            }};
}

} // namespace fv::cli
