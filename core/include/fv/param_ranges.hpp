// The allowed ranges of the model's parameters and of their physical counterparts, stated once: the CLI's
// validators and help texts (app/cli), the data reader (measurements.hpp), the app's edits (AppState::sync)
// and the app's sliders all take them from here, so that a message, a slider end and a check agree.
#pragma once

#include "fv/params.hpp"

#include <string>

namespace fv {

struct ParamRange {
    double lo, hi;
    bool lo_open = false; // lo itself excluded
};

// What the model accepts (and the CLI, the data files and the app's edits).
inline constexpr ParamRange kZetaRange{0, 100};
inline constexpr ParamRange kThetaRange{0, 180}; // degrees; other angles are mirror images
inline constexpr ParamRange kRdispRange{0, 1e4, true};
// The ode scheme's target error, the accuracy the status ok promises (--tolerance on the command line,
// tolerance= in Python; default SteadyOptions::ode_tolerance).
inline constexpr ParamRange kToleranceRange{1e-12, 1e-4};
inline constexpr ParamRange kIRange{0, 10};

// Physical units (units.hpp): v_b in m/s, the vibration amplitude A and z_ss in um, the frequency f in kHz.
inline constexpr ParamRange kVbRange{0, 1e6};
inline constexpr ParamRange kAmplitudeRange{0, 1e6, true};
inline constexpr ParamRange kFrequencyRange{0, 1e6, true};
inline constexpr ParamRange kZssRange{0, 1e6, true};

// Measured data (measurements.hpp). r_x: the model gives [0, 1]; the margin admits noise and calibration
// offsets, anything further off is a unit or column mix-up such as percent. sigma, the standard uncertainty
// of r_x: the fit weighs each point by 1/sigma^2, so sigma must keep that weight a finite, usable number
// (1e-200 squared underflows to 0 and the weight to infinity; the fit then had NaN). Below 1e-6 it is also
// far below what the model itself can vouch for (its error estimate, ~1e-8, and the data's own scatter), so
// such a sigma is a unit mistake, refused at load rather than clamped.
inline constexpr ParamRange kRxDataRange{-0.5, 1.5};
inline constexpr ParamRange kSigmaRange{1e-6, 10};

// The app's view, in the shared table because sessions and share links carry it and the link's parser is in
// core: the animation speed in vibration periods per second (the panel's slider spans part of it), the trail
// behind P and T in vibration periods, the top view's zoom factor (the mouse wheel) and each coordinate of
// its pan in the model's length unit (a drag).
inline constexpr ParamRange kSpeedRange{0.05, 10};
inline constexpr ParamRange kTrailRange{0.1, 10};
inline constexpr ParamRange kZoomRange{0.05, 20};
inline constexpr ParamRange kPanRange{-1e6, 1e6};

// The part of each range the app's sliders span (values beyond them are typed, scripted or given on the
// command line); each lies inside the range above.
inline constexpr ParamRange kZetaSlider{0, 3};
inline constexpr ParamRange kThetaSlider = kThetaRange;
inline constexpr ParamRange kRdispSlider{0.1, 100}; // logarithmic
inline constexpr ParamRange kISlider{0, 3};

// "[0, 100]", "(0, 10000]".
std::string describe(ParamRange r);

// v lies in r (false for NaN).
bool inside(double v, ParamRange r);

// Empty when p is admissible (validate()) and inside the ranges above (theta in degrees within
// kThetaRange), else one line naming the parameter and its allowed range, e.g.
// "zeta = 200; allowed: zeta in [0, 100]".
std::string range_error(const Params& p);

} // namespace fv
