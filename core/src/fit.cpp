#include "fv/fit.hpp"

#include "fv/steady_state.hpp"
#include "fv/sweep.hpp"
#include "fv/units.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace fv {

namespace {

// Grid over [ln rdisp_min, ln rdisp_max]: ~1.8x apart on the default range, fine enough that the
// least-squares basin (r_x varies smoothly and monotonically with r_disp at fixed zeta) is bracketed by grid
// neighbours.
constexpr int kGrid = 13;
// Central-difference step in ln rdisp: large enough that model noise (~1e-5) stays far below the difference,
// small enough that the O(h^2) truncation is negligible next to the uncertainty.
constexpr double kH = 0.02;
constexpr double kTolU = 1e-4; // stop when the Gauss-Newton step in ln rdisp is below this
constexpr int kMaxIter = 12;

class Problem {
  public:
    Problem(const MeasurementSet& data, const FitOptions& opt, double i)
        : i_(i), threads_(opt.threads), y_(data.points.size()), w_(data.points.size()),
          theta_(data.points.size()), zeta_(data.points.size()) {
        for (std::size_t k = 0; k < data.points.size(); ++k) {
            const Measurement& m = data.points[k];
            const auto kk = static_cast<Eigen::Index>(k);
            y_[kk] = m.rx;
            w_[kk] = m.sigma ? 1 / (*m.sigma * *m.sigma) : 1.0;
            theta_[kk] = (m.theta_deg ? *m.theta_deg : *opt.theta_deg) * kPi / 180;
            zeta_[kk] = m.zeta;
        }
    }

    // Model r_x at every point for each ln rdisp in `us`, all (point, u) pairs spread over the threads.
    std::vector<Eigen::VectorXd> model(const std::vector<double>& us) {
        const int n = static_cast<int>(y_.size());
        std::vector<Eigen::VectorXd> out(us.size(), Eigen::VectorXd(n));
        std::vector<char> unsteady(us.size() * static_cast<std::size_t>(n), 0);
        parallel_for(
            static_cast<int>(us.size()) * n,
            [&](int job) {
                const int j = job / n, k = job % n;
                Params p;
                p.zeta = zeta_[k];
                p.theta = theta_[k];
                p.rdisp = std::exp(us[static_cast<std::size_t>(j)]);
                p.i = i_;
                const SteadyResult r = steady_ratio(Model::dahl, p);
                out[static_cast<std::size_t>(j)][k] = r.rx;
                unsteady[static_cast<std::size_t>(job)] = r.status != SteadyStatus::converged;
            },
            threads_);
        evaluations += static_cast<int>(unsteady.size());
        unsteady_count += static_cast<int>(std::count(unsteady.begin(), unsteady.end(), 1));
        return out;
    }

    double chi2(const Eigen::VectorXd& m) const { return (w_.array() * (y_ - m).array().square()).sum(); }
    const Eigen::VectorXd& y() const { return y_; }
    const Eigen::VectorXd& w() const { return w_; }
    Eigen::Index size() const { return y_.size(); }

    int evaluations = 0, unsteady_count = 0;

  private:
    double i_;
    int threads_;
    Eigen::VectorXd y_, w_, theta_, zeta_;
};

FitCandidate fit_one(const MeasurementSet& data, const FitOptions& opt, double i) {
    Problem pr(data, opt, i);
    const double lo = std::log(opt.rdisp_min), hi = std::log(opt.rdisp_max);

    std::vector<double> grid(kGrid);
    for (int g = 0; g < kGrid; ++g) grid[static_cast<std::size_t>(g)] = lo + (hi - lo) * g / (kGrid - 1);
    const std::vector<Eigen::VectorXd> gm = pr.model(grid);
    std::size_t best = 0;
    for (std::size_t g = 1; g < grid.size(); ++g)
        if (pr.chi2(gm[g]) < pr.chi2(gm[best])) best = g;

    // Gauss-Newton on the single parameter u = ln rdisp, kept inside the grid cells around the best node
    // (the minimum lies there) and inside the search range.
    const double ulo = grid[best > 0 ? best - 1 : 0], uhi = grid[std::min(best + 1, grid.size() - 1)];
    double u = grid[best];
    Eigen::VectorXd m = gm[best];
    double s = pr.chi2(m);
    Eigen::VectorXd jac;
    bool converged = false;
    for (int iter = 0; iter < kMaxIter && !converged; ++iter) {
        const std::vector<Eigen::VectorXd> d = pr.model({u - kH, u + kH});
        jac = (d[1] - d[0]) / (2 * kH);
        const double jtj = (pr.w().array() * jac.array().square()).sum();
        const double jtr = (pr.w().array() * jac.array() * (pr.y() - m).array()).sum();
        if (!(jtj > 0)) break; // the data do not depend on rdisp here
        double step = jtr / jtj;
        bool accepted = false;
        // Backtracking: halve until chi2 does not grow (the model is not linear in u).
        for (int half = 0; half < 8 && !accepted && !converged; ++half, step /= 2) {
            const double un = std::clamp(u + step, ulo, uhi);
            if (std::abs(un - u) < kTolU) {
                converged = true;
                break;
            }
            const Eigen::VectorXd mn = pr.model({un})[0];
            const double sn = pr.chi2(mn);
            if (sn <= s) {
                converged = std::abs(un - u) < 10 * kTolU;
                accepted = true;
                u = un, m = mn, s = sn;
            }
        }
        // No descent along the Gauss-Newton direction: u is at the minimum as far as model noise allows.
        if (!accepted) converged = true;
    }
    // Jacobian at the final point for the uncertainty.
    {
        const std::vector<Eigen::VectorXd> d = pr.model({u - kH, u + kH});
        jac = (d[1] - d[0]) / (2 * kH);
    }

    FitCandidate c;
    const auto n = static_cast<int>(pr.size());
    c.i = i;
    c.rdisp = std::exp(u);
    c.weighted = data.has_sigma;
    c.chi2 = s;
    c.dof = n - 1;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    c.reduced_chi2 = c.dof > 0 ? s / c.dof : nan;
    c.aic = c.weighted ? s + 2 : n * std::log(std::max(s, 1e-300) / n) + 2;
    const double jtj = (pr.w().array() * jac.array().square()).sum();
    const double scale = c.weighted ? 1.0 : c.reduced_chi2;
    c.log_rdisp_sigma = jtj > 0 ? std::sqrt(scale / jtj) : std::numeric_limits<double>::infinity();
    c.rdisp_sigma = c.rdisp * c.log_rdisp_sigma;
    c.model.assign(m.data(), m.data() + m.size());
    for (Eigen::Index k = 0; k < pr.size(); ++k) c.residuals.push_back(pr.y()[k] - m[k]);
    if (opt.amplitude_um) {
        c.zss_um = units::zss_from_rdisp(c.rdisp, *opt.amplitude_um);
        c.zss_um_sigma = *c.zss_um * c.log_rdisp_sigma; // z_ss = A / rdisp: same relative uncertainty
    }
    c.at_bound = u - lo < 1e-3 || hi - u < 1e-3;
    c.converged = converged;
    c.evaluations = pr.evaluations;
    c.unsteady = pr.unsteady_count;
    return c;
}

} // namespace

FitResult fit_rdisp(const MeasurementSet& data, const FitOptions& opt) {
    if (data.points.empty()) throw FitError("no data points to fit");
    if (!data.has_theta && !opt.theta_deg)
        throw FitError("the data have no theta_deg column; give the vibration angle theta (degrees)");
    if (opt.theta_deg && !(std::isfinite(*opt.theta_deg) && *opt.theta_deg >= 0 && *opt.theta_deg <= 180))
        throw FitError("theta must be a number in [0, 180] degrees");
    if (!(std::isfinite(opt.rdisp_min) && std::isfinite(opt.rdisp_max) && opt.rdisp_min > 0 &&
          opt.rdisp_min < opt.rdisp_max))
        throw FitError("the r_disp search range must satisfy 0 < rdisp_min < rdisp_max (finite)");
    if (opt.amplitude_um && !(std::isfinite(*opt.amplitude_um) && *opt.amplitude_um > 0))
        throw FitError("the amplitude must be a finite number > 0 (um)");

    FitResult r;
    if (opt.shape != ShapeChoice::i1) r.candidates.push_back(fit_one(data, opt, 0.0));
    if (opt.shape != ShapeChoice::i0) r.candidates.push_back(fit_one(data, opt, 1.0));
    r.best = *std::min_element(r.candidates.begin(), r.candidates.end(),
                               [](const FitCandidate& a, const FitCandidate& b) { return a.aic < b.aic; });
    return r;
}

SteadyStatus fit_status(const FitResult& r, std::string& why) {
    SteadyStatus st = SteadyStatus::converged;
    why.clear();
    for (const FitCandidate& c : r.candidates) {
        bool finite = std::isfinite(c.rdisp);
        for (double m : c.model) finite = finite && std::isfinite(m);
        char buf[160];
        if (!finite) {
            std::snprintf(buf, sizeof buf, "i = %g: a model value or r_disp is not a finite number", c.i);
            st = SteadyStatus::non_finite;
        } else if (c.unsteady > 0) {
            std::snprintf(buf, sizeof buf,
                          "i = %g: %d of %d model evaluations did not reach the steady state", c.i,
                          c.unsteady, c.evaluations);
            if (st == SteadyStatus::converged) st = SteadyStatus::not_converged;
        } else {
            continue;
        }
        why += (why.empty() ? "" : "; ") + std::string(buf);
    }
    return st;
}

} // namespace fv
