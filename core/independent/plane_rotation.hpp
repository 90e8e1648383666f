// A vector of a body's frame in the world frame: turned by the body's angle,
// counter-clockwise positive (the one rotation the independent truth uses).
#pragma once

#include <cmath>

#include "planarbench/case.hpp"

namespace pb::independent {

[[nodiscard]] inline Vec2 rotate(double angle_rad, const Vec2& v) {
  const double c = std::cos(angle_rad);
  const double s = std::sin(angle_rad);
  return {c * v.x() - s * v.y(), s * v.x() + c * v.y()};
}

}  // namespace pb::independent
