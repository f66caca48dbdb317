// Angles in degrees.
#pragma once

#include <cmath>

namespace multicpg {

// Wraps an angle to (-180, 180] (docs/learning.md "Deviation": yaw and its deviations).
inline double wrap_degrees(double degrees) {
  constexpr double kFullTurn = 360.0;
  constexpr double kHalfTurn = 180.0;
  double w = std::fmod(degrees, kFullTurn);
  if (w <= -kHalfTurn) w += kFullTurn;
  if (w > kHalfTurn) w -= kFullTurn;
  return w;
}

}  // namespace multicpg
