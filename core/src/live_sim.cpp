#include "fv/live_sim.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fv {

int LiveSim::animation_steps(const Params& p) {
    const double needed = 2 * kPi * (1 + p.zeta) * p.rdisp * 8;
    return static_cast<int>(std::clamp(std::ceil(needed / 36) * 36, 360.0, 36000.0));
}

LiveSim::LiveSim(Model model, const Params& p) : model_(model), p_(p) {
    last_mean_ = Vec2(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    reset();
}

Vec2 LiveSim::P() const {
    return body_point(p_, tau_) + offset_;
}
Vec2 LiveSim::vibration_centre() const {
    return P() - std::sin(tau_) * Vec2(std::cos(p_.theta), std::sin(p_.theta));
}
Vec2 LiveSim::velocity() const {
    return body_velocity(p_, tau_);
}

Vec2 LiveSim::force() const {
    if (model_ == Model::rigid) {
        // Eq. (2): friction opposes the velocity with magnitude F_c; shown as the ratio's sign convention
        // (along the motion), like the Dahl force (P - T)/z_ss.
        const Vec2 v = velocity();
        const double s = v.norm();
        return s > 0 ? Vec2(v / s) : Vec2(Vec2::Zero());
    }
    return lag_ * p_.rdisp;
}

bool LiveSim::slipping() const {
    if (model_ == Model::rigid) return true;
    return z() >= p_.zss() * (p_.i == 0 ? 1 - 1e-9 : 0.995);
}

void LiveSim::reset(Start start) {
    n_ = animation_steps(p_);
    tau_ = 0;
    k_ = 0;
    period_ = 0;
    phase_ = 0;
    // Lengths are in units of x_v, so the full deflection is z_ss = 1 / r_disp (F = lag r_disp = (1, 0)).
    lag_ = start == Start::sliding && model_ == Model::dahl ? Vec2(p_.zss(), 0) : Vec2(Vec2::Zero());
    offset_ = Vec2::Zero();
    sum_ = Vec2::Zero();
    last_mean_ = Vec2(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    history_.clear();
    record();
}

void LiveSim::start_steady(Vec2 lag_at_period_start) {
    const Vec2 P_before = P();
    tau_ = std::ceil(tau_ / (2 * kPi) - 1e-12) * 2 * kPi;
    phase_ = tau_;
    k_ = 0;
    sum_ = Vec2::Zero();
    last_mean_ = Vec2(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    lag_ = lag_at_period_start;
    if (lag_.norm() > p_.zss()) lag_ *= p_.zss() / lag_.norm();
    offset_ += P_before - P();
    history_.clear();
    record();
}

void LiveSim::apply(Model model, const Params& p) {
    const Vec2 P_before = P();
    model_ = model;
    p_ = p;
    // A new step size starts a new period count at the current time (the running mean restarts with it).
    n_ = animation_steps(p_);
    phase_ = tau_;
    k_ = 0;
    sum_ = Vec2::Zero();
    if (lag_.norm() > p_.zss()) lag_ *= p_.zss() / lag_.norm();
    offset_ += P_before - P();
}

void LiveSim::step(int count) {
    const double dt = dtau();
    for (int c = 0; c < count; ++c) {
        const double t1 = phase_ + (k_ + 1) * dt;
        // Move of P over the step from the phase within the period: independent of how long the run is.
        const double a = (k_ + 0.5) * dt;
        const double ds = 2 * std::cos(phase_ + a) * std::sin(0.5 * dt);
        const Vec2 dP{p_.zeta * dt + ds * std::cos(p_.theta), ds * std::sin(p_.theta)};
        if (model_ == Model::dahl) lag_ = dahl_update(p_, lag_, dP);
        tau_ = t1;
        sum_ += force();
        if (++k_ == n_) {
            last_mean_ = sum_ / n_; // Eq. (30)
            sum_ = Vec2::Zero();
            k_ = 0;
            phase_ = tau_;
            ++period_;
        }
        record();
    }
}

void LiveSim::record() {
    LiveSample s;
    s.tau = tau_;
    s.P = P();
    s.T = model_ == Model::rigid ? s.P : Vec2(s.P - lag_);
    s.F = force();
    s.slip = slipping();
    s.fx_sum = (history_.empty() ? 0.0 : history_.back().fx_sum) + s.F.x();
    history_.push_back(s);
    const double keep = history_periods_ * 2 * kPi;
    while (!history_.empty() && history_.front().tau < tau_ - keep) history_.pop_front();
}

} // namespace fv
