#pragma once

#include <Eigen/Core>

namespace fv {
using Vec2 = Eigen::Vector2d;
} // namespace fv
