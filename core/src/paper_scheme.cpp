#include "fv/paper_scheme.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace fv {

Vec2 body_point(const Params& p, double tau) {
    // Eqs. (28)-(29) divided by x_v = v_v/omega.
    const double s = std::sin(tau);
    return {p.zeta * tau + s * std::cos(p.theta), s * std::sin(p.theta)};
}

Vec2 body_velocity(const Params& p, double tau) {
    // Eq. (1) divided by v_v.
    const double c = std::cos(tau);
    return {p.zeta + c * std::cos(p.theta), c * std::sin(p.theta)};
}

PaperStepper::PaperStepper(const Params& p, int steps_per_period, Vec2 initial_lag)
    : p_(p), n_(steps_per_period), dtau_(2 * kPi / steps_per_period), lag_(initial_lag) {
    if (steps_per_period < 1) throw std::invalid_argument("steps per period must be >= 1");
    dsin_.resize(static_cast<std::size_t>(n_));
    const double half = std::sin(0.5 * dtau_);
    for (int k = 0; k < n_; ++k) dsin_[static_cast<std::size_t>(k)] = 2 * std::cos((k + 0.5) * dtau_) * half;
}

double PaperStepper::tau() const {
    return (static_cast<double>(period_) * n_ + k_) * dtau_;
}
Vec2 PaperStepper::P() const {
    return body_point(p_, tau());
}
Vec2 PaperStepper::T() const {
    return P() - lag_;
}

Sample PaperStepper::sample() const {
    Sample s;
    s.tau = tau();
    s.P = P();
    s.T = s.P - lag_;
    s.z = z();
    s.F = force();
    return s;
}

Vec2 dahl_update(const Params& p, Vec2 lag, Vec2 dP) {
    const double zss = p.zss();
    // P(t + dt) - T(t): the asperity is pulled along this line (Fig. 8).
    const Vec2 pull = lag + dP;
    const double d = pull.norm(); // |T(t) P(t+dt)|
    const double z = lag.norm();  // Eq. (18)
    double z_new;
    if (p.i == 0) {
        // Eq. (27): sticks (deflection follows P) below z_ss, slips at z_ss. Never Eq. (20) with i = 0:
        // pow(0, 0) == 1 would let z run past z_ss.
        z_new = std::min(d, zss);
    } else {
        const double v_dt = d - z; // v(t) dt, Eq. (19)
        const double sgn = v_dt > 0 ? 1.0 : (v_dt < 0 ? -1.0 : 0.0);
        // Eq. (17) with the exponent i of Eq. (16). The base is >= 0 whenever z <= z_ss; the clamp keeps
        // pow() finite for non-integer i if a coarse step ever left z above z_ss.
        const double base = std::max(0.0, 1 - sgn * z / zss);
        const double factor = p.i == 1 ? base : std::pow(base, p.i);
        z_new = z + v_dt * factor; // Eq. (20)
        // Guards that act only when P moves by a sizeable fraction of z_ss in one step: the continuous
        // model (16) keeps 0 <= z <= z_ss, a too-coarse explicit step can overshoot either bound.
        z_new = std::clamp(z_new, 0.0, std::max(zss, z));
    }
    // Eqs. (21)-(22): T(t+dt) lies on the pull line at distance z(t+dt) from P(t+dt).
    return d > 0 ? Vec2(pull * (z_new / d)) : Vec2(Vec2::Zero());
}

void PaperStepper::step() {
    const double ds = dsin_[static_cast<std::size_t>(k_)];
    // P(t + dt) - P(t), Eqs. (28)-(29).
    const Vec2 dP{p_.zeta * dtau_ + ds * std::cos(p_.theta), ds * std::sin(p_.theta)};
    lag_ = dahl_update(p_, lag_, dP);
    if (++k_ == n_) {
        k_ = 0;
        ++period_;
    }
}

} // namespace fv
