// Turning a force in the plane and the signed angle between two forces: one definition for the search on the
// circle's angle, the period map's sensitivities on the circle, the evidence of reaching a state and the
// coasting along the circle.
#pragma once

#include "fv/vec2.hpp"

#include <cmath>

namespace fv::solver {

// v turned by a quarter turn (counter-clockwise): the circle's tangent at the force v.
inline Vec2 perp(const Vec2& v) {
    return {-v.y(), v.x()};
}

// v turned by a radians (counter-clockwise).
inline Vec2 rotated(const Vec2& v, double a) {
    const double c = std::cos(a), s = std::sin(a);
    return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

// The signed angle that turns `from` onto `to`, in (-pi, pi].
inline double turn_angle(const Vec2& from, const Vec2& to) {
    return std::atan2(from.x() * to.y() - from.y() * to.x(), from.dot(to));
}

} // namespace fv::solver
