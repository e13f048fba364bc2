#include "output.hpp"

#include "errors.hpp"

#include "fv/atomic_file.hpp"
#include "fv/units.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <limits>

namespace fv::cli {
namespace {

// 12 significant digits: well past the 1e-5 accuracy, short enough to read. Missing values are empty.
std::string num(double v) {
    if (std::isnan(v)) return "";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.12g", v);
    return buf;
}

// NaN and infinities become null in JSON (nlohmann does this for NaN; be explicit for both).
nlohmann::json jnum(double v) {
    return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

// Degrees back from radians, rounded to 12 significant digits so that 30 reads 30, not 29.999999999999996.
double theta_deg(const Params& p) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.12g", p.theta * 180 / kPi);
    return std::strtod(buf, nullptr);
}

nlohmann::json json_of(const SweepPoint& r) {
    return {{"model", to_string(r.model)},
            {"i", jnum(r.params.i)},
            {"theta_deg", jnum(theta_deg(r.params))},
            {"rdisp", jnum(r.params.rdisp)},
            {"zeta", jnum(r.params.zeta)},
            {"r_x", jnum(r.result.rx)},
            {"r_y", jnum(r.result.ry)},
            {"periods", r.result.periods},
            {"error_estimate", jnum(r.result.error_estimate)},
            {"status", to_string(r.result.status)},
            {"scheme", r.model == Model::dahl ? to_string(r.result.scheme) : "quadrature"},
            {"steps_per_period", r.result.steps_per_period},
            {"extrapolated_levels", r.result.levels}};
}

bool has_vb(const Vibration& v) {
    return v.amplitude_um && v.frequency_khz;
}

double vb_of(const SweepPoint& r, const Vibration& v) {
    return units::vb_from_zeta(r.params.zeta, *v.amplitude_um, *v.frequency_khz);
}

// NaN (shown empty or null) for the rigid model, which has no z_ss.
double zss_of(const SweepPoint& r, const Vibration& v) {
    return r.model == Model::dahl ? units::zss_from_rdisp(r.params.rdisp, *v.amplitude_um)
                                  : std::numeric_limits<double>::quiet_NaN();
}

} // namespace

Format parse_format(const std::string& s) {
    if (s == "csv") return Format::csv;
    if (s == "json") return Format::json;
    return Format::text;
}

std::string ratio_table(const std::vector<SweepPoint>& rows, Format f, const Vibration& vib) {
    if (f == Format::json) {
        nlohmann::json arr = nlohmann::json::array();
        for (const auto& r : rows) {
            nlohmann::json j = json_of(r);
            if (has_vb(vib)) j["vb_m_s"] = jnum(vb_of(r, vib));
            if (vib.amplitude_um) j["zss_um"] = jnum(zss_of(r, vib));
            arr.push_back(j);
        }
        return (rows.size() == 1 ? arr[0] : arr).dump(2) + "\n";
    }
    std::string s = "model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate";
    s += std::string(has_vb(vib) ? ",vb_m_s" : "") + (vib.amplitude_um ? ",zss_um" : "") + "\n";
    for (const auto& r : rows) {
        s += std::string(to_string(r.model)) + "," + num(r.params.i) + "," + num(theta_deg(r.params)) + "," +
             num(r.params.rdisp) + "," + num(r.params.zeta) + "," + num(r.result.rx) + "," +
             num(r.result.ry) + "," + std::to_string(r.result.periods) + "," + num(r.result.error_estimate);
        if (has_vb(vib)) s += "," + num(vb_of(r, vib));
        if (vib.amplitude_um) s += "," + num(zss_of(r, vib));
        s += "\n";
    }
    return s;
}

std::string ratio_text(const SweepPoint& r, const Vibration& vib) {
    char buf[1024];
    const auto& p = r.params;
    const auto& res = r.result;
    std::string s;
    if (r.model == Model::rigid) {
        std::snprintf(buf, sizeof buf,
                      "model         rigid Coulomb, Eq. (9)\n"
                      "zeta          %s\ntheta         %s deg\n",
                      num(p.zeta).c_str(), num(theta_deg(p)).c_str());
        s = buf;
    } else {
        std::snprintf(buf, sizeof buf,
                      "model         Dahl, i = %s%s\n"
                      "zeta          %s\ntheta         %s deg\nrdisp         %s   (z_ss = %s x_v)\n",
                      num(p.i).c_str(), p.i == 0 ? " (stiction, Eq. (27))" : "", num(p.zeta).c_str(),
                      num(theta_deg(p)).c_str(), num(p.rdisp).c_str(), num(1 / p.rdisp).c_str());
        s = buf;
    }
    // The physical view, as far as the command line gave the vibration.
    if (vib.amplitude_um) s += "amplitude     " + num(*vib.amplitude_um) + " um\n";
    if (has_vb(vib)) {
        s += "frequency     " + num(*vib.frequency_khz) + " kHz\n";
        s += "v_v           " + num(units::vibration_velocity(*vib.amplitude_um, *vib.frequency_khz)) +
             " m/s   (2 pi f A)\n";
        s += "v_b           " + num(vb_of(r, vib)) + " m/s   (zeta v_v)\n";
    }
    if (vib.amplitude_um && r.model == Model::dahl)
        s += "z_ss          " + num(zss_of(r, vib)) + " um   (A/rdisp)\n";
    // Values below the printed precision are shown as 0, not as "-0.000000000".
    auto shown = [](double v) { return std::abs(v) < 5e-10 ? 0.0 : v; };
    std::snprintf(buf, sizeof buf, "r_x           %.9f\nr_y           %.9f\n", shown(res.rx), shown(res.ry));
    s += buf;
    if (r.model == Model::dahl && res.scheme == Scheme::ode) {
        std::snprintf(
            buf, sizeof buf,
            "steady state  %s after %d periods (continuous-time solver: dtau -> 0 limit of the scheme, "
            "events located, Newton)\n",
            res.status == SteadyStatus::converged ? "reached" : "NOT reached", res.periods);
        s += buf;
    } else if (r.model == Model::dahl) {
        if (res.levels > 1)
            std::snprintf(buf, sizeof buf,
                          "steady state  %s after %d periods (up to %d steps per period, %d resolutions "
                          "extrapolated to dtau -> 0)\n",
                          res.status == SteadyStatus::converged ? "reached" : "NOT reached", res.periods,
                          res.steps_per_period, res.levels);
        else
            std::snprintf(buf, sizeof buf,
                          "steady state  %s after %d periods (%d steps per period, paper's scheme as is)\n",
                          res.status == SteadyStatus::converged ? "reached" : "NOT reached", res.periods,
                          res.steps_per_period);
        s += buf;
    }
    std::snprintf(buf, sizeof buf, "error est.    %.2e\n", res.error_estimate);
    s += buf;
    return s;
}

std::string trace_table(const SweepPoint& row, Format f) {
    const auto& samples = row.result.period;
    if (f == Format::json) {
        nlohmann::json j = json_of(row);
        nlohmann::json cols;
        for (const char* c : {"tau", "Px", "Py", "Tx", "Ty", "z", "Fx", "Fy"})
            cols[c] = nlohmann::json::array();
        for (const auto& s : samples) {
            cols["tau"].push_back(s.tau);
            cols["Px"].push_back(s.P.x());
            cols["Py"].push_back(s.P.y());
            cols["Tx"].push_back(s.T.x());
            cols["Ty"].push_back(s.T.y());
            cols["z"].push_back(s.z);
            cols["Fx"].push_back(s.F.x());
            cols["Fy"].push_back(s.F.y());
        }
        j["trace"] = cols;
        return j.dump(1) + "\n";
    }
    std::string s = "tau,Px,Py,Tx,Ty,z,Fx,Fy\n";
    s.reserve(samples.size() * 120);
    for (const auto& x : samples) {
        s += num(x.tau) + "," + num(x.P.x()) + "," + num(x.P.y()) + "," + num(x.T.x()) + "," + num(x.T.y()) +
             "," + num(x.z) + "," + num(x.F.x()) + "," + num(x.F.y()) + "\n";
    }
    return s;
}

void check_out(const std::string& out, const char* flag) {
    if (out.empty()) return;
    if (auto why = check_writable(out); !why.empty()) throw UsageError(std::string(flag) + ": " + why);
}

void deliver(const std::string& content, const std::string& out) {
    if (out.empty()) {
        std::cout << content << std::flush;
        if (!std::cout) throw RuntimeFailure("cannot write to standard output");
        return;
    }
    if (auto why = write_file_atomic(out, content); !why.empty()) throw RuntimeFailure(why);
}

void warn_if_unsteady(const SweepPoint& row) {
    if (row.model != Model::dahl || row.result.status == SteadyStatus::converged) return;
    std::fprintf(
        stderr,
        "frictionviz: warning: steady state not reached for zeta=%g theta=%g rdisp=%g i=%g after %d periods; "
        "error estimate %.2e\n",
        row.params.zeta, theta_deg(row.params), row.params.rdisp, row.params.i, row.result.periods,
        row.result.error_estimate);
}

} // namespace fv::cli
