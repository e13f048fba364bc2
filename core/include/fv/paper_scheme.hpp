// The paper's tracking scheme for the lumped asperity (Section 3, Eqs. (17)-(29)), one step at a time.
//
// Dimensionless form (docs/model.md): tau = omega t, lengths in units of x_v = v_v/omega, forces in units of
// F_c. P(tau) = (zeta tau + sin(tau) cos(theta), sin(tau) sin(theta))            Eqs. (28)-(29) F/F_c  = (P -
// T) / z_ss                                                    Eqs. (13), (23)-(24)
#pragma once

#include "fv/params.hpp"
#include "fv/vec2.hpp"

#include <cstdint>
#include <vector>

namespace fv {

// Body point P at dimensionless time tau, Eqs. (28)-(29).
Vec2 body_point(const Params& p, double tau);
// dP/dtau, from Eq. (1).
Vec2 body_velocity(const Params& p, double tau);

// One step of the scheme, Eqs. (17)-(27): from the lag L = P(t) - T(t) and the body's move dP = P(t+dt) -
// P(t), the lag L(t+dt) = P(t+dt) - T(t+dt). This is the whole model; PaperStepper and the app's live
// simulation both step with it.
Vec2 dahl_update(const Params& p, Vec2 lag, Vec2 dP);

// One recorded instant.
struct Sample {
    double tau = 0;
    Vec2 P{0, 0};
    Vec2 T{0, 0};
    double z = 0; // |P - T|, Eq. (18)
    Vec2 F{0, 0}; // (P - T)/z_ss, Eqs. (23)-(24)
};

// Steps the scheme with a fixed number of steps per vibration period (dtau = 2 pi / n, Eq. (32)).
// Positions are kept relative to the start of the current period, so long runs lose no precision.
class PaperStepper {
  public:
    // initial_lag = P(0) - T(0); the paper leaves it open, zero (unstretched asperity) is the default.
    PaperStepper(const Params& p, int steps_per_period, Vec2 initial_lag = Vec2::Zero());

    void step(); // advance by one dtau

    const Params& params() const { return p_; }
    int steps_per_period() const { return n_; }
    double dtau() const { return dtau_; }
    std::int64_t step_index() const { return period_ * n_ + k_; } // steps taken so far
    std::int64_t period() const { return period_; }               // completed periods
    int phase_step() const { return k_; }                         // steps into the current period

    double tau() const;
    Vec2 P() const; // absolute coordinates
    Vec2 T() const;
    Vec2 lag() const { return lag_; } // P - T
    double z() const { return lag_.norm(); }
    Vec2 force() const { return lag_ * p_.rdisp; }
    Sample sample() const;

    // Replace the lag (for warm starts); keeps time. |lag| must not exceed z_ss.
    void set_lag(Vec2 lag) { lag_ = lag; }

  private:
    Params p_;
    int n_;
    double dtau_;
    // sin((k+1) dtau) - sin(k dtau) for k = 0..n-1, formed as 2 cos((k+1/2) dtau) sin(dtau/2) so that the
    // step of P keeps full relative precision however small dtau is.
    std::vector<double> dsin_;
    std::int64_t period_ = 0;
    int k_ = 0;
    // The state is the lag P - T alone: P is known in closed form, so T = P - lag. Keeping the lag instead
    // of T avoids subtracting two large, drifting coordinates.
    Vec2 lag_;
};

} // namespace fv
