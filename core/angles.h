#pragma once
// The one helper that wraps angles; every angle in canopy is in radians.
#include <cmath>
#include <numbers>

namespace canopy {

inline constexpr double kPi = std::numbers::pi;
inline constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// Wraps an angle to (-π, π].
inline double wrapAngle(double a) {
  a = std::remainder(a, kTwoPi);  // in [-π, π]
  return a <= -kPi ? a + kTwoPi : a;
}

/// Wraps an angle to [0, 2π).
inline double wrapAnglePositive(double a) {
  a = std::fmod(a, kTwoPi);
  if (a < 0.0) a += kTwoPi;
  return a < kTwoPi ? a : 0.0;  // −1e-18 + 2π rounds to 2π
}

}  // namespace canopy
