// The app's measured data and physical units: loading a CSV into the UI state, and keeping zeta, r_disp and
// the data consistent when the vibration amplitude or frequency changes.
#pragma once

#include "ui_state.hpp"

#include "fv/fit.hpp"
#include "fv/param_ranges.hpp"

#include <future>
#include <optional>
#include <string>

namespace fv::app {

// Shows `data` (read with ui's A and f) and returns the status line "loaded FILE: N points ...".
std::string show_measured(UiState& ui, MeasurementSet data);

// Reads `path` (columns as in measurements.hpp; a vb column is converted with ui's A and f) into ui.data.
// Returns the status line: "loaded FILE: N points ..." or the reader's "FILE:LINE:COL: message"; on an
// error the data shown before stay.
std::string load_measured(UiState& ui, const std::string& path);

// zeta of every point again from its v_b (Measurement::vb) under A and f, without reading the file; on an
// error ("FILE:LINE: v_b = ... gives zeta = ...; allowed: ...") `data` is unchanged.
std::string convert_vb(MeasurementSet& data, double amplitude_um, double frequency_khz);

// New amplitude and/or frequency. v_b = zeta 2 pi f A and z_ss = A / r_disp stay what they were, so
// zeta and r_disp follow (Eqs. (6), (34)); data read from a vb column are converted again from the v_b
// kept per point (convert_vb), the file is not read again. Returns an
// error line (and changes nothing) when the result leaves the allowed ranges, else "".
std::string set_vibration(UiState& ui, std::optional<double> amplitude_um,
                          std::optional<double> frequency_khz);

// ui.session.params in physical units: v_b in m/s and z_ss in um.
double vb_of(const UiState& ui);
double zss_of(const UiState& ui);

// Fitting r_disp and i to the data shown (fv::fit_rdisp, both exponents, smaller AIC) off the UI thread:
// a fit takes seconds, the window keeps drawing.
class DataFit {
  public:
    // Starts on a copy of ui.data; points without theta_deg take the angle shown. One fit at a time.
    void start(const UiState& ui);
    bool running() const { return job_.valid(); }
    // When the fit has finished (or at once with wait): the parameters with the fitted r_disp and i, and
    // the status line; std::nullopt while it runs. On a failed fit the parameters are unset.
    struct Outcome {
        std::optional<Params> params;
        std::string status;
    };
    std::optional<Outcome> poll(const UiState& ui, bool wait = false);

  private:
    struct Job {
        std::optional<FitResult> fit;
        std::string error;
    };
    std::future<Job> job_;
};

} // namespace fv::app
