// One period (or any stretch [tau0, tau1]) of the lag L = P - T through its phases (lag_phases.hpp): the
// period map Phi: L(0) -> L(2 pi), its derivative (discrete variational equations composed with the
// saltation matrices of the events), the period means of F (Eq. (33) with dtau -> 0), and optionally the
// events and samples of the period for figures.
#pragma once

#include "lag_phases.hpp"

#include "fv/ode_solver.hpp"
#include "fv/paper_scheme.hpp"

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace fv::solver {

enum class Phase { stick, circle, interior };

struct PeriodRequest {
    double atol = 1e-9;       // local tolerance of the integrated displacements (x_v units)
    double atol_force = 1e-7; // local tolerance of the period mean of F per unit time (quadrature)
    bool sensitivity = false; // compute d L(tau1) / d L(tau0)
    std::vector<OdeEvent>* events = nullptr;
    std::vector<Sample>* samples = nullptr; // at tau = 2 pi k / n_samples within (tau0, tau1]
    int n_samples = 0;
    const Params* params = nullptr; // for the samples' absolute P
    long max_steps = 200000;
    // Longest step (tau units). Where the steps are this long at both tolerances of a verification (a smooth
    // period), their difference would not show the quadrature's error: the check run halves it.
    double max_step = 0.5;
};

struct PeriodResult {
    bool ok = true; // false: the integrator could not continue (see `failure`)
    const char* failure = "";
    Vec2 l_end{0, 0};          // force F/F_c = rdisp L at tau1
    Vec2 dL{0, 0};             // L(tau1) - L(tau0) in x_v, summed phase by phase (no cancellation)
    Vec2 force_integral{0, 0}; // int F dtau over [tau0, tau1]
    Eigen::Matrix2d E = Eigen::Matrix2d::Zero(); // dL(tau1)/dL(tau0) - I
    // int dl(tau)/dl(tau0) dtau over [tau0, tau1] (trapezoidal over the steps, which overestimates the
    // integral of a decaying sensitivity): force_integral moves by G dl0 when the start moves by dl0.
    Eigen::Matrix2d G = Eigen::Matrix2d::Zero();
    Phase start = Phase::stick, end = Phase::stick;
    bool visited_circle = false; // slipped at full deflection at some time
    bool left_circle = false;    // was on the circle and left it (v < 0: relaxation or stick)
    double pin_drop = 0;         // largest 1 - |l| dropped beyond kPin where a grazing reach was taken
    // Smallest v = e . P' on the circle at the steps' start and stage points (infinity: never on the circle):
    // how far the period is from leaving the circle.
    double v_min_circle = std::numeric_limits<double>::infinity();
    long steps = 0, rejected = 0;
    int events = 0;
};

// The phase a state starts in at tau (a state outside the disc is pulled back onto the circle first).
Phase classify(const LagModel& m, double tau, Vec2& l);

PeriodResult run_lag(const LagModel& m, Vec2 l0, double tau0, double tau1, const PeriodRequest& rq);

} // namespace fv::solver
