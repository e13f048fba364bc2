// The slow creep towards the circle, skipped by projective steps (see creep_skip.hpp).
#include "creep_skip.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace fv::solver {
namespace {

// The skip ends this close to the circle: from there the search on the circle's angle takes over, as it does
// for a search in the plane that gets within it (newton_search.cpp), and a creep that goes all the way to
// the circle is the approach to a state on it, which `reaches` recognises (reach.cpp).
constexpr double kClosestDeficit = 1e-6;
constexpr int kMaxJumps = 200;

// ln u with u = (1 - rho)^(1 - i): logarithms, so that deficits down to 1e-300 stay finite.
double log_u(double rho, double i) {
    return (1 - i) * std::log1p(-rho);
}

double angle_of(const Vec2& l) {
    return std::atan2(l.y(), l.x());
}

// A settled point of the creep: where it is, ln u there, and u's growth per period, (i - 1) r times the
// period's integral of v (exact for the creep law; measured from successive sections it would drown in the
// integration's noise once u's relative growth per period falls below ~1e-8, about d < 0.07 at i = 10).
struct Base {
    Vec2 x{0, 0};
    double lu = 0, du = 0;
};

// Two periods from z, both creep periods: the first settles the angle onto the creep's slow curve, the second
// (sampled) gives the integral of v. False where either is not a creep period (the motion leaves the creep).
bool settle(const ReachSetup& s, const Vec2& z, Base& b, int& periods) {
    const LagModel& m = *s.m;
    PeriodRequest rq = state_only(s);
    Vec2 z1 = z;
    PeriodResult pr;
    ++periods;
    if (!advance(s, z1, rq, &pr) || !creep_period(m, z, pr)) return false;
    std::vector<Sample> samples;
    rq.samples = &samples;
    rq.n_samples = 64;
    rq.params = s.p;
    Vec2 z2 = z1;
    ++periods;
    if (!advance(s, z2, rq, &pr) || !creep_period(m, z1, pr)) return false;
    const double v = v_integral(m, samples);
    if (!(v > 0)) return false;
    b.x = z2;
    b.lu = log_u(z2.norm(), m.i);
    b.du = (m.i - 1) * m.r * v;
    return std::isfinite(b.lu);
}

} // namespace

bool creep_period(const LagModel& m, const Vec2& l0, const PeriodResult& pr) {
    return m.i > 1 && pr.ok && pr.start == Phase::interior && pr.end == Phase::interior && pr.events == 0 &&
           !pr.visited_circle && l0.dot(m.dP(0)) > 0;
}

CreepSkip skip_creep(const ReachSetup& s, Vec2 prev, Vec2 x) {
    const double i = s.m->i;
    CreepSkip out;
    out.x = x;
    Base base;
    if (!settle(s, x, base, out.periods)) return out;
    out.x = base.x;
    // The angle's drift per unit of ln u, from the last two bases (long baselines: the drift per period
    // drowns in the integration's noise as well).
    double last_lu = log_u(prev.norm(), i), last_phi = angle_of(prev);
    double n = 4;
    bool bounded = false; // a projection `beyond` periods past the base was seen to leave the creep
    double beyond = 0;
    for (int jump = 0; jump < kMaxJumps && 1 - base.x.norm() > kClosestDeficit; ++jump) {
        const double phi = angle_of(base.x);
        const double slope =
            base.lu - last_lu > 1e-6 ? std::remainder(phi - last_phi, 2 * kPi) / (base.lu - last_lu) : 0.0;
        const double dlu = std::log1p(n * base.du * std::exp(-base.lu));
        const double rho = -std::expm1((base.lu + dlu) / (1 - i));
        const double phi_z = phi + slope * dlu;
        const Vec2 z = rho * Vec2(std::cos(phi_z), std::sin(phi_z));
        Base next;
        if (settle(s, z, next, out.periods)) {
            last_lu = base.lu;
            last_phi = phi;
            base = next;
            out.x = base.x;
            out.skipped += n;
            beyond -= n + 2;
            n = bounded ? std::max(1.0, std::floor(std::min(4 * n, beyond / 2))) : 4 * n;
            continue;
        }
        if (n <= 2) {
            // The motion leaves the creep within a few periods of the base, and z is already past: the
            // motion goes on from there. (Near the circle the creep per period is below the integration's
            // noise, so integrating on from the base would never get across.)
            out.x = z;
            break;
        }
        bounded = true;
        beyond = n;
        n = std::max(1.0, std::floor(n / 4));
    }
    return out;
}

} // namespace fv::solver
