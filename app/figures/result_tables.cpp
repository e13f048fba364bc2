// The result tables of ratio, sweep, trace and render (figure_tables.hpp writes a figure's with them).
#include "figures/result_tables.hpp"

#include "fv/units.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace fv::app {
namespace {

// 12 significant digits: well past the 1e-5 accuracy, short enough to read. Missing values are empty.
std::string num(double v) {
    if (std::isnan(v)) return "";
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.12g", v + 0.0); // + 0.0: -0 prints as 0
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
    return std::strtod(buf, nullptr) + 0.0; // + 0.0: -0 reads 0
}

// The r_x, r_y cells: empty when not a finite number (a failed row), never "nan" or "inf".
std::string ratio_num(double v) {
    return std::isfinite(v) ? num(v) : "";
}

// What a failure status means, for the text report and the stderr line.
std::string reason_of(const SweepPoint& r) {
    const SteadyResult& res = r.result;
    char buf[200];
    switch (status_of(r)) {
    case SteadyStatus::converged:
    case SteadyStatus::periodic:
        return "";
    case SteadyStatus::not_periodic:
        std::snprintf(buf, sizeof buf,
                      "the motion does not repeat within %d periods: r_x, r_y are long-time means over %d "
                      "periods, standard error %.2e",
                      kMaxPeriodK, res.window, res.mean_standard_error);
        return buf;
    case SteadyStatus::not_converged:
        std::snprintf(buf, sizeof buf, "steady state not verified after %d periods: %s; error estimate %.2e",
                      res.periods, res.detail.empty() ? "the search did not settle" : res.detail.c_str(),
                      res.error_estimate);
        return buf;
    case SteadyStatus::integration_failed:
        std::snprintf(buf, sizeof buf, "the integrator could not continue after %d periods: %s", res.periods,
                      res.detail.empty() ? "no reason given" : res.detail.c_str());
        return buf;
    case SteadyStatus::non_finite:
        return ok(res.status) ? "r_x or r_y is not a finite number"
                              : "a value that is not a finite number came up";
    case SteadyStatus::unsettled:
        return "the motion does not settle: the only periodic state found is unstable, so there is no steady "
               "r_x, r_y (the values shown are that unstable state's)";
    }
    return "";
}

// The status as printed: "ok", "period_2", or the failure's word.
std::string status_text(const SweepPoint& r) {
    return reported_word(r.result);
}

// Largest |mu| of the reported state's Floquet multipliers, NaN where none were computed (rigid model,
// the paper's scheme, limits in closed form).
double largest_multiplier(const SweepPoint& r) {
    return r.model == Model::dahl && r.result.have_multipliers ? r.result.largest_multiplier()
                                                               : std::numeric_limits<double>::quiet_NaN();
}

nlohmann::json json_multipliers(const SteadyResult& res) {
    if (!res.have_multipliers) return nullptr;
    nlohmann::json a = nlohmann::json::array();
    for (const auto& m : res.multipliers) a.push_back({jnum(m.real()), jnum(m.imag())});
    return a;
}

nlohmann::json json_of(const SweepPoint& r, bool status_known = true) {
    nlohmann::json j = {{"model", to_string(r.model)},
                        {"i", jnum(r.params.i)},
                        {"theta_deg", jnum(theta_deg(r.params))},
                        {"rdisp", jnum(r.params.rdisp)},
                        {"zeta", jnum(r.params.zeta)},
                        {"r_x", jnum(r.result.rx)},
                        {"r_y", jnum(r.result.ry)},
                        {"periods", r.result.periods},
                        {"error_estimate", jnum(r.result.error_estimate)},
                        {"status", status_known ? nlohmann::json(status_text(r)) : nlohmann::json(nullptr)},
                        {"scheme", r.model == Model::dahl ? to_string(r.result.scheme) : "quadrature"},
                        {"steps_per_period", r.result.steps_per_period},
                        {"extrapolated_levels", r.result.levels}};
    if (r.model != Model::dahl) return j;
    // Which steady state: the history it belongs to, its period, its Floquet multipliers ([re, im], |mu|
    // descending) and whether one is slow (|mu| >= 0.99: where the motion ends depends on its history).
    j["start"] = to_string(r.result.start);
    j["period_k"] = r.result.period_k;
    j["multipliers"] = json_multipliers(r.result);
    j["largest_multiplier"] = jnum(largest_multiplier(r));
    j["slow"] = r.result.slow();
    if (r.result.status == SteadyStatus::not_periodic) {
        j["standard_error"] = jnum(r.result.mean_standard_error);
        j["window_periods"] = r.result.window;
    }
    if (r.result.scheme == Scheme::ode) {
        j["start_reaches"] = r.result.start_reaches;
        j["creep_periods_skipped"] = jnum(r.result.creep_periods_skipped);
        nlohmann::json states = nlohmann::json::array();
        for (const SteadyState& x : r.result.states) {
            nlohmann::json from = nlohmann::json::array();
            if (x.from_rest) from.push_back("rest");
            if (x.from_sliding) from.push_back("sliding");
            nlohmann::json mu = nlohmann::json::array();
            for (const auto& m : x.multipliers) mu.push_back({jnum(m.real()), jnum(m.imag())});
            states.push_back({{"r_x", jnum(x.rx)},
                              {"r_y", jnum(x.ry)},
                              {"period_k", x.period},
                              {"multipliers", mu},
                              {"largest_multiplier", jnum(x.largest_multiplier())},
                              {"slow", x.slow()},
                              {"error_estimate", jnum(x.error_estimate)},
                              {"reached_from", from}});
        }
        j["states"] = states;
    }
    return j;
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

SteadyStatus status_of(const SweepPoint& r) {
    return reported_status(r.result);
}

Format parse_format(const std::string& s) {
    if (s == "csv") return Format::csv;
    if (s == "json") return Format::json;
    return Format::text;
}

std::string RatioTableStream::head() const {
    if (f_ == Format::json) return total_ == 1 ? "" : "[\n";
    return "model,i,theta_deg,rdisp,zeta,r_x,r_y,periods,error_estimate,status,start,largest_multiplier,"
           "states" +
           std::string(has_vb(v_) ? ",vb_m_s" : "") + (v_.amplitude_um ? ",zss_um" : "") + "\n";
}

std::string RatioTableStream::rows(const std::vector<SweepPoint>& rows) {
    std::string s;
    for (const auto& r : rows) {
        if (f_ == Format::json) {
            nlohmann::json j = json_of(r, statuses_known_);
            if (has_vb(v_)) j["vb_m_s"] = jnum(vb_of(r, v_));
            if (v_.amplitude_um) j["zss_um"] = jnum(zss_of(r, v_));
            if (total_ == 1) {
                s += j.dump(2);
                continue;
            }
            // As nlohmann's dump(2) of the whole array: each item indented by two more spaces.
            std::string item = j.dump(2);
            for (std::size_t k = 0; (k = item.find('\n', k)) != std::string::npos; k += 3)
                item.insert(k + 1, "  ");
            s += (done_ == 0 ? "  " : ",\n  ") + item;
            ++done_;
            continue;
        }
        s +=
            std::string(to_string(r.model)) + "," + num(r.params.i) + "," + num(theta_deg(r.params)) + "," +
            num(r.params.rdisp) + "," + num(r.params.zeta) + "," + ratio_num(r.result.rx) + "," +
            ratio_num(r.result.ry) + "," + std::to_string(r.result.periods) + "," +
            num(r.result.error_estimate) + "," + (statuses_known_ ? status_text(r) : "") + "," +
            (r.model == Model::dahl ? to_string(r.result.start) : "") + "," + num(largest_multiplier(r)) +
            "," +
            (r.model == Model::dahl && r.result.scheme == Scheme::ode ? std::to_string(r.result.states.size())
                                                                      : "");
        if (has_vb(v_)) s += "," + num(vb_of(r, v_));
        if (v_.amplitude_um) s += "," + num(zss_of(r, v_));
        s += "\n";
    }
    return s;
}

std::string RatioTableStream::tail() const {
    if (f_ != Format::json) return "";
    return total_ == 1 ? "\n" : "\n]\n";
}

std::string ratio_table(const std::vector<SweepPoint>& rows, Format f, const Vibration& vib,
                        bool statuses_known) {
    RatioTableStream t(f, vib, rows.size(), statuses_known);
    std::string s = t.head();
    s += t.rows(rows);
    return s + t.tail();
}

// Which steady state the numbers belong to, in words: the start, the period, the multipliers and what
// a slow one means (docs/model.md, "Which steady state").
// Where the state list says which starts reach a state.
std::string reached_by(const SteadyState& x) {
    if (x.from_rest && x.from_sliding) return "reached from rest and from sliding";
    if (x.from_rest) return "reached from rest";
    if (x.from_sliding) return "reached from sliding";
    return "reached from neither start";
}

std::string state_text(const SteadyResult& res) {
    std::string s = "start         " + std::string(to_string(res.start)) +
                    (res.start == Start::rest ? "   (sliding and vibration begin together, T = P)"
                                              : "   (vibration switched on during steady sliding)");
    if (res.scheme == Scheme::ode && ok(res.status))
        s += res.start_reaches ? "; its motion reaches this state"
                               : "; NOT shown that its motion reaches this state";
    s += "\n";
    if (res.states.size() > 1) {
        s += "states        " + std::to_string(res.states.size()) +
             " stable steady states (the start decides which one the motion settles into):\n";
        char buf[300];
        for (const SteadyState& x : res.states) {
            std::snprintf(buf, sizeof buf, "                r_x %.9f  r_y %.9f  period %d  |mu| %.4g  %s\n",
                          x.rx, x.ry, x.period, x.largest_multiplier(), reached_by(x).c_str());
            s += buf;
        }
    }
    if (res.status == SteadyStatus::periodic)
        s += "period        the motion repeats every " + std::to_string(res.period_k) +
             " periods of the vibration; r_x, r_y are its means over them\n";
    if (res.status == SteadyStatus::not_periodic)
        s += "window        means over " + std::to_string(res.window) + " periods, standard error " +
             num(res.mean_standard_error) + "\n";
    if (!res.have_multipliers) return s;
    char buf[300];
    const double m0 = std::abs(res.multipliers[0]), m1 = std::abs(res.multipliers[1]);
    std::snprintf(buf, sizeof buf, "multipliers   |mu| = %.4g, %.4g (Floquet, of the %s map)\n", m0, m1,
                  res.period_k == 1 ? "period" : "k-period");
    s += buf;
    if (res.slow()) {
        if (m0 >= 1)
            s +=
                "              slow: |mu| = 1, a disturbance along it does not shrink exponentially (a state "
                "on the circle with i > 1 is approached only algebraically from inside): where the motion "
                "ends depends on its history\n";
        else {
            std::snprintf(
                buf, sizeof buf,
                "              slow: a disturbance halves only after %.0f periods: where the motion "
                "ends depends on its history\n",
                std::log(0.5) / std::log(m0));
            s += buf;
        }
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
        // What the search did, not a claim about convergence speed (docs/model.md, "The periodic steady
        // state").
        auto count = [](long n, const char* one, const char* many) {
            return std::to_string(n) + " " + (n == 1 ? one : many);
        };
        s += "search        " + count(res.periods, "period", "periods") +
             " integrated: " + count(res.newton_steps, "Newton update", "Newton updates") +
             (res.on_circle ? " on the circle's angle, " : " in the plane, ") +
             count(res.plain_steps, "plain period", "plain periods") + ", " +
             count(res.periods_skipped, "stuck period", "stuck periods") + " skipped in closed form\n";
        if (res.creep_periods_skipped > 0) {
            std::snprintf(buf, sizeof buf,
                          "creep         about %.3g periods of slow creep towards the circle projected, not "
                          "integrated (i > 1: the motion from the start takes that long)\n",
                          res.creep_periods_skipped);
            s += buf;
        }
        std::snprintf(
            buf, sizeof buf,
            "steady period %d law changes, %d Radau IIA steps (the dtau -> 0 limit of the scheme)\n",
            res.events_per_period, res.steps_per_period);
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
    const SteadyStatus st = status_of(r);
    s += std::string("status        ") + status_text(r) + (ok(st) ? "" : " (" + reason_of(r) + ")") + "\n";
    if (r.model == Model::dahl) s += state_text(res);
    return s;
}

bool all_finite(const std::vector<Sample>& period) {
    for (const Sample& x : period)
        if (!std::isfinite(x.tau) || !x.P.allFinite() || !x.T.allFinite() || !std::isfinite(x.z) ||
            !x.F.allFinite())
            return false;
    return true;
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
    // The status on every row, as in ratio tables: a row read alone still says whether it is a result.
    const SteadyStatus st =
        ok(row.result.status) && !all_finite(samples) ? SteadyStatus::non_finite : row.result.status;
    const std::string status = "," + std::string(to_string(st)) + "\n";
    std::string s = "tau,Px,Py,Tx,Ty,z,Fx,Fy,status\n";
    s.reserve(samples.size() * 130);
    for (const auto& x : samples) {
        s += num(x.tau) + "," + num(x.P.x()) + "," + num(x.P.y()) + "," + num(x.T.x()) + "," + num(x.T.y()) +
             "," + num(x.z) + "," + num(x.F.x()) + "," + num(x.F.y()) + status;
    }
    return s;
}

std::string describe_failure(const SweepPoint& r) {
    std::string s =
        status_text(r) + " at zeta=" + num(r.params.zeta) + " theta=" + num(theta_deg(r.params)) + " deg";
    if (r.model == Model::dahl)
        s += " rdisp=" + num(r.params.rdisp) + " i=" + num(r.params.i);
    else
        s += " (rigid model)";
    return s + " (" + reason_of(r) + ")";
}

} // namespace fv::app
