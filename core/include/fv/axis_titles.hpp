// The axis titles of the quantities that the figures and the app's live panels share: one text per quantity,
// so that a figure and the live panel showing the same thing label it the same way. (Markup: _{} subscripts.)
#pragma once

namespace fv::titles {

inline constexpr const char* kZeta = "velocity ratio ζ = v_{b}/v_{v}";
inline constexpr const char* kTheta = "vibration angle θ [°]";
inline constexpr const char* kRx = "friction ratio r_{x}";
inline constexpr const char* kRy = "side-force ratio r_{y}";
// The top view: positions in units of the vibration amplitude.
inline constexpr const char* kTopViewX = "x / x_{v}";
inline constexpr const char* kTopViewY = "y / x_{v}";
// Time in radians of the vibration's phase.
inline constexpr const char* kTime = "time τ = ωt";
// The spring's pull on the tip, in units of F_c: what every force plot shows (fv::kForceConvention).
inline constexpr const char* kForce = "F / F_{c} = (P − T) / z_{ss}";

} // namespace fv::titles
