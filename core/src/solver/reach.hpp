// Which periodic state the motion from a start settles into (docs/model.md, "Which steady state"): fixed
// points of the period map (or of its k-times iterate) found by Newton's method, each accepted for a start
// only with evidence that the motion from that start gets into its contraction region, and the stable
// states found on the way that the start does not reach.
#pragma once

#include "verify_state.hpp"

#include <complex>
#include <vector>

namespace fv::solver {

// What the searches share: the model, the search's integration settings (with sensitivity), the aim and
// the tolerance of the means, and whether the reached state's period is recorded for a figure.
struct ReachSetup {
    const Params* p = nullptr;
    const LagModel* m = nullptr;
    PeriodRequest rq;
    double aim = 0, tol = 0;
    bool record = false;
    int record_samples = 1024;
    int max_search_periods = 400; // Newton's periods (sensitivities) over all searches from one start
};

// A periodic state: the motion repeats every k periods from l0.
struct Orbit {
    SteadyStatus status = SteadyStatus::not_converged;
    int k = 1;
    Vec2 l0{0, 0}; // force at the start of a period (l = F/F_c)
    double rx = 0, ry = 0;
    double error_estimate = 0, steady_error = 0, integration_error = 0;
    std::complex<double> mu[2]; // Floquet multipliers of the k-period map, |mu| descending
    bool have_mu = false;
    bool on_circle = false;
    bool circle_state = false; // on the circle all period long (i > 0): approached from inside radially
    Eigen::Matrix2d M = Eigen::Matrix2d::Identity(); // derivative of the k-period map at l0
    bool reached = false; // the motion from the start gets into its contraction region
    int newton_steps = 0, plain_steps = 0;
    long periods_skipped = 0;
    int events_per_period = 0, steps_per_period = 0;
    const char* failure = "";
    std::vector<OdeEvent> events;
    std::vector<Sample> samples;
    double standard_error = 0; // not_periodic: of the long-time means
    int window = 0;            // not_periodic: periods averaged
};

struct Reach {
    Orbit state;               // what the motion from the start settles into (its status says how sure)
    std::vector<Orbit> others; // stable states found on the way that the start does not reach (verified)
    int periods = 0;           // periods integrated
    double skipped = 0;        // periods of slow creep projected over, not integrated (creep_skip.hpp)
};

// The periods followed from a start before its motion is called not periodic, and the window (after
// them) over which the long-time means and their standard error (batch means) are taken then.
inline constexpr int kFollowPeriods = 600;
inline constexpr int kWindowPeriods = 1000;
inline constexpr int kWindowBatches = 20;
// A motion whose sections still range over more than this many tolerances within the window's last batch
// (and over at least half as far as in its first) keeps moving: not a slow transient (reach.cpp).
inline constexpr double kMovingSections = 100;
// Beside an unstable period-1 state, the motion's sections within this of repeating before Newton's method
// for period 1 is tried from them (reach.cpp: further off it retraces the search that found the unstable
// state).
inline constexpr double kNearRepeat = 1e-3;
// Slow creeps skipped per start (each followed again from where its skip ends).
inline constexpr int kMaxCreepSkips = 2;
// A skip is tried after this many creep periods in a row, and taken when it projects at least kMinCreepSkip.
inline constexpr int kMinCreepRun = 4;
inline constexpr double kMinCreepSkip = 16;
// Slow approaches coasted over per start (coast.hpp; each a series of projections).
inline constexpr int kMaxCoasts = 16;

// The map as the search integrates it (the same state and quadrature control, which both set the steps),
// without the sensitivity: a point of the motion and the fixed point are then points of the same map.
PeriodRequest state_only(const ReachSetup& s);

// How close (force units) a point of the motion must come to a state to have arrived at it: 30 times the
// aim, the sections' integration noise (at least 1e-10).
double arrival_noise(const ReachSetup& s);

// The integral of v = e . P' over a period from its evenly spaced samples: the trapezoidal rule, spectrally
// accurate for the smooth periodic integrand. 0 without samples.
double v_integral(const LagModel& m, const std::vector<Sample>& samples);

// One period of the motion from l (force units). For i = 0 a whole stuck period is a translation: the
// motion is skipped to its first slip in closed form and that period finished (a later section of the
// same motion). `last` gets the last period integrated.
bool advance(const ReachSetup& s, Vec2& l, const PeriodRequest& rq, PeriodResult* last = nullptr);

// What a search before (the default search from rest, steady_search.cpp) found, so that the search from the
// start's motion does not repeat it.
struct Prior {
    // A stable state found that the start's motion was not shown to reach: a guess that leads to it again is
    // not verified and tested again, only followed up later.
    const Orbit* rejected = nullptr;
    // An unstable state found: what the output names where the motion settles into nothing stable.
    const Orbit* unstable = nullptr;
    // Starts whose Newton's method gave up (no progress for kGiveUp periods) or found the unstable state:
    // from the same start the same search does so again, so it is not run again (at zeta 0.448, theta 8.1
    // deg, rdisp 37, i = 10 five such searches cost 93 of 225 periods).
    std::vector<Vec2> fruitless;
};

// The state the motion from `start` (force units) settles into. `guesses`: first guesses for Newton's
// method (a warm start, limits, the start itself), tried in order before the motion is followed.
Reach reach_from(const ReachSetup& s, Vec2 start, const std::vector<Vec2>& guesses, const Prior& prior = {});

// Evidence that the motion through x (force units, a point of the start's motion) settles into the state y
// of the k-period map with derivative M (docs/model.md, "Which steady state"). `periods` counts the
// periods integrated for it.
bool reaches(const ReachSetup& s, Vec2 x, const Vec2& y, const Eigen::Matrix2d& M, int k, bool circle_state,
             int& periods);

// Whether Floquet multipliers (|mu| descending) make a state stable.
bool stable(const std::complex<double> mu[2]);

// The period-1 state a verification describes (status converged only when its error estimate is within
// the tolerance).
Orbit orbit_of(const ReachSetup& s, const Verified& v);

// Floquet multipliers of a period-1 state from its period's derivative M = DPhi. A state on the circle
// with no law change in its period has M of rank one (the pinning forgets the radial part); its radial
// multiplier is the approach to the circle from inside: 0 for i < 1 (finite time), exp(-r int v dtau) for
// i = 1, and 1 for i > 1 (algebraic: a deficit d obeys d' = -r v d^i).
void period1_multipliers(const ReachSetup& s, const PeriodResult& pr, Vec2 l0, std::complex<double> mu[2]);

} // namespace fv::solver
