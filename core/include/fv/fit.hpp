// Fitting the displacement ratio r_disp of the Dahl model to measured friction ratios r_x(zeta).
//
// Weighted least squares in u = ln r_disp (r_disp spans decades; the log keeps steps and the uncertainty
// meaningful): a log-spaced grid finds the basin, Gauss-Newton with central-difference Jacobians and
// backtracking refines it. Model values come from fv::steady_ratio(Model::dahl, ...) (accurate to 1e-5), one
// evaluation per point and trial r_disp, spread over threads with fv::parallel_for.
#pragma once

#include "fv/measurements.hpp"
#include "fv/steady_state.hpp"

#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fv {

// Bad fit inputs (no angle for some point, bounds out of order, ...); what() is one line.
struct FitError : std::invalid_argument {
    using std::invalid_argument::invalid_argument;
};

enum class ShapeChoice { i0, i1, automatic }; // automatic: fit both, keep the smaller AIC

struct FitOptions {
    std::optional<double> theta_deg; // angle of points without a theta_deg column value
    ShapeChoice shape = ShapeChoice::automatic;
    std::optional<double> amplitude_um;      // vibration amplitude; gives z_ss = A / r_disp in um
    double rdisp_min = 0.1, rdisp_max = 100; // search range (the accuracy contract covers [0.2, 100])
    int threads = 0;                         // 0: all cores
};

struct FitCandidate {
    double i = 0; // Dahl exponent fitted with (0 or 1)
    double rdisp = 0;
    double rdisp_sigma = 0;     // standard uncertainty (delta method: rdisp * sigma of ln rdisp)
    double log_rdisp_sigma = 0; // standard uncertainty of ln rdisp (the fitted parameter)
    bool weighted = false;      // weights 1/sigma^2 from the data; else unit weights and the uncertainty is
                                // scaled by the residual variance RSS/(n-1)
    double chi2 = 0;            // sum of weighted squared residuals (RSS when unweighted)
    int dof = 0;                // points - 1
    double reduced_chi2 = 0;    // chi2 / dof (NaN when dof == 0)
    double aic = 0;             // weighted: chi2 + 2; unweighted: n ln(RSS/n) + 2
    std::vector<double> model;  // r_x of the model at each point
    std::vector<double> residuals; // measured - model, per point
    std::optional<double> zss_um, zss_um_sigma;
    bool at_bound = false;  // r_disp ended at rdisp_min or rdisp_max: the data do not pin it inside
    bool converged = false; // Gauss-Newton step fell below tolerance
    int evaluations = 0;    // model evaluations used
    int unsteady = 0;       // evaluations that did not reach the steady state (their error is larger)
};

struct FitResult {
    FitCandidate best;
    std::vector<FitCandidate> candidates; // one per exponent tried (i = 0 first)
};

FitResult fit_rdisp(const MeasurementSet& data, const FitOptions& opt = {});

// Whether the fit's model evaluations are results the solver vouches for: converged; non_finite when a model
// value or r_disp is not a finite number; not_converged when some evaluation did not reach its steady state
// (FitCandidate::unsteady). `why` says which ("i = 0: 3 of 40 model evaluations did not reach the steady
// state"), for reports and error lines; empty when converged.
SteadyStatus fit_status(const FitResult& r, std::string& why);

} // namespace fv
