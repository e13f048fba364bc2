#include "measured_data.hpp"

#include "fv/format.hpp"
#include "fv/units.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <vector>

namespace fv::app {
namespace {

ReadOptions read_options(const UiState& ui) {
    ReadOptions o;
    o.amplitude_um = ui.session.amplitude_um;
    o.frequency_khz = ui.session.frequency_khz;
    return o;
}

std::string describe(const MeasurementSet& d, const UiState& ui) {
    std::string s = "loaded " + std::filesystem::path(d.file).filename().string() + ": " +
                    std::to_string(d.points.size()) + " point" + (d.points.size() == 1 ? "" : "s");
    if (d.from_vb)
        s += ", v_b converted with A = " + format_number("%g", ui.session.amplitude_um) +
             " µm, f = " + format_number("%g", ui.session.frequency_khz) + " kHz";
    return s;
}

} // namespace

std::string show_measured(UiState& ui, MeasurementSet data) {
    const std::string msg = describe(data, ui);
    ui.data = std::move(data);
    ui.data_is_example = false;
    return msg;
}

std::string load_measured(UiState& ui, const std::string& path) {
    try {
        MeasurementSet d = read_measurements(path, read_options(ui));
        if (d.points.empty()) return path + ": no data rows; nothing to show";
        return show_measured(ui, std::move(d));
    } catch (const DataError& e) {
        return e.what();
    }
}

std::string set_vibration(UiState& ui, std::optional<double> amplitude_um,
                          std::optional<double> frequency_khz) {
    UiState next = ui;
    if (amplitude_um) next.session.amplitude_um = *amplitude_um;
    if (frequency_khz) next.session.frequency_khz = *frequency_khz;
    try {
        // Same v_b and z_ss under the new vibration.
        next.session.params.zeta =
            units::zeta_from_vb(vb_of(ui), next.session.amplitude_um, next.session.frequency_khz);
        next.session.params.rdisp = units::rdisp_from_zss(next.session.amplitude_um, zss_of(ui));
    } catch (const units::UnitError& e) {
        return e.what();
    }
    std::string bad = range_error(next.session.params);
    if (bad.empty())
        bad = units::physical_view_error(next.session.params, next.session.amplitude_um,
                                         next.session.frequency_khz);
    if (!bad.empty())
        return "A = " + format_number("%g", next.session.amplitude_um) +
               " µm, f = " + format_number("%g", next.session.frequency_khz) +
               " kHz at the same v_b and z_ss: " + bad;
    if (next.data && next.data->from_vb)
        if (std::string why = convert_vb(*next.data, next.session.amplitude_um, next.session.frequency_khz);
            !why.empty())
            return why;
    ui = std::move(next);
    return "";
}

std::string convert_vb(MeasurementSet& data, double amplitude_um, double frequency_khz) {
    std::vector<double> zetas;
    zetas.reserve(data.points.size());
    for (const Measurement& m : data.points) {
        if (!m.vb) return data.file + ": no v_b kept for line " + std::to_string(m.line);
        double zeta = HUGE_VAL;
        try {
            zeta = units::zeta_from_vb(*m.vb, amplitude_um, frequency_khz);
        } catch (const units::UnitError&) {
            // v_b / v_v beyond the doubles: out of the zeta range below
        }
        if (!inside(zeta, kZetaRange))
            return data.file + ":" + std::to_string(m.line) + ": v_b = " + format_number("%g", *m.vb) +
                   " m/s gives zeta = " + format_number("%.4g", zeta) +
                   " at A = " + format_number("%g", amplitude_um) +
                   " µm, f = " + format_number("%g", frequency_khz) + " kHz; allowed: zeta in " +
                   describe(kZetaRange);
        zetas.push_back(zeta);
    }
    for (std::size_t k = 0; k < zetas.size(); ++k) data.points[k].zeta = zetas[k];
    return "";
}

void DataFit::start(const UiState& ui) {
    if (running() || !ui.data) return;
    FitOptions o;
    o.theta_deg = ui.session.params.theta * 180 / kPi;
    o.shape = ShapeChoice::automatic;
    o.amplitude_um = ui.session.amplitude_um;
    o.threads = 1; // the renderer keeps the other core
    job_ = std::async(std::launch::async, [data = *ui.data, o] {
        Job j;
        try {
            j.fit = fit_rdisp(data, o);
        } catch (const FitError& e) {
            j.error = e.what();
        }
        return j;
    });
}

std::optional<DataFit::Outcome> DataFit::poll(const UiState& ui, bool wait) {
    if (!running()) return std::nullopt;
    if (!wait && job_.wait_for(std::chrono::seconds(0)) != std::future_status::ready) return std::nullopt;
    const Job j = job_.get();
    Outcome out;
    if (!j.fit) {
        out.status = "fit failed: " + j.error;
        return out;
    }
    const FitCandidate& b = j.fit->best;
    Params p = ui.session.params;
    p.rdisp = b.rdisp;
    p.i = b.i;
    out.params = p;
    out.status = "fit: r_disp = " + format_number("%.4g", b.rdisp) + " ± " +
                 format_number("%.2g", b.rdisp_sigma) +
                 " (z_ss = " + format_number("%.4g", b.zss_um.value_or(NAN)) +
                 " µm), i = " + format_number("%g", b.i) + " (smaller AIC); " +
                 (b.weighted ? "reduced χ² = " : "RSS/dof = ") + format_number("%.3g", b.reduced_chi2);
    if (b.at_bound) out.status += "; r_disp is at the search bound: the data do not pin it";
    return out;
}

double vb_of(const UiState& ui) {
    return units::vb_from_zeta(ui.session.params.zeta, ui.session.amplitude_um, ui.session.frequency_khz);
}

double zss_of(const UiState& ui) {
    return units::zss_from_rdisp(ui.session.params.rdisp, ui.session.amplitude_um);
}

} // namespace fv::app
